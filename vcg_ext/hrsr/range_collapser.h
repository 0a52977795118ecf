// The greedy collapse (ALGORITHM.md §6.2) of a range of nodes: the whole graph, or one tile of
// it (D-42).
#pragma once

#include "graph/vertex_heap.h"
#include "hrsr/collapse_graph.h"
#include "parallel.h"

#include <cstdint>
#include <vector>

namespace hrsr::collapsing {

/// A node of another tile lost `dead` and takes `into` instead (written while the tiles run,
/// applied after: a tile writes only its own nodes' lists).
struct Relink {
    std::uint32_t node, dead, into;
};

/// Collapses the nodes [begin, end) over the edges between them, with, per node, its smallest
/// admissible edge and a heap of the nodes ordered by that edge (graph/vertex_heap.h). The
/// globally smallest admissible edge is the best edge of both its endpoints, so the heap's top
/// gives it. One heap entry per node instead of one per edge (with stale copies) keeps the queue
/// at a fifth of the bytes and the heap shallow; the order of the merges is exactly that of a
/// queue of all edges (see collapse_next()). Edges to nodes outside are carried through the
/// merges but not taken; what they change outside is left in `relinks`.
class RangeCollapser {
public:
    /// exec: runs the first best-edge search in parallel (null inside a tile's own task).
    RangeCollapser(CollapseGraph& g, std::uint32_t begin, std::uint32_t end, const Execution* exec);

    /// Appends every queued node's smallest cost.
    void add_costs(std::vector<float>& costs) const;

    /// The cost of the next collapse; false when no admissible edge is left.
    bool next_cost(double& cost) const;

    /// Performs the next collapse; false when no admissible edge is left.
    bool collapse_next(std::vector<CollapseRecord>& records);

    bool contains(std::uint32_t i) const { return i >= begin_ && i < end_; }

    /// Queues the node with its smallest edge inside, or takes it out without one.
    void refresh(std::uint32_t i);
    void erase(std::uint32_t i) { queue_.erase(i - begin_); }

    /// Notes that node i of the range has (or had) an edge to a node outside it.
    void mark_border(std::uint32_t i) {
        if (on_border_[i - begin_]) return;
        on_border_[i - begin_] = 1;
        border_.push_back(i);
    }
    /// The range's nodes that ever had an edge outside it: a superset of the live ones that
    /// have one now (D-42 looks for edges across tiles there only).
    const std::vector<std::uint32_t>& border() const { return border_; }

    std::vector<Relink> relinks;

private:
    bool best_edge(std::uint32_t i, EdgeKey& best) const;

    CollapseGraph& g_;
    std::uint32_t begin_, end_;
    VertexHeap queue_; ///< nodes of the range with an admissible edge, by their smallest one
    std::vector<std::uint8_t> on_border_;
    std::vector<std::uint32_t> border_;
};

} // namespace hrsr::collapsing
