#include "hrsr/collapse.h"

#include "geometry.h"
#include "graph/neighbour_graph.h"
#include "graph/vertex_heap.h"
#include "knn.h"

#include <algorithm>
#include <cmath>

namespace hrsr {

namespace {

// The collapse graph with, per node, its smallest admissible edge, and a heap of the nodes
// ordered by that edge (graph/vertex_heap.h; an edge's cost is its §6.1 priority). The globally
// smallest admissible edge is the best edge of both its endpoints, so the heap's top gives it.
// One heap entry per node instead of one per edge (with stale copies) keeps the queue at a fifth
// of the bytes and the heap shallow; the order of the merges is exactly that of a queue of all
// edges (see merge()).
class Collapser {
public:
    Collapser(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals)
        : x_(positions), n_(normals), w_(positions.size(), 1), alive_(positions.size(), 1),
          neighbours_(positions.size()), queue_(positions.size()) {}

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
        const std::size_t n = neighbours_.size();
        std::vector<EdgeKey> best(n);
        std::vector<std::uint8_t> has_best(n, 0);
        parallel_for(exec, n,
                     [&](std::size_t i) { has_best[i] = best_edge(std::uint32_t(i), best[i]); });
        queue_.assign(std::move(best), has_best);
    }

    // Performs the next collapse; false when no admissible edge is left.
    bool collapse_next(std::vector<CollapseRecord>& records) {
        if (queue_.empty()) return false;
        const EdgeKey e = queue_.key(queue_.top());
        merge(e.lo, e.hi, records);
        return true;
    }

    const std::vector<Vec3>& positions() const { return x_; }
    const std::vector<Vec3>& normals() const { return n_; }
    const std::vector<std::uint32_t>& weights() const { return w_; }
    bool alive(std::uint32_t i) const { return alive_[i]; }

private:
    // §6.1: tangent distance times the merged weight, in both distance modes. The > 90° rule
    // holds for the graph as built (D-14); an edge inherited through a merge is not checked
    // again (D-15, withdrawn: checking it made the bunny, the lion and the dragon sample worse).
    EdgeKey edge_key(std::uint32_t a, std::uint32_t b) const {
        const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
        return {tangent_distance(x_[hi] - x_[lo], n_[lo], n_[hi]) * double(w_[lo] + w_[hi]), lo,
                hi};
    }

    // The node's smallest edge; false if it has none.
    bool best_edge(std::uint32_t i, EdgeKey& best) const {
        bool found = false;
        for (std::uint32_t j : neighbours_[i]) {
            const EdgeKey key = edge_key(i, j);
            if (!found || key < best) {
                best = key;
                found = true;
            }
        }
        return found;
    }

    // Queues the node with its smallest edge, or takes it out without one.
    void refresh(std::uint32_t i) {
        EdgeKey best;
        if (best_edge(i, best))
            queue_.set(i, best);
        else
            queue_.erase(i);
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
        queue_.erase(b);
        refresh(a);
        // Only edges at a changed (a moved, b's edges became a's): a neighbour whose best edge
        // touched a or b looks again at all its edges, any other one only at its edge to a.
        for (std::uint32_t c : neighbours_[a]) {
            if (queue_.contains(c) && (queue_.key(c).touches(a) || queue_.key(c).touches(b))) {
                refresh(c);
                continue;
            }
            const EdgeKey key = edge_key(c, a);
            if (!queue_.contains(c) || key < queue_.key(c)) queue_.set(c, key);
        }
    }

    std::vector<Vec3> x_, n_;
    std::vector<std::uint32_t> w_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::vector<std::uint32_t>> neighbours_;
    VertexHeap queue_; ///< nodes with an admissible edge, by their smallest one
};

} // namespace

CollapsedCloud collapse(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                        const CollapseOptions& options, const Execution& exec) {
    validate(options);
    const std::size_t n = positions.size();
    CollapsedCloud result;
    result.budget = n - std::min(n, std::size_t(std::llround(double(n) * options.collapse_ratio)));

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
        result.survivors.push_back(PointIndex(i));
        result.positions.push_back(collapser.positions()[i]);
        result.normals.push_back(collapser.normals()[i]);
        result.weights.push_back(collapser.weights()[i]);
    }
    return result;
}

} // namespace hrsr
