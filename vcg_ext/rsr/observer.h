// Watching RsR's mutations from outside (geometry-central's MutationManager is the model): tests
// check invariants after every insertion without debug flags in the algorithm.
#pragma once

#include "rsr/component.h"
#include "rsr/faces.h"

#include <vector>

namespace hrsr::rsr {

enum class Phase { FaceSplit, Handles, Ears };

class Observer {
public:
    virtual ~Observer() = default;
    /// The spanning tree is embedded and its faces labelled.
    virtual void tree_built(const RotationSystem&, const Faces&) {}
    /// Edge {u, v} was inserted in `phase`; `triangles` holds every triangle recorded so far and
    /// `new_triangles` how many of them (at the end) this insertion recorded.
    virtual void edge_inserted(Phase, std::uint32_t /*u*/, std::uint32_t /*v*/,
                               const RotationSystem&, const Faces&,
                               const std::vector<LocalTriangle>& /*triangles*/,
                               std::size_t /*new_triangles*/) {}
    /// All phases are done; the faces that are not recorded triangles are the holes.
    virtual void finished(const RotationSystem&, const Faces&,
                          const std::vector<LocalTriangle>& /*triangles*/) {}
};

} // namespace hrsr::rsr
