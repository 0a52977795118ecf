// A reconstruction of the cloud in spatial order (spatial_order.h, D-40) handed back in the
// input's indices: what reconstruct() returns and reports speaks only of those.
#pragma once

#include "reconstruction.h"
#include "spatial_order.h"

namespace hrsr {

/// Maps every point index of `mesh` and `report` (vertices, dropped and unplaced points, the
/// per-point fates and duplicates) from `order`'s to the input's, and numbers the vertices in
/// input order: each point's first vertex by input index, then the copies made for
/// non-manifold points (§5.8), also by input index. The same for any thread count.
void restore_input_order(const SpatialOrder& order, Reconstruction& mesh,
                         ReconstructionReport& report,
                         const Execution& exec = Execution{1, nullptr});

} // namespace hrsr
