#include "hrsr/range_collapser.h"

#include <utility>

namespace hrsr::collapsing {

RangeCollapser::RangeCollapser(CollapseGraph& g, std::uint32_t begin, std::uint32_t end,
                               const Execution* exec)
    : g_(g), begin_(begin), end_(end), queue_(end - begin), on_border_(end - begin, 0) {
    std::vector<EdgeKey> best(end - begin);
    std::vector<std::uint8_t> has_best(end - begin, 0);
    auto find = [&](std::size_t i) {
        has_best[i] = g_.alive[begin + i] && best_edge(std::uint32_t(begin + i), best[i]);
    };
    if (exec)
        parallel_for(*exec, best.size(), find);
    else
        for (std::size_t i = 0; i < best.size(); ++i) find(i);
    queue_.assign(std::move(best), has_best);
    if (begin == 0 && end == g.x.size()) return; // the whole graph: nothing outside
    for (std::uint32_t i = begin; i < end; ++i)
        for (std::uint32_t j : g_.neighbours[i])
            if (!contains(j)) {
                mark_border(i);
                break;
            }
}

void RangeCollapser::add_costs(std::vector<float>& costs) const {
    for (std::uint32_t s = 0; s < end_ - begin_; ++s)
        if (queue_.contains(s)) costs.push_back(float(queue_.key(s).cost));
}

bool RangeCollapser::next_cost(double& cost) const {
    if (queue_.empty()) return false;
    cost = queue_.key(queue_.top()).cost;
    return true;
}

bool RangeCollapser::collapse_next(std::vector<CollapseRecord>& records) {
    if (queue_.empty()) return false;
    const EdgeKey e = queue_.key(queue_.top());
    const std::uint32_t a = e.lo, b = e.hi;
    g_.merge(a, b, records);
    g_.move_edges(
        a, b, [&](std::uint32_t c) { return contains(c); },
        [&](std::uint32_t c) {
            relinks.push_back({c, b, a});
        });
    erase(b);
    refresh(a);
    // Only edges at a changed (a moved, b's edges became a's): a neighbour whose best edge
    // touched a or b looks again at all its edges, any other one only at its edge to a.
    for (std::uint32_t c : g_.neighbours[a]) {
        if (!contains(c)) continue;
        const std::uint32_t s = c - begin_;
        if (queue_.contains(s) && (queue_.key(s).touches(a) || queue_.key(s).touches(b))) {
            refresh(c);
            continue;
        }
        const EdgeKey key = g_.edge_key(c, a);
        if (!queue_.contains(s) || key < queue_.key(s)) queue_.set(s, key);
    }
    return true;
}

void RangeCollapser::refresh(std::uint32_t i) {
    EdgeKey best;
    if (best_edge(i, best))
        queue_.set(i - begin_, best);
    else
        queue_.erase(i - begin_);
}

// The node's smallest edge inside; false if it has none.
bool RangeCollapser::best_edge(std::uint32_t i, EdgeKey& best) const {
    bool found = false;
    for (std::uint32_t j : g_.neighbours[i]) {
        if (!contains(j)) continue;
        const EdgeKey key = g_.edge_key(i, j);
        if (!found || key < best) {
            best = key;
            found = true;
        }
    }
    return found;
}

} // namespace hrsr::collapsing
