#include "knn.h"

#include <vcg/space/index/kdtree/kdtree.h>

#include <algorithm>
#include <limits>
#include <new>

namespace hrsr {

// Leaves of 32 points instead of vcglib's 16: fewer nodes to descend for the same points; on the
// 800k dragon sample queries at k = 1, 8, 71 and 193 took 6–18 % less (docs/BENCHMARKS.md,
// session 22).
constexpr unsigned kPointsPerLeaf = 32;

struct KnnIndex::Tree {
    explicit Tree(const std::vector<Vec3>& points)
        : kd(vcg::ConstDataWrapper<Vec3>(points.data(), int(points.size())), kPointsPerLeaf) {}
    vcg::KdTree<double> kd;
};

KnnIndex::KnnIndex(const std::vector<Vec3>& points) : points_(points), size_(points.size()) {
    // vcg's constructor reads points[0]: an empty tree must never be built.
    if (!points_.empty()) tree_ = std::make_unique<Tree>(points_);
}

KnnIndex::~KnnIndex() = default;

namespace {
bool closer(const Neighbour& a, const Neighbour& b) {
    return a.squared_distance < b.squared_distance ||
           (a.squared_distance == b.squared_distance && a.index < b.index);
}

// vcg returns a max-heap; ties at equal distance come in traversal order. Sorting by
// (distance, index) gives one order for everybody (D-10). Sorted by distance alone first and the
// rare runs of equal distances by index after: the same order, and the one comparison is what
// makes it cheaper (the sort was a third of a query at k = 192).
void sort_neighbours(std::vector<Neighbour>& out) {
    std::sort(out.begin(), out.end(), [](const Neighbour& a, const Neighbour& b) {
        return a.squared_distance < b.squared_distance;
    });
    for (auto run = out.begin(); run != out.end();) {
        auto end = run + 1;
        while (end != out.end() && end->squared_distance == run->squared_distance) ++end;
        if (end - run > 1) std::sort(run, end, closer);
        run = end;
    }
}

// The queue of vcg's k-nearest query, reused per thread: vcg reallocates its storage only when k
// changes.
vcg::KdTree<double>::PriorityQueue& query_queue() {
    thread_local vcg::KdTree<double>::PriorityQueue queue;
    return queue;
}
} // namespace

void KnnIndex::nearest(const Vec3& p, int k, std::vector<Neighbour>& out) const {
    out.clear();
    if (!tree_ || k <= 0) return;
    const int wanted = int(std::min<std::size_t>(std::size_t(k), size_));
    vcg::KdTree<double>::PriorityQueue& queue = query_queue();
    tree_->kd.doQueryK(p, wanted, queue);
    out.resize(std::size_t(queue.getNofElements()));
    // vcg's weights are SquaredNorm(p − q) in double: bit for bit (q − p).SquaredNorm(), which
    // callers compute, so they are taken as they are. (Recomputing them read every neighbour's
    // point again in input order, scattered in memory: 14 % of the normal pipeline's profile.)
    for (int e = 0; e < queue.getNofElements(); ++e)
        out[std::size_t(e)] = {std::uint32_t(queue.getIndex(e)), queue.getWeight(e)};
    sort_neighbours(out);
}

void KnnIndex::squared_distances_at_ranks(std::uint32_t i, const std::vector<int>& ranks,
                                          std::vector<double>& out) const {
    const int deepest = ranks.empty() ? 0 : *std::max_element(ranks.begin(), ranks.end());
    out.assign(ranks.size(), std::numeric_limits<double>::infinity());
    if (!tree_ || deepest < 1) return;
    // The point itself is one of the deepest + 1 nearest (at distance 0, or tied with more than
    // `deepest` exact duplicates of it, all at 0), so the r-th neighbour's distance is the
    // (r + 1)-th smallest: no order of the indices is needed, only of the distances.
    const int wanted = int(std::min<std::size_t>(std::size_t(deepest) + 1, size_));
    vcg::KdTree<double>::PriorityQueue& queue = query_queue();
    tree_->kd.doQueryK(points_[i], wanted, queue);
    thread_local std::vector<double> distances;
    distances.resize(std::size_t(queue.getNofElements()));
    for (int e = 0; e < queue.getNofElements(); ++e) distances[std::size_t(e)] = queue.getWeight(e);
    for (std::size_t r = 0; r < ranks.size(); ++r) {
        const std::size_t at = std::size_t(std::max(ranks[r], 0));
        if (ranks[r] < 1 || at >= distances.size()) continue;
        std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(at),
                         distances.end());
        out[r] = distances[at];
    }
}

void KnnIndex::neighbours_of(std::uint32_t i, int k, std::vector<Neighbour>& out) const {
    const int wanted = int(std::min<std::size_t>(std::size_t(std::max(k, 0)), size_ - 1));
    nearest(points_[i], wanted + 1, out);
    auto self =
        std::find_if(out.begin(), out.end(), [i](const Neighbour& n) { return n.index == i; });
    if (self != out.end()) {
        out.erase(self);
    } else if (!out.empty()) {
        out.pop_back(); // only with more than `wanted` exact duplicates of point i
    }
    if (out.size() > std::size_t(wanted)) out.resize(std::size_t(wanted));
}

bool KnnIndex::at_least(const Vec3& p, double radius, std::size_t count,
                        const std::function<bool(double)>& accept) const {
    if (count == 0) return true;
    if (!tree_) return false;
    const auto& nodes = tree_->kd._getNodes();
    const auto& points = tree_->kd._getPoints();
    const double squared_radius = radius * radius;
    // Depth first, the side of each split holding p first; a cell is entered only when its
    // split plane is within `radius` (as vcg's own queries prune, but in double).
    struct Cell {
        unsigned node;
        double squared_plane_distance;
    };
    thread_local std::vector<Cell> stack;
    stack.assign(1, {0U, 0.0});
    std::size_t found = 0;
    while (!stack.empty()) {
        const Cell cell = stack.back();
        stack.pop_back();
        if (cell.squared_plane_distance > squared_radius) continue;
        const auto& node = nodes[cell.node];
        if (node.leaf) {
            for (unsigned i = node.start, end = node.start + node.size; i < end; ++i) {
                const double squared = vcg::SquaredNorm(p - points[i]);
                if (squared <= squared_radius && accept(squared) && ++found == count) return true;
            }
            continue;
        }
        const double offset = p[int(node.dim)] - node.splitValue;
        const unsigned below = node.firstChildId, above = node.firstChildId + 1;
        stack.push_back({offset < 0 ? above : below, offset * offset});
        stack.push_back({offset < 0 ? below : above, cell.squared_plane_distance});
    }
    return false;
}

void KnnIndex::within(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (!tree_) return;
    thread_local std::vector<unsigned int> indices;
    thread_local std::vector<double> squared;
    indices.clear();
    squared.clear();
    tree_->kd.doQueryDist(p, float(radius), indices, squared);
    out.assign(indices.begin(), indices.end());
}

void reserve_room_for_union(std::vector<std::uint32_t>& buffer, std::size_t entries) {
    try { // the union adds at most one relation per entry
        buffer.reserve(2 * entries);
    } catch (const std::bad_alloc&) {
        buffer.reserve(entries);
    }
}

KnnTable knn_table(const KnnIndex& index, int k, const Execution& exec) {
    KnnTable table;
    const std::size_t n = index.size();
    if (n < 2 || k <= 0) return table;
    table.k = int(std::min<std::size_t>(std::size_t(k), n - 1));
    reserve_room_for_union(table.index, n * std::size_t(table.k));
    table.index.resize(n * std::size_t(table.k));
    parallel_for(exec, n, [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        index.neighbours_of(std::uint32_t(i), table.k, found);
        std::uint32_t* row = table.index.data() + i * std::size_t(table.k);
        for (int j = 0; j < table.k; ++j) row[j] = found[std::size_t(j)].index;
    });
    return table;
}

} // namespace hrsr
