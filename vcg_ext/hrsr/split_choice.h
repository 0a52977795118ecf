// Which two spokes a vertex split should use (ALGORITHM.md §8.4, D-18).
#pragma once

#include "mesh/split_mesh.h"
#include "options.h"

namespace hrsr::reexpand {

struct SplitChoice {
    bool found = false;
    std::uint32_t a = 0, b = 0; ///< h_in comes from a, h_out goes to b
    double energy = 0;
    SplitMesh::BorderSplit omit = SplitMesh::BorderSplit::None; ///< D-34
};

/// Evaluates every ordered pair of spokes of c (whose star is given) for c at p_old and a new
/// vertex at p_new by E = E_D + w · E_A (w = constants::kMinAngleWeight) and applies the dihedral
/// guard. Wedges that are not faces (the boundary gap) are not scored (D-18). Ties go to the first
/// pair in circulation order (D-10).
/// Where c lies on a border loop longer than D-28 closes and p_new in its gap, border splits
/// (D-34) are candidates too: a small hole of the coarse mesh keeps its few edges.
SplitChoice choose_split(const SplitMesh& mesh, std::uint32_t c, const Star& star,
                         const Vec3& p_old, const Vec3& p_new);

} // namespace hrsr::reexpand
