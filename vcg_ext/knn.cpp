#include "knn.h"

#include "knn_tree.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <new>

namespace hrsr {

struct KnnIndex::Tree {
    Tree(const std::vector<Vec3>& points, const Execution& exec) : kd(points, exec) {}
    KdTreeWithSlots kd;
};

KnnIndex::KnnIndex(const std::vector<Vec3>& points) : KnnIndex(points, Execution{1, nullptr}) {}

KnnIndex::KnnIndex(const std::vector<Vec3>& points, const Execution& exec)
    : points_(points.data()), size_(points.size()) {
    // vcg's constructor reads points[0]: an empty tree must never be built.
    if (points.empty()) return;
    tree_ = std::make_unique<Tree>(points, exec);
    const auto& box = tree_->kd._getAABBox(); // vcglib's, of these points
    for (int a = 0; a < 3; ++a)
        coordinate_scale_ =
            std::max({coordinate_scale_, std::abs(box.min[a]), std::abs(box.max[a])});
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

namespace {
// Calls visit(slot, squared distance) for every point of the tree within sqrt(squared_radius)
// of p, until visit returns true (then true). Depth first, the side of each split holding p
// first; a cell is entered only when its split plane is within the radius (as vcg's own queries
// prune, but in double).
template <class Visit>
bool visit_within(KdTreeWithSlots& kd, const Vec3& p, double squared_radius, Visit&& visit) {
    const auto& nodes = kd._getNodes();
    const auto& points = kd._getPoints();
    struct Cell {
        unsigned node;
        double squared_plane_distance;
    };
    thread_local std::vector<Cell> stack;
    stack.assign(1, {0U, 0.0});
    while (!stack.empty()) {
        const Cell cell = stack.back();
        stack.pop_back();
        if (cell.squared_plane_distance > squared_radius) continue;
        const auto& node = nodes[cell.node];
        if (node.leaf) {
            for (unsigned e = node.start, end = node.start + node.size; e < end; ++e) {
                const double squared = vcg::SquaredNorm(p - points[e]);
                if (squared <= squared_radius && visit(e, squared)) return true;
            }
            continue;
        }
        // The points were parted at the split value, or (vcglib of MeshLab 2020.09) at it in
        // single precision: the far side is no nearer than the plane less that difference.
        const double split = node.splitValue;
        const double offset = p[int(node.dim)] - split;
        const double beyond =
            std::max(0.0, std::abs(offset) - std::abs(split - double(float(split))));
        const unsigned below = node.firstChildId, above = node.firstChildId + 1;
        stack.push_back({offset < 0 ? above : below, beyond * beyond});
        stack.push_back({offset < 0 ? below : above, cell.squared_plane_distance});
    }
    return false;
}
} // namespace

bool KnnIndex::at_least(const Vec3& p, double radius, std::size_t count,
                        const std::function<bool(double)>& accept) const {
    if (count == 0) return true;
    if (!tree_) return false;
    std::size_t found = 0;
    return visit_within(tree_->kd, p, radius * radius, [&](unsigned, double squared) {
        return accept(squared) && ++found == count;
    });
}

bool KnnIndex::neighbours_within(std::uint32_t i, double radius, int k, std::vector<Neighbour>& out,
                                 bool walk_order, std::size_t at_most) const {
    out.clear();
    if (!tree_) return k <= 0;
    if (k <= 0) return true;
    // Near ties: vcglib's float pruning misjudges a split plane's distance by at most about
    // 2^-24 of it and of the split coordinate, so where the k-th and the next are further apart
    // than this, its query cannot have missed any of the k nearest.
    const double relative = 1e-6, absolute = 1e-6 * coordinate_scale_;
    const double gathered = radius * (1 + relative) + absolute; // holds a near tie of the k-th
    const auto& slot_points = tree_->kd.slot_points();
    const bool too_many = visit_within(tree_->kd, points_[i], gathered * gathered,
                                       [&](unsigned slot, double squared) {
                                           if (slot_points[slot] != i)
                                               out.push_back({slot_points[slot], squared});
                                           return out.size() > at_most;
                                       });
    if (too_many || out.size() < std::size_t(k)) return false;
    thread_local std::vector<double> distances;
    distances.resize(out.size());
    for (std::size_t e = 0; e < out.size(); ++e) distances[e] = out[e].squared_distance;
    if (distances.size() > std::size_t(k))
        std::nth_element(distances.begin(), distances.begin() + k, distances.end());
    const double kth = *std::max_element(distances.begin(), distances.begin() + k);
    const double kth_distance = std::sqrt(kth);
    if (kth_distance > radius) return false; // the next one may lie beyond what was gathered
    // A tie, exact or near, at the k-th distance: which of them vcglib's query keeps only its
    // walk decides (exact ties on the torus model's regular grid: RsR closed with vcglib's
    // choice, a 10-edge slit with the smallest indices). Left to that query.
    if (distances.size() > std::size_t(k) &&
        std::sqrt(distances[std::size_t(k)]) <= kth_distance * (1 + relative) + absolute)
        return false;
    out.erase(std::remove_if(out.begin(), out.end(),
                             [kth](const Neighbour& n) { return n.squared_distance > kth; }),
              out.end());
    if (!walk_order) sort_neighbours(out);
    return true;
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

// A relative margin on a kept radius for the rounding of distances recomputed and squared again.
constexpr double kRadiusMargin = 1e-9;

namespace {
// A radius kept in float (half the memory) never below the double it stands for.
float rounded_up(double r) {
    const auto f = float(r);
    return double(f) >= r ? f : std::nextafter(f, HUGE_VALF);
}

// A NeighbourReach round meets its points in spatial order (D-40), so the point a thread served
// last lies near the next one and was about as densely sampled: its k-th distance, widened, is
// the next one's first radius to try where none is kept. A guess changes only the work: it is
// taken only where it holds the k nearest, beyond the k-th by the margin the query's radius has
// and with no tie there, and the walk meets them in the same order whatever its radius
// (docs/BENCHMARKS.md, session 43).
constexpr double kGuessWidening = 1.1;
// A guess that gathers more than this many times k, plus a few, is given up (after an outlier).
constexpr std::size_t kMaxGatheredPerNeighbour = 4;

std::atomic<std::uint64_t> last_pass{0}; // rounds numbered apart: no guess from another round

struct LastReach {
    std::uint64_t pass = 0;
    double radius = 0;
};
thread_local LastReach last_reach;

double guessed_radius(std::uint64_t pass) {
    return last_reach.pass == pass ? last_reach.radius * kGuessWidening : 0;
}

// The distance of the farthest of `found` (the k-th of the k nearest).
double farthest_of(const std::vector<Neighbour>& found) {
    double farthest = 0;
    for (const Neighbour& n : found) farthest = std::max(farthest, n.squared_distance);
    return std::sqrt(farthest);
}

// The k nearest of point i by the guess where the path by vcglib's k-th distance would find
// them in the same order: not at a k-th distance of 0 (copies of the point: that path sorts
// them), nor within its margin of the guess.
bool neighbours_by_guess(const KnnIndex& index, std::uint32_t i, int k, std::uint64_t pass,
                         std::vector<Neighbour>& out) {
    const double radius = guessed_radius(pass);
    if (!(radius > 0 && index.neighbours_within(i, radius, k, out, true,
                                                kMaxGatheredPerNeighbour * std::size_t(k) + 64)))
        return false;
    const double kth = farthest_of(out);
    return kth > 0 && kth * (1 + kRadiusMargin) <= radius;
}
} // namespace

void NeighbourReach::begin_round(std::size_t points, int k) {
    pass_ = ++last_pass;
    if (k == k_ && radius_.size() == points) return;
    k_ = k;
    radius_.assign(points, 0.0f);
}

void NeighbourReach::neighbours(const KnnIndex& index, std::uint32_t i,
                                std::vector<Neighbour>& out) {
    const double radius = radius_[i];
    const bool found = radius > 0
                           ? index.neighbours_within(i, radius * (1 + kRadiusMargin), k_, out, true)
                           : neighbours_by_guess(index, i, k_, pass_, out);
    if (!found) {
        // The k-th distance by vcglib's query, then the points within it in the walk's order;
        // tied at the k-th, the query's own (sorted).
        thread_local std::vector<int> rank(1);
        thread_local std::vector<double> kth;
        rank[0] = k_;
        index.squared_distances_at_ranks(i, rank, kth);
        const double reach = std::sqrt(kth.front());
        if (!(reach > 0 && std::isfinite(reach) &&
              index.neighbours_within(i, reach * (1 + kRadiusMargin), k_, out, true)))
            index.neighbours_of(i, k_, out);
    }
    const double kth = farthest_of(out);
    last_reach = {pass_, kth};
    radius_[i] = rounded_up(kth);
}

void NeighbourReach::moved(const std::vector<Vec3>& before, const std::vector<double>& shift,
                           const Execution& exec) {
    const std::size_t n = std::min(radius_.size(), before.size());
    if (n == 0) return;
    // The grid: cells about the mean radius, at most kMaxCellsPerAxis a side.
    Vec3 lo = before[0], hi = before[0];
    double radius_sum = 0;
    std::size_t known = 0;
    for (std::size_t i = 0; i < n; ++i) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], before[i][a]);
            hi[a] = std::max(hi[a], before[i][a]);
        }
        if (radius_[i] > 0) {
            radius_sum += radius_[i];
            ++known;
        }
    }
    if (known == 0) return;
    const Vec3 extent = hi - lo;
    const double largest = std::max({extent[0], extent[1], extent[2]});
    const double cell = std::max(radius_sum / double(known), largest / kMaxCellsPerAxis);
    std::size_t cells[3];
    for (int a = 0; a < 3; ++a) cells[a] = std::size_t(extent[a] / cell) + 1;
    const auto coordinate = [&](double x, int a) {
        return std::min(cells[a] - 1, std::size_t(std::max(0.0, (x - lo[a]) / cell)));
    };
    std::vector<float> largest_shift(cells[0] * cells[1] * cells[2], 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t c =
            (coordinate(before[i][0], 0) * cells[1] + coordinate(before[i][1], 1)) * cells[2] +
            coordinate(before[i][2], 2);
        // Rounded up to float, so that the bound never shrinks.
        const float s = std::nextafter(float(std::abs(shift[i])), HUGE_VALF);
        largest_shift[c] = std::max(largest_shift[c], s);
    }
    parallel_for_blocks(exec, n, kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) {
            const double r = radius_[i];
            if (!(r > 0)) continue;
            // The ball holds point i's k nearest; widened for the rounding of its box.
            const double reach = r * (1 + 1e-6) + 1e-12 * (1 + largest);
            std::size_t from[3], to[3];
            bool wide = false; // a radius far above the mean: its query as it comes
            for (int a = 0; a < 3; ++a) {
                from[a] = coordinate(before[i][a] - reach, a);
                to[a] = coordinate(before[i][a] + reach, a);
                wide = wide || to[a] - from[a] > kMaxCellsAcrossBall;
            }
            if (wide) {
                radius_[i] = 0.0f;
                continue;
            }
            double near = 0;
            for (std::size_t x = from[0]; x <= to[0]; ++x)
                for (std::size_t y = from[1]; y <= to[1]; ++y)
                    for (std::size_t z = from[2]; z <= to[2]; ++z)
                        near = std::max(near,
                                        double(largest_shift[(x * cells[1] + y) * cells[2] + z]));
            const double grown = r + std::abs(shift[i]) + near;
            radius_[i] = grown <= kMaxGrowth * r ? rounded_up(grown) : 0.0f;
        }
    });
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
