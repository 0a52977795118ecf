#include "graph/neighbour_graph.h"

#include <algorithm>
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
// graph, RsR's candidate graph) each array below is a hundred megabytes or more. The input is
// freed once both directions are gathered, the rows are deduplicated in place, and the result
// keeps that buffer (trimmed only when a large part of it went to repeats).
CsrGraph symmetric_union(CsrGraph directed, const Execution& exec) {
    const std::size_t n = directed.size();
    // Every relation i -> j is stored at both ends; repeats (mutual neighbours) and self loops
    // are removed per row afterwards, so the fill order does not matter.
    std::vector<std::uint64_t> fill(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        fill[i + 1] += directed.degree(i);
        for (const std::uint32_t* j = directed.begin(i); j != directed.end(i); ++j) ++fill[*j + 1];
    }
    std::partial_sum(fill.begin(), fill.end(), fill.begin());
    std::vector<std::uint32_t> raw(fill[n]);
    {
        std::vector<std::uint64_t> cursor(fill.begin(), fill.end() - 1);
        for (std::size_t i = 0; i < n; ++i) {
            for (const std::uint32_t* j = directed.begin(i); j != directed.end(i); ++j) {
                raw[cursor[i]++] = *j;
                raw[cursor[*j]++] = std::uint32_t(i);
            }
        }
    }
    directed = CsrGraph();
    std::vector<std::uint64_t> unique_count(n, 0);
    parallel_for(exec, n, [&](std::size_t i) {
        auto first = raw.begin() + std::ptrdiff_t(fill[i]);
        auto last = raw.begin() + std::ptrdiff_t(fill[i + 1]);
        std::sort(first, last);
        last = std::unique(first, last);
        last = std::remove(first, last, std::uint32_t(i));
        unique_count[i] = std::uint64_t(last - first);
    });
    CsrGraph g;
    g.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) g.offsets[i + 1] = g.offsets[i] + unique_count[i];
    // Row i moves left to g.offsets[i] <= fill[i]; in increasing i nothing unread is overwritten.
    for (std::size_t i = 0; i < n; ++i)
        if (g.offsets[i] != fill[i])
            std::copy_n(raw.begin() + std::ptrdiff_t(fill[i]), unique_count[i],
                        raw.begin() + std::ptrdiff_t(g.offsets[i]));
    raw.resize(g.offsets[n]);
    if (raw.capacity() - raw.size() > raw.size() / 8) raw.shrink_to_fit();
    g.adjacency = std::move(raw);
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
