#include "hrsr/collapse.h"

#include "geometry.h"
#include "graph/neighbour_graph.h"
#include "knn.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace hrsr {

namespace {

// A queued edge, valid while both endpoints still have the versions they had when it was pushed
// (lazy deletion: merging a node bumps its version, which invalidates all its old entries).
struct QueuedEdge {
    double priority;
    std::uint32_t lo, hi;
    std::uint32_t lo_version, hi_version;
    bool operator>(const QueuedEdge& o) const {
        return std::tie(priority, lo, hi) > std::tie(o.priority, o.lo, o.hi); // D-10
    }
};

class Collapser {
public:
    Collapser(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals)
        : x_(positions), n_(normals), w_(positions.size(), 1), version_(positions.size(), 0),
          alive_(positions.size(), 1), neighbours_(positions.size()) {}

    void build_graph(int k, const Execution& exec) {
        { // the kd-tree and the kNN graphs are freed before the queue is filled (peak memory)
            KnnTable table;
            {
                const KnnIndex index(x_); // freed before the union's arrays are allocated
                table = knn_table(index, k, exec);
            }
            const CsrGraph g = symmetric_union(std::move(table), x_.size(), exec);
            for (std::uint32_t i = 0; i < g.size(); ++i) {
                neighbours_[i].reserve(std::size_t(g.end(i) - g.begin(i))); // one allocation each
                for (const std::uint32_t* j = g.begin(i); j != g.end(i); ++j)
                    if (n_[i].dot(n_[*j]) >= 0)
                        neighbours_[i].push_back(*j); // D-14: > 90° never linked
            }
        }
        for (const auto& list : neighbours_) edges_ += list.size();
        edges_ /= 2;
        queue_.reserve(edges_ + edges_ / 4 + 16); // room for stale entries, see drop_stale_entries
        for (std::uint32_t i = 0; i < neighbours_.size(); ++i)
            for (std::uint32_t j : neighbours_[i])
                if (i < j) queue_.push_back(entry(i, j));
        std::make_heap(queue_.begin(), queue_.end(), std::greater<QueuedEdge>());
    }

    // Pops and performs the next valid collapse; false when no valid edge is left.
    bool collapse_next(std::vector<CollapseRecord>& records) {
        while (!queue_.empty()) {
            std::pop_heap(queue_.begin(), queue_.end(), std::greater<QueuedEdge>());
            const QueuedEdge e = queue_.back();
            queue_.pop_back();
            if (stale(e)) continue;
            if (n_[e.lo].dot(n_[e.hi]) < 0) continue; // D-15: merged normals may have turned apart
            merge(e.lo, e.hi, records);
            return true;
        }
        return false;
    }

    const std::vector<Vec3>& positions() const { return x_; }
    const std::vector<Vec3>& normals() const { return n_; }
    const std::vector<std::uint32_t>& weights() const { return w_; }
    bool alive(std::uint32_t i) const { return alive_[i]; }

private:
    bool stale(const QueuedEdge& e) const {
        return !alive_[e.lo] || !alive_[e.hi] || version_[e.lo] != e.lo_version ||
               version_[e.hi] != e.hi_version;
    }

    // Every graph edge has at most one valid entry and the graph only loses edges, so when the
    // heap is about to outgrow the room reserved for it (a quarter more than the first edge
    // count), at least a fifth of it is stale: it is rebuilt from the valid entries instead of
    // reallocated. Memory stays at the reservation, and the valid entries (totally ordered,
    // D-10) come out in the same order as before.
    void drop_stale_entries(std::size_t incoming) {
        if (queue_.size() + incoming <= queue_.capacity()) return;
        queue_.erase(std::remove_if(queue_.begin(), queue_.end(),
                                    [&](const QueuedEdge& e) { return stale(e); }),
                     queue_.end());
        std::make_heap(queue_.begin(), queue_.end(), std::greater<QueuedEdge>());
    }

    QueuedEdge entry(std::uint32_t a, std::uint32_t b) const {
        const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
        // §6.1: tangent distance times the merged weight, in both distance modes.
        const double priority =
            tangent_distance(x_[hi] - x_[lo], n_[lo], n_[hi]) * double(w_[lo] + w_[hi]);
        return {priority, lo, hi, version_[lo], version_[hi]};
    }

    void push(std::uint32_t a, std::uint32_t b) {
        queue_.push_back(entry(a, b));
        std::push_heap(queue_.begin(), queue_.end(), std::greater<QueuedEdge>());
    }

    void merge(std::uint32_t a, std::uint32_t b, std::vector<CollapseRecord>& records) {
        const double wa = w_[a], wb = w_[b], total = wa + wb;
        const Vec3 merged = (x_[a] * wa + x_[b] * wb) / total;
        Vec3 normal = (n_[a] * wa + n_[b] * wb) / total;
        const double length = normal.Norm();
        normal = length > 1e-12 ? normal / length : n_[a]; // D-9
        records.push_back({a, b, x_[a], x_[b]});
        x_[a] = merged;
        n_[a] = normal;
        w_[a] += w_[b];
        alive_[b] = 0;
        ++version_[a];
        ++version_[b];
        // b's neighbours become a's (no repeats, no self loops).
        edges_ -= neighbours_[b].size();
        for (std::uint32_t c : neighbours_[b]) {
            auto& list = neighbours_[c];
            list.erase(std::remove(list.begin(), list.end(), b), list.end());
            if (c == a) continue;
            if (std::find(neighbours_[a].begin(), neighbours_[a].end(), c) ==
                neighbours_[a].end()) {
                neighbours_[a].push_back(c);
                list.push_back(a);
                ++edges_;
            }
        }
        std::vector<std::uint32_t>().swap(neighbours_[b]);
        drop_stale_entries(neighbours_[a].size());
        for (std::uint32_t c : neighbours_[a]) push(a, c);
    }

    std::vector<Vec3> x_, n_;
    std::vector<std::uint32_t> w_, version_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::vector<std::uint32_t>> neighbours_;
    std::size_t edges_ = 0;         ///< edges of the current graph
    std::vector<QueuedEdge> queue_; ///< binary min-heap on (priority, lo, hi), with stale entries
};

} // namespace

CollapsedCloud collapse(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                        const CollapseOptions& options, const Execution& exec) {
    validate(options);
    const std::size_t n = positions.size();
    CollapsedCloud result;
    result.budget = n - std::min(n, std::size_t(std::llround(double(n) * options.collapse_ratio)));
    if (options.max_collapses > 0) result.budget = std::min(result.budget, options.max_collapses);

    Collapser collapser(positions, normals);
    if (result.budget > 0) {
        if (exec.progress) exec.progress->begin("collapse graph");
        collapser.build_graph(options.collapse_k, exec);
        if (exec.progress) exec.progress->begin("collapse");
        result.records.reserve(result.budget);
        while (result.records.size() < result.budget) {
            if (!collapser.collapse_next(result.records)) {
                result.ran_out_of_edges = true; // §6.2: stop gracefully, report the ratio reached
                break;
            }
            if (exec.progress && (result.records.size() & 0x3fff) == 0)
                exec.progress->update(double(result.records.size()) / double(result.budget));
        }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        if (!collapser.alive(i)) continue;
        result.survivors.push_back(i);
        result.positions.push_back(collapser.positions()[i]);
        result.normals.push_back(collapser.normals()[i]);
        result.weights.push_back(collapser.weights()[i]);
    }
    return result;
}

} // namespace hrsr
