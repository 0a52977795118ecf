// Internal: the entry points of reconstruction.h with observers that watch every mutation of
// RsR's rotation system and every split of the re-expansion (tests check invariants through
// them). Not part of the public API: the observers take the algorithm's internal types.
#pragma once

#include "hrsr/reexpansion.h"
#include "reconstruction.h"
#include "rsr/observer.h"

namespace hrsr {

/// reconstruct_rsr() with an observer (may be null) that watches every component (which are then
/// reconstructed one after the other).
Reconstruction reconstruct_rsr(const PointSet& input, const RsrOptions& options,
                               const Execution& exec, ReconstructionReport& report,
                               rsr::Observer* observer);

/// reconstruct_hrsr() with observers (either may be null): `observer` watches the RsR stage,
/// `reexpansion_observer` every split.
Reconstruction reconstruct_hrsr(const PointSet& input, const ReconstructionOptions& options,
                                const Execution& exec, ReconstructionReport& report,
                                rsr::Observer* observer,
                                ReexpansionObserver* reexpansion_observer = nullptr);

/// reconstruct() with an observer (may be null) of the RsR stage.
Reconstruction reconstruct(const PointSet& input, const ReconstructionOptions& options,
                           const Execution& exec, ReconstructionReport& report,
                           rsr::Observer* observer);

} // namespace hrsr
