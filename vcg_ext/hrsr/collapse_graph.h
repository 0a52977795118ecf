// The graph HRsR's collapse works on (ALGORITHM.md §6.1): per node its position, normal, weight,
// neighbours and the node it was merged into.
#pragma once

#include "graph/vertex_heap.h"
#include "hrsr/collapse.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace hrsr::collapsing {

struct CollapseGraph {
    std::vector<Vec3> x, n;
    std::vector<std::uint32_t> w;
    std::vector<std::uint8_t> alive;
    std::vector<std::vector<std::uint32_t>> neighbours; ///< symmetric, no repeats, no self loops
    std::vector<std::uint32_t> into;                    ///< itself while alive

    /// §6.1: tangent distance times the merged weight, in both distance modes. The > 90° rule
    /// holds for the graph as built (D-14); an edge inherited through a merge is not checked
    /// again (D-15, withdrawn: checking it made the bunny, the lion and the dragon sample worse).
    EdgeKey edge_key(std::uint32_t a, std::uint32_t b) const;

    /// Merges b into a (a < b) and records it. The lists are left to move_edges().
    void merge(std::uint32_t a, std::uint32_t b, std::vector<CollapseRecord>& records);

    /// b's edges become a's (no repeats, no self loops) and b's list is freed. A neighbour whose
    /// list `writes(c)` rejects (another tile's task owns it) keeps its edge to b: `defer(c)` is
    /// called and relink() does it later.
    template <class Writes, class Defer>
    void move_edges(std::uint32_t a, std::uint32_t b, Writes writes, Defer defer) {
        std::vector<std::uint32_t>& mine = neighbours[a];
        for (std::uint32_t c : neighbours[b]) {
            if (c == a) continue;
            const bool writable = writes(c);
            if (writable)
                erase(c, b);
            else
                defer(c);
            if (std::find(mine.begin(), mine.end(), c) == mine.end()) {
                mine.push_back(c);
                if (writable) neighbours[c].push_back(a);
            }
        }
        erase(a, b);
        std::vector<std::uint32_t>().swap(neighbours[b]);
    }

    /// The live node that i was merged into, directly or not (paths are shortened on the way).
    std::uint32_t survivor(std::uint32_t i);

    /// A deferred part of move_edges(): c's edge to `dead` becomes one to `to`.
    void relink(std::uint32_t c, std::uint32_t dead, std::uint32_t to);

private:
    void erase(std::uint32_t c, std::uint32_t j);
};

/// The graph over the symmetric kNN union (k = options' collapse_k), edges over 90° left out.
/// `index`: a kd-tree on `positions`, or null (one is built here); freed once the kNN table is
/// made.
CollapseGraph build_graph(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                          int k, const Execution& exec, std::unique_ptr<KnnIndex> index = nullptr);

} // namespace hrsr::collapsing
