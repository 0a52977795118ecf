// Closing the tiny faces that the other phases leave open (deviation D-23).
#pragma once

#include "rsr/embedding.h"

namespace hrsr::rsr {

struct SmallHoleStats {
    std::size_t triangles_closed = 0; ///< 3-dart faces recorded as they are
    std::size_t quads_split = 0;      ///< 4-dart faces split by a diagonal into two triangles
    std::size_t quads_recorded_only =
        0; ///< nearly collinear 4-dart faces closed by two triangles outside the rotation
};

/// D-23: after the ear phase, a face of 3 darts is recorded as a triangle, and a face of 4 darts
/// is closed by two triangles on the diagonal with the larger smallest angle among those whose
/// triangles wind with their corners' normals (D-52), if any (inserted into the
/// rotation when it lies inside the face there). Such faces are left by the 175° sliver
/// rule of §5.5.2 and the side rules of the ears on nearly collinear points; a real hole in
/// the data has more boundary points than that. Faces are visited in order of their first dart
/// (vertex, position), so the result is deterministic.
SmallHoleStats close_small_holes(Embedding& embedding);

} // namespace hrsr::rsr
