#include "graph/neighbour_graph.h"

#include <algorithm>
#include <atomic>
#include <numeric>

namespace hrsr {

CsrGraph symmetric_union(KnnTable table, std::size_t n, const Execution& exec) {
    CsrGraph directed;
    directed.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        directed.offsets[i + 1] = directed.offsets[i] + std::size_t(table.k);
    directed.adjacency = std::move(table.index);
    return symmetric_union(std::move(directed), exec);
}

// Peak memory matters here: with k = 70 on a few hundred thousand points (the orientation
// graph, RsR's candidate graph) each array below is a hundred megabytes or more. Storing every
// relation at both ends and deduplicating afterwards needed three times the input; instead each
// row is cleaned in place, only the relations missing at the other end (those that are not
// mutual, typically well under half) are counted, and the result is written once: the input
// plus the result, about 2.4 times the input, is the peak.
CsrGraph symmetric_union(CsrGraph directed, const Execution& exec) {
    const std::size_t n = directed.size();
    std::vector<std::uint32_t>& a = directed.adjacency;
    // Each row sorted by index, without repeats or self loops, at the start of its slot.
    std::vector<std::uint32_t> own(n, 0);
    parallel_for(exec, n, [&](std::size_t i) {
        auto first = a.begin() + std::ptrdiff_t(directed.offsets[i]);
        auto last = a.begin() + std::ptrdiff_t(directed.offsets[i + 1]);
        std::sort(first, last);
        last = std::unique(first, last);
        last = std::remove(first, last, std::uint32_t(i));
        own[i] = std::uint32_t(last - first);
    });
    auto row = [&](std::size_t i) { return a.data() + directed.offsets[i]; };
    auto lists = [&](std::uint32_t j, std::uint32_t i) {
        return std::binary_search(row(j), row(j) + own[j], i);
    };
    // i lists j but j does not list i: j's row gains i. Counted, then placed, from the rows
    // that hold them; where they land within a row does not matter (rows are sorted last).
    std::vector<std::atomic<std::uint32_t>> missing(n);
    parallel_for(exec, n, [&](std::size_t i) {
        for (const std::uint32_t* j = row(i); j != row(i) + own[i]; ++j)
            if (!lists(*j, std::uint32_t(i))) missing[*j].fetch_add(1, std::memory_order_relaxed);
    });
    CsrGraph g;
    g.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) g.offsets[i + 1] = g.offsets[i] + own[i] + missing[i];
    g.adjacency.resize(g.offsets[n]);
    parallel_for(exec, n, [&](std::size_t i) {
        std::copy_n(row(i), own[i], g.adjacency.begin() + std::ptrdiff_t(g.offsets[i]));
        missing[i].store(own[i], std::memory_order_relaxed); // from now on: the fill cursor
    });
    parallel_for(exec, n, [&](std::size_t i) {
        for (const std::uint32_t* j = row(i); j != row(i) + own[i]; ++j)
            if (!lists(*j, std::uint32_t(i)))
                g.adjacency[g.offsets[*j] + missing[*j].fetch_add(1, std::memory_order_relaxed)] =
                    std::uint32_t(i);
    });
    directed = CsrGraph();
    parallel_for(exec, n, [&](std::size_t i) {
        std::sort(g.adjacency.begin() + std::ptrdiff_t(g.offsets[i]),
                  g.adjacency.begin() + std::ptrdiff_t(g.offsets[i + 1]));
    });
    return g;
}

DisjointSets::DisjointSets(std::size_t n) {
    reset(n);
}

void DisjointSets::reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), 0u);
    size_.assign(n, 1);
}

std::uint32_t DisjointSets::find(std::uint32_t x) {
    while (parent_[x] != x) {
        parent_[x] = parent_[parent_[x]];
        x = parent_[x];
    }
    return x;
}

bool DisjointSets::unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
    return true;
}

} // namespace hrsr
