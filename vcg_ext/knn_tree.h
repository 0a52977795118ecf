// vcglib's kd-tree as KnnIndex holds it: which point each slot holds, and a build whose subtrees
// below the top levels run in parallel, giving the tree vcglib's constructor gives.
#pragma once

#include "parallel.h"
#include "point_set.h"

#include <vcg/space/index/kdtree/kdtree.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace hrsr {

// Leaves of 32 points instead of vcglib's 16: fewer nodes to descend for the same points; on the
// 800k dragon sample queries at k = 1, 8, 71 and 193 took 6–18 % less (docs/BENCHMARKS.md,
// session 22).
inline constexpr unsigned kPointsPerLeaf = 32;

/// vcglib's tree (its protected members have the same names and meanings in the vcglib of
/// MeshLab 2020.09, 2022.02 and 2025.07).
struct KdTreeWithSlots : vcg::KdTree<double> {
    using Base = vcg::KdTree<double>;
    using Base::KdTree;

    /// The tree of `points` (at least one), with leaves of kPointsPerLeaf: vcglib's tree, by
    /// its createTree on the whole cloud, or where the cloud is large with the subtrees below
    /// the top levels built in parallel (the same split at every node, the same points in every
    /// leaf, in the same slot order; only the nodes' numbers differ, which no query depends
    /// on). Where vcglib's split reads past a node's points (all of them below its split value
    /// rounded to float: copies of a point at a coordinate no float holds) it reads padding,
    /// not past the arrays, and a tree whose leaves then do not tile the slots, or that has a
    /// leaf too large for vcglib's 16-bit size, is built again by create_tree_guarded. The tree
    /// is the same for any thread count. Another vcglib (no createTree to call): its constructor.
    KdTreeWithSlots(const std::vector<Vec3>& points, const Execution& exec);

    const std::vector<unsigned int>& slot_points() const { return mIndices; }

    /// Whether this vcglib's build can be split by levels: createTree(node, start, end, level)
    /// stops at targetMaxDepth and returns the depth it reached (vcglib of MeshLab 2020.09).
    template <class Self = KdTreeWithSlots>
    static auto splits_by_levels(Self* t)
        -> decltype(int(t->createTree(0U, 0U, 0U, 0U)), t->targetMaxDepth = 0U,
                    t->targetCellSize = 0U, t->numLevel = 0U,
                    t->mAABB.Add(typename Self::VectorType()), std::true_type());
    static std::false_type splits_by_levels(...);
    static constexpr bool builds_by_levels() {
        return decltype(splits_by_levels(static_cast<KdTreeWithSlots*>(nullptr)))::value;
    }

private:
    /// Below this many points the sequential build is as fast.
    static constexpr std::size_t kParallelFrom = 1U << 16;

    /// Levels built by vcglib's createTree on the whole cloud (2^5 subtrees below them):
    /// fixed, so that the tree does not depend on the thread count.
    static constexpr unsigned kTopLevels = 5;

    /// Runs createTree(0, 0, size, level) on t's slots [0, size) with slots past them that no
    /// coordinate is below: where vcglib's split reads past a node's points (all below the
    /// split value rounded to float), and the ranges it then makes read on, one slot further a
    /// level, they stay in the array. The slots past `size` are removed after.
    template <class Self>
    static int create_tree_padded(Self& t, unsigned size, unsigned level) {
        const double inf = std::numeric_limits<double>::infinity();
        const std::size_t pad = std::size_t(t.targetMaxDepth) + 2;
        t.mPoints.resize(size);
        t.mIndices.resize(size);
        t.mPoints.resize(size + pad, typename Self::VectorType(inf, inf, inf));
        t.mIndices.resize(size + pad, 0U);
        t.mNodes.assign(1, typename Self::Node());
        t.mNodes.back().leaf = 0;
        const int levels = t.createTree(0, 0, size, level);
        t.mPoints.resize(size);
        t.mIndices.resize(size);
        return levels;
    }

    // A slot range [start, end) at a leaf of the top levels.
    struct Stretch {
        std::size_t node;
        unsigned start, end;
        unsigned depth; ///< of the leaf, the root's being 1
    };

    // The leaves under `node` in depth-first order (left first), their ranges from their starts
    // (vcglib keeps a leaf's size in 16 bits; the leaves tile the slots in this order).
    template <class Self>
    static void leaves(const Self& t, std::size_t node, unsigned depth, std::vector<Stretch>& out) {
        const auto& n = t.mNodes[node];
        if (n.leaf) {
            out.push_back({node, n.start, 0, depth});
            return;
        }
        leaves(t, n.firstChildId, depth + 1, out);
        leaves(t, n.firstChildId + 1, depth + 1, out);
    }

    // A subtree below the top levels: its nodes (root first, children numbered from 1) and
    // the depth createTree reached there.
    template <class Self>
    struct Subtree {
        std::vector<typename Self::Node> nodes;
        int levels = 0;
    };

    // The slots [0, n) hold the points in order and the box is theirs (vcglib's constructor's
    // first loop), by blocks: the box's min and max do not depend on the order.
    template <class Self>
    static void copy_points(Self& t, const std::vector<Vec3>& points, const Execution& exec) {
        const auto n = unsigned(points.size());
        const std::size_t room = std::size_t(n) + t.targetMaxDepth + 2; // create_tree_padded
        t.mPoints.reserve(room);
        t.mIndices.reserve(room);
        t.mPoints.resize(n);
        t.mIndices.resize(n);
        std::vector<typename Self::AxisAlignedBoxType> boxes(block_count(n, kCheapBlock));
        parallel_for_blocks(exec, n, kCheapBlock,
                            [&](std::size_t b, std::size_t first, std::size_t end) {
                                boxes[b].Set(points[first]);
                                for (std::size_t i = first; i < end; ++i) {
                                    t.mPoints[i] = points[i];
                                    t.mIndices[i] = unsigned(i);
                                    boxes[b].Add(points[i]);
                                }
                            });
        t.mAABB = boxes.front();
        for (const auto& b : boxes) t.mAABB.Add(b);
    }

    // The leaves with their ranges; empty where the ranges do not tile the slots [0, n) with
    // the sizes vcglib keeps in 16 bits (a split read past its node).
    template <class Self>
    static std::vector<Stretch> tiled_leaves(const Self& t, unsigned n) {
        std::vector<Stretch> stretches;
        leaves(t, 0, 1, stretches);
        if (stretches.front().start != 0) return {};
        for (std::size_t s = 0; s < stretches.size(); ++s) {
            Stretch& l = stretches[s];
            l.end = s + 1 < stretches.size() ? stretches[s + 1].start : n;
            if (l.start > l.end ||
                t.mNodes[l.node].size != static_cast<unsigned short>(l.end - l.start))
                return {};
        }
        return stretches;
    }

    // The leaves the stop at depth `stop` made: at the stop's depth, too large for a leaf, and
    // not one of the two of a split that left one side empty (those stay leaves at any depth).
    template <class Self>
    static std::vector<Stretch> stopped_leaves(const Self& t, const std::vector<Stretch>& all,
                                               unsigned stop) {
        std::vector<Stretch> stopped;
        if (t.targetMaxDepth <= stop) return stopped;
        for (std::size_t s = 0; s < all.size(); ++s) {
            const Stretch& l = all[s];
            if (l.depth != stop + 1 || l.end - l.start <= t.targetCellSize) continue;
            const Stretch& sibling = all[l.node % 2 == 1 ? s + 1 : s - 1]; // left ids are odd
            if (sibling.end > sibling.start) stopped.push_back(l);
        }
        return stopped;
    }

    // The subtree createTree would build at leaf l, in a tree of its own slots; the slots come
    // back into t's reordered as its splits left them.
    template <class Self>
    static Subtree<Self> grow(Self& t, const Stretch& l, const std::vector<Vec3>& points) {
        Self sub(vcg::ConstDataWrapper<Vec3>(points.data(), 1), t.targetCellSize, t.targetMaxDepth);
        const unsigned size = l.end - l.start;
        sub.mPoints.reserve(std::size_t(size) + t.targetMaxDepth + 2); // create_tree_padded
        sub.mIndices.reserve(std::size_t(size) + t.targetMaxDepth + 2);
        sub.mPoints.assign(t.mPoints.begin() + l.start, t.mPoints.begin() + l.end);
        sub.mIndices.assign(t.mIndices.begin() + l.start, t.mIndices.begin() + l.end);
        Subtree<Self> out;
        out.levels = create_tree_padded(sub, size, l.depth);
        std::copy(sub.mPoints.begin(), sub.mPoints.end(), t.mPoints.begin() + l.start);
        std::copy(sub.mIndices.begin(), sub.mIndices.end(), t.mIndices.begin() + l.start);
        out.nodes = std::move(sub.mNodes);
        return out;
    }

    // The subtree's nodes appended to t's, its root replacing leaf l, renumbered.
    template <class Self>
    static void append(Self& t, const Stretch& l, const Subtree<Self>& sub) {
        const auto offset = unsigned(t.mNodes.size()) - 1; // sub's node 1 goes to size()
        const auto renumbered = [&](typename Self::Node node) {
            if (node.leaf)
                node.start += l.start;
            else
                node.firstChildId = node.firstChildId + offset;
            return node;
        };
        t.mNodes[l.node] = renumbered(sub.nodes[0]);
        for (std::size_t k = 1; k < sub.nodes.size(); ++k)
            t.mNodes.push_back(renumbered(sub.nodes[k]));
    }

    // Whether the leaves tile the slots [0, n) with the sizes they keep: not where a split read
    // past its node, nor for a leaf of 65,536 points or more (its size does not fit 16 bits).
    template <class Self>
    static bool leaves_tile(const Self& t, unsigned n) {
        const std::vector<Stretch> stretches = tiled_leaves(t, n);
        return !stretches.empty() &&
               std::all_of(stretches.begin(), stretches.end(),
                           [](const Stretch& l) { return l.end - l.start <= 0xffffU; });
    }

    // createTree's tree built again where its split broke it (its float comparison: every point
    // of a node below the split value; copies of a point at a coordinate no float holds): the
    // same box, axis and split value, the points parted by the value in double, and a node
    // whose points all lie on one side (all within a few units in the last place) halved by
    // slots, its split value still a bound for the query's pruning to within those units.
    template <class Self>
    static int create_tree_guarded(Self& t, unsigned node, unsigned start, unsigned end,
                                   unsigned level) {
        typename Self::AxisAlignedBoxType box;
        box.Set(t.mPoints[start]);
        for (unsigned i = start + 1; i < end; ++i) box.Add(t.mPoints[i]);
        const auto diag = box.max - box.min;
        const unsigned dim =
            diag[0] > diag[1] ? (diag[0] > diag[2] ? 0 : 2) : (diag[1] > diag[2] ? 1 : 2);
        const double split = 0.5 * (box.max[dim] + box.min[dim]);
        unsigned mid = start;
        for (unsigned i = start; i < end; ++i)
            if (t.mPoints[i][dim] < split) {
                std::swap(t.mPoints[i], t.mPoints[mid]);
                std::swap(t.mIndices[i], t.mIndices[mid]);
                ++mid;
            }
        if (mid == start || mid == end) mid = start + (end - start) / 2;
        const auto first = unsigned(t.mNodes.size());
        t.mNodes[node].dim = dim;
        t.mNodes[node].splitValue = split;
        t.mNodes[node].firstChildId = first;
        t.mNodes[node].leaf = 0;
        t.mNodes.resize(t.mNodes.size() + 2);
        int levels = int(level);
        const unsigned from[2] = {start, mid}, to[2] = {mid, end};
        for (unsigned c = 0; c < 2; ++c) {
            auto& child = t.mNodes[first + c];
            if (to[c] - from[c] <= t.targetCellSize || level >= t.targetMaxDepth) {
                child.leaf = 1;
                child.start = from[c];
                child.size = static_cast<unsigned short>(to[c] - from[c]);
            } else {
                child.leaf = 0;
                levels =
                    std::max(levels, create_tree_guarded(t, first + c, from[c], to[c], level + 1));
            }
        }
        return levels;
    }

    template <class Self = KdTreeWithSlots>
    void build(const std::vector<Vec3>& points, const Execution& exec) {
        Self& t = *static_cast<Self*>(this);
        const auto n = unsigned(points.size());
        bool built = true;
        if (n < kParallelFrom) { // vcglib's constructor, padded
            copy_points(t, points, exec);
            t.numLevel = unsigned(create_tree_padded(t, n, 1));
        } else {
            built = build_by_levels(points, exec);
        }
        if (built && leaves_tile(t, n)) return;
        copy_points(t, points, exec); // n > 1: one point is always a leaf that tiles
        t.mNodes.assign(1, typename Self::Node());
        t.numLevel = unsigned(create_tree_guarded(t, 0, 0, n, 1));
    }

    // False where a split of the top levels read past its node (the tree is then unfinished:
    // createTree would break the same way on the whole cloud).
    template <class Self = KdTreeWithSlots>
    bool build_by_levels(const std::vector<Vec3>& points, const Execution& exec) {
        Self& t = *static_cast<Self*>(this);
        const auto n = unsigned(points.size());
        copy_points(t, points, exec);
        // The top levels by vcglib's own createTree, stopped at kTopLevels.
        const unsigned max_depth = t.targetMaxDepth, stop = std::min(kTopLevels, max_depth);
        t.targetMaxDepth = stop;
        int levels = create_tree_padded(t, n, 1);
        t.targetMaxDepth = max_depth;
        const std::vector<Stretch> stretches = tiled_leaves(t, n);
        if (stretches.empty()) return false;
        const std::vector<Stretch> stopped = stopped_leaves(t, stretches, stop);
        std::vector<Subtree<Self>> subtrees(stopped.size());
        parallel_for(
            exec, stopped.size(), [&](std::size_t g) { subtrees[g] = grow(t, stopped[g], points); },
            1);
        for (std::size_t g = 0; g < stopped.size(); ++g) {
            append(t, stopped[g], subtrees[g]);
            levels = std::max(levels, subtrees[g].levels);
        }
        t.numLevel = unsigned(levels);
        return true;
    }
};

inline KdTreeWithSlots::KdTreeWithSlots(const std::vector<Vec3>& points, const Execution& exec)
    : Base(vcg::ConstDataWrapper<Vec3>(points.data(), builds_by_levels() ? 1 : int(points.size())),
           kPointsPerLeaf) {
    if constexpr (builds_by_levels()) build(points, exec);
}

} // namespace hrsr
