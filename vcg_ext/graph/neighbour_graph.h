// Undirected graphs over point indices (compressed sparse rows) and union-find.
#pragma once

#include "knn.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// Undirected graph: the neighbours of i are adjacency[offsets[i] .. offsets[i + 1]), sorted
/// by index, without self loops or repeats; j is a neighbour of i exactly when i is one of j.
struct CsrGraph {
    std::vector<std::uint64_t> offsets{0};
    std::vector<std::uint32_t> adjacency;

    std::size_t size() const { return offsets.size() - 1; }
    const std::uint32_t* begin(std::size_t i) const { return adjacency.data() + offsets[i]; }
    const std::uint32_t* end(std::size_t i) const { return adjacency.data() + offsets[i + 1]; }
    std::size_t degree(std::size_t i) const { return std::size_t(offsets[i + 1] - offsets[i]); }
};

/// The symmetric union of a kNN relation: {i, j} is an edge when j is among i's neighbours or
/// i among j's (D-7). `n` is the number of points (the table may be empty for n < 2). Taken by
/// value: pass the table with std::move and its storage becomes the union's input, not a copy.
CsrGraph symmetric_union(KnnTable table, std::size_t n, const Execution& exec);

/// The same for any directed relation given as rows (row i: the targets of i, any order, self
/// loops and repeats ignored). By value as well: its buffer becomes the result's when it has
/// room for the added relations (reserve twice its size), else it is freed once copied.
CsrGraph symmetric_union(CsrGraph directed, const Execution& exec);

/// Union-find with path halving and union by size.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n);
    /// n singletons again, keeping the storage (for scratch sets reused in a loop).
    void reset(std::size_t n);
    std::uint32_t find(std::uint32_t x);
    /// Returns false when a and b were already in the same set.
    bool unite(std::uint32_t a, std::uint32_t b);

private:
    std::vector<std::uint32_t> parent_;
    std::vector<std::uint32_t> size_;
};

} // namespace hrsr
