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

namespace {

// Where `row` (sorted, `length` entries) holds i, or -1: a branch-free binary search (most
// answers are "yes", at unpredictable depths, where branches cost more than the comparisons).
std::int64_t find_in_sorted_row(const std::uint32_t* row, std::size_t length, std::uint32_t i) {
    if (length == 0) return -1;
    const std::uint32_t* p = row;
    while (length > 1) {
        const std::size_t half = length / 2;
        p = p[half] <= i ? p + half : p;
        length -= half;
    }
    return *p == i ? p - row : -1;
}

// Moves row i (own[i] entries at start[i]) to offsets[i] inside `a`, which grows to offsets[n]
// within its capacity (no reallocation); start[i] becomes offsets[i]. Rows are packed to the
// left in increasing order, then moved right to their final places in decreasing order: every
// move reads what no earlier move has overwritten.
void spread_rows_in_place(std::vector<std::uint32_t>& a, std::vector<std::uint64_t>& start,
                          const std::vector<std::uint32_t>& own,
                          const std::vector<std::uint64_t>& offsets) {
    const std::size_t n = own.size();
    std::uint64_t packed = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (packed != start[i]) { // a move to the left: std::copy's precondition holds
            const auto first = a.begin() + std::ptrdiff_t(start[i]);
            std::copy(first, first + own[i], a.begin() + std::ptrdiff_t(packed));
        }
        start[i] = packed;
        packed += own[i];
    }
    a.resize(offsets[n]);
    for (std::size_t i = n; i-- > 0;) {
        const auto first = a.begin() + std::ptrdiff_t(start[i]);
        if (offsets[i] != start[i])
            std::copy_backward(first, first + own[i],
                               a.begin() + std::ptrdiff_t(offsets[i] + own[i]));
        start[i] = offsets[i];
    }
}

// Sorts a row. Rows of up to kRankSortedRow entries (kNN rows: k = 70 by default) by rank:
// each entry's place is the number of entries before it in the order, counted without a branch
// (std::sort's comparisons of unordered indices mispredicted: 2.7 times slower at k = 70).
void sort_row(std::uint32_t* row, std::size_t length) {
    constexpr std::size_t kRankSortedRow = 128;
    if (length > kRankSortedRow) {
        std::sort(row, row + length);
        return;
    }
    std::uint32_t copy[kRankSortedRow];
    std::copy(row, row + length, copy);
    for (std::size_t i = 0; i < length; ++i) {
        const std::uint32_t v = copy[i];
        std::uint32_t place = 0; // equal entries keep their order
        for (std::size_t j = 0; j < i; ++j) place += copy[j] <= v;
        for (std::size_t j = i + 1; j < length; ++j) place += copy[j] < v;
        row[place] = v;
    }
}

// Sorts row[0, sorted + added), whose first `sorted` entries are in order: the added ones are
// sorted on their own and merged in from the back (the row has no free room; the added part
// is copied out first). No two entries are equal.
void merge_added_part(std::uint32_t* row, std::uint32_t sorted, std::uint32_t added) {
    if (added == 0) return;
    std::uint32_t* tail = row + sorted;
    sort_row(tail, added);
    if (sorted == 0 || row[sorted - 1] < tail[0]) return;
    thread_local std::vector<std::uint32_t> spare;
    spare.assign(tail, tail + added);
    std::int64_t a = std::int64_t(sorted) - 1, b = std::int64_t(added) - 1;
    for (std::int64_t out = std::int64_t(sorted + added) - 1; b >= 0; --out)
        row[out] = a >= 0 && row[a] > spare[std::size_t(b)] ? row[a--] : spare[std::size_t(b--)];
}

} // namespace

// Peak memory matters here: with k = 70 on a few hundred thousand points (the orientation
// graph, RsR's candidate graph) the input is a hundred megabytes or more. Storing every relation
// at both ends and deduplicating afterwards needed three times the input. Instead each row is
// cleaned in place and only the relations missing at the other end (those that are not mutual:
// for kNN about a tenth) are added. When the input's buffer has room for them (knn_table()
// reserves it; untouched capacity costs address space, not memory) the union is built inside
// it; otherwise in a second array, twice the input at the peak. One bit per input entry tells
// mutual from one-sided relations.
CsrGraph symmetric_union(CsrGraph directed, const Execution& exec) {
    const std::size_t n = directed.size();
    std::vector<std::uint32_t>& a = directed.adjacency;
    std::vector<std::uint64_t>& start = directed.offsets; // row i: own[i] entries from start[i]
    std::vector<std::uint32_t> own(n, 0);
    parallel_for(exec, n, [&](std::size_t i) { // sorted, without repeats or self loops
        sort_row(a.data() + start[i], std::size_t(start[i + 1] - start[i])); // may be empty
        auto first = a.begin() + std::ptrdiff_t(start[i]);
        auto last = std::unique(first, a.begin() + std::ptrdiff_t(start[i + 1]));
        last = std::remove(first, last, std::uint32_t(i));
        own[i] = std::uint32_t(last - first);
    });
    const std::uint32_t* base = a.data();
    // One bit per input entry i -> j (by its place in the input rows). Each pair is searched
    // once, from its smaller end i < j. Found: the partner entry j -> i gets its bit ("mutual");
    // not found: i -> j gets its bit ("one-sided"). So an entry to a larger index is one-sided
    // when its bit is set, one to a smaller index when it is not. Bits are set with atomic ORs:
    // a "mutual" bit of row j is set by the thread working on row i, and the bits sharing its
    // byte may belong to other rows. They are only read after that pass.
    const std::vector<std::uint64_t> input_start(start.begin(), start.end());
    std::vector<std::atomic<std::uint8_t>> bits((input_start[n] + 7) / 8);
    auto set_bit = [&](std::uint64_t b) {
        bits[b / 8].fetch_or(std::uint8_t(1u << (b % 8)), std::memory_order_relaxed);
    };
    parallel_for(exec, n, [&](std::size_t i) {
        const std::uint32_t* row = base + start[i];
        for (std::uint32_t t = 0; t < own[i]; ++t) {
            const std::uint32_t j = row[t];
            if (j < i) continue;
            const std::int64_t at = find_in_sorted_row(base + start[j], own[j], std::uint32_t(i));
            set_bit(at < 0 ? input_start[i] + t : input_start[j] + std::uint64_t(at));
        }
    });
    auto one_sided = [&](std::size_t i, std::uint32_t t) {
        const std::uint64_t b = input_start[i] + t;
        const bool bit = (bits[b / 8].load(std::memory_order_relaxed) >> (b % 8)) & 1u;
        return base[start[i] + t] > i ? bit : !bit;
    };
    // One-sided i -> j: j's row gains i.
    std::vector<std::atomic<std::uint32_t>> missing(n);
    parallel_for(exec, n, [&](std::size_t i) {
        for (std::uint32_t t = 0; t < own[i]; ++t)
            if (one_sided(i, t))
                missing[base[start[i] + t]].fetch_add(1, std::memory_order_relaxed);
    });
    CsrGraph g;
    g.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) g.offsets[i + 1] = g.offsets[i] + own[i] + missing[i];
    const std::size_t total = g.offsets[n];
    if (total <= a.capacity()) {
        spread_rows_in_place(a, start, own, g.offsets);
        g.adjacency = std::move(a);
        base = g.adjacency.data(); // the same buffer, now the result's
    } else {
        g.adjacency.resize(total);
        parallel_for(exec, n, [&](std::size_t i) {
            std::copy_n(a.begin() + std::ptrdiff_t(start[i]), own[i],
                        g.adjacency.begin() + std::ptrdiff_t(g.offsets[i]));
        });
    }
    // The missing relations go after each row's own ones, in any order (they are sorted and
    // merged in last); the own parts are only read meanwhile.
    for (std::size_t i = 0; i < n; ++i) missing[i].store(0, std::memory_order_relaxed);
    parallel_for(exec, n, [&](std::size_t i) {
        for (std::uint32_t t = 0; t < own[i]; ++t) {
            if (!one_sided(i, t)) continue;
            const std::uint32_t j = base[start[i] + t];
            g.adjacency[g.offsets[j] + own[j] +
                        missing[j].fetch_add(1, std::memory_order_relaxed)] = std::uint32_t(i);
        }
    });
    directed = CsrGraph();
    // The own part of each row is sorted already: only the added part (about a tenth of a kNN
    // row) is sorted, then merged in (sorting whole rows again was a third of the union).
    parallel_for(exec, n, [&](std::size_t i) {
        std::uint32_t* row = g.adjacency.data() + g.offsets[i];
        merge_added_part(row, own[i], std::uint32_t(g.offsets[i + 1] - g.offsets[i]) - own[i]);
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
