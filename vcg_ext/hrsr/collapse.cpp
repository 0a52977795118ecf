#include "hrsr/collapse.h"

#include "geometry.h"
#include "graph/neighbour_graph.h"
#include "knn.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace hrsr {

namespace {

// An edge key, totally ordered by (priority, lo, hi) (D-10).
struct EdgeKey {
    double priority;
    std::uint32_t lo, hi;
    bool operator<(const EdgeKey& o) const {
        return std::tie(priority, lo, hi) < std::tie(o.priority, o.lo, o.hi);
    }
    bool touches(std::uint32_t i) const { return lo == i || hi == i; }
};

// The collapse graph with, per node, its smallest admissible edge, and an indexed min-heap of
// the nodes ordered by that edge. The globally smallest admissible edge is the best edge of both
// its endpoints, so the heap's top gives it. One heap entry per node instead of one per edge
// (with stale copies) keeps the queue at a fifth of the bytes and the heap shallow; the order of
// the merges is exactly that of a queue of all edges (see merge()).
class Collapser {
public:
    Collapser(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals)
        : x_(positions), n_(normals), w_(positions.size(), 1), alive_(positions.size(), 1),
          neighbours_(positions.size()), best_(positions.size()), has_best_(positions.size(), 0),
          slot_(positions.size(), kNotQueued) {}

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
        parallel_for(exec, neighbours_.size(), [&](std::size_t i) { find_best(std::uint32_t(i)); });
        heap_.reserve(neighbours_.size());
        for (std::uint32_t i = 0; i < neighbours_.size(); ++i)
            if (has_best_[i]) heap_.push_back(i);
        std::make_heap(heap_.begin(), heap_.end(),
                       [&](std::uint32_t a, std::uint32_t b) { return before(b, a); });
        for (std::uint32_t s = 0; s < heap_.size(); ++s) slot_[heap_[s]] = s;
    }

    // Performs the next collapse; false when no admissible edge is left.
    bool collapse_next(std::vector<CollapseRecord>& records) {
        if (heap_.empty()) return false;
        const EdgeKey e = best_[heap_[0]];
        merge(e.lo, e.hi, records);
        return true;
    }

    const std::vector<Vec3>& positions() const { return x_; }
    const std::vector<Vec3>& normals() const { return n_; }
    const std::vector<std::uint32_t>& weights() const { return w_; }
    bool alive(std::uint32_t i) const { return alive_[i]; }

private:
    static constexpr std::uint32_t kNotQueued = ~std::uint32_t(0);

    // §6.1: tangent distance times the merged weight, in both distance modes. D-15: an edge
    // whose normals have turned more than 90° apart is not admissible (until one end changes).
    bool admissible_key(std::uint32_t a, std::uint32_t b, EdgeKey& key) const {
        const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
        if (n_[lo].dot(n_[hi]) < 0) return false;
        key = {tangent_distance(x_[hi] - x_[lo], n_[lo], n_[hi]) * double(w_[lo] + w_[hi]), lo, hi};
        return true;
    }

    void find_best(std::uint32_t i) {
        has_best_[i] = 0;
        EdgeKey key;
        for (std::uint32_t j : neighbours_[i])
            if (admissible_key(i, j, key) && (!has_best_[i] || key < best_[i])) {
                best_[i] = key;
                has_best_[i] = 1;
            }
    }

    bool before(std::uint32_t a, std::uint32_t b) const { return best_[a] < best_[b]; }

    void place(std::uint32_t s, std::uint32_t node) {
        heap_[s] = node;
        slot_[node] = s;
    }
    void sift_up(std::uint32_t s) {
        const std::uint32_t node = heap_[s];
        while (s > 0) {
            const std::uint32_t parent = (s - 1) / 2;
            if (!before(node, heap_[parent])) break;
            place(s, heap_[parent]);
            s = parent;
        }
        place(s, node);
    }
    void sift_down(std::uint32_t s) {
        const std::uint32_t node = heap_[s], size = std::uint32_t(heap_.size());
        for (;;) {
            std::uint32_t child = 2 * s + 1;
            if (child >= size) break;
            if (child + 1 < size && before(heap_[child + 1], heap_[child])) ++child;
            if (!before(heap_[child], node)) break;
            place(s, heap_[child]);
            s = child;
        }
        place(s, node);
    }
    void dequeue(std::uint32_t node) {
        const std::uint32_t s = slot_[node];
        if (s == kNotQueued) return;
        slot_[node] = kNotQueued;
        const std::uint32_t last = heap_.back();
        heap_.pop_back();
        if (last == node) return;
        place(s, last);
        sift_up(s);
        sift_down(slot_[last]);
    }
    // Puts the node where its (new) best edge belongs, or takes it out without one.
    void requeue(std::uint32_t node) {
        if (!has_best_[node]) return dequeue(node);
        if (slot_[node] == kNotQueued) {
            heap_.push_back(node);
            slot_[node] = std::uint32_t(heap_.size() - 1);
        }
        sift_up(slot_[node]);
        sift_down(slot_[node]);
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
        // b's neighbours become a's (no repeats, no self loops).
        for (std::uint32_t c : neighbours_[b]) {
            auto& list = neighbours_[c];
            list.erase(std::remove(list.begin(), list.end(), b), list.end());
            if (c == a) continue;
            if (std::find(neighbours_[a].begin(), neighbours_[a].end(), c) ==
                neighbours_[a].end()) {
                neighbours_[a].push_back(c);
                list.push_back(a);
            }
        }
        std::vector<std::uint32_t>().swap(neighbours_[b]);
        has_best_[b] = 0;
        dequeue(b);
        find_best(a);
        requeue(a);
        // Only edges at a changed (a moved, b's edges became a's): a neighbour whose best edge
        // touched a or b looks again at all its edges, any other one only at its edge to a.
        for (std::uint32_t c : neighbours_[a]) {
            EdgeKey key;
            if (has_best_[c] && (best_[c].touches(a) || best_[c].touches(b))) {
                find_best(c);
            } else if (admissible_key(c, a, key) && (!has_best_[c] || key < best_[c])) {
                best_[c] = key;
                has_best_[c] = 1;
            } else {
                continue;
            }
            requeue(c);
        }
    }

    std::vector<Vec3> x_, n_;
    std::vector<std::uint32_t> w_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::vector<std::uint32_t>> neighbours_;
    std::vector<EdgeKey> best_; ///< per node: its smallest admissible edge, if has_best_
    std::vector<std::uint8_t> has_best_;
    std::vector<std::uint32_t> heap_; ///< nodes with an admissible edge, min-heap on best_
    std::vector<std::uint32_t> slot_; ///< per node: its index in heap_, or kNotQueued
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
