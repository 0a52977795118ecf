#include "rsr/candidate_graph.h"

#include "geometry.h"
#include "preprocess/components.h"

#include <algorithm>
#include <cmath>
#include <parallel/algorithm>
#include <stdexcept>

namespace hrsr::rsr {

int candidate_rank(int k, std::size_t points) {
    k = int(std::min<std::size_t>(std::size_t(k), points > 0 ? points - 1 : 0));
    // GEL's rank ⌊2k/3⌋ counted from the point itself = the ⌊2k/3⌋-th true neighbour (clamped,
    // D-8).
    return std::clamp(k * constants::kPreMaxRankNumerator / constants::kPreMaxRankDenominator, 1,
                      std::max(k, 1));
}

namespace {

// Local point i's k nearest in the component from the cloud's known row, when that row
// has exactly k entries, all in this component: the component's own query would give the same
// points (a subset holding a point's k nearest in the whole cloud holds its k nearest), in the
// same order (the local indices keep the cloud's order) and at the same distances (computed as
// the query computes them). False = ask the index.
bool known_row(const ComponentCloud& cloud, std::uint32_t i, int k, std::vector<Neighbour>& out) {
    const ComponentCloud::KnownNeighbours& known = cloud.known_neighbours;
    if (known.table == nullptr || known.table->k != k) return false;
    const std::uint32_t* row = known.table->row(known.cloud_index[i]);
    for (int j = 0; j < k; ++j)
        if (row[j] == kNoNeighbour || known.component_of[row[j]] != known.component) return false;
    out.resize(std::size_t(k));
    for (int j = 0; j < k; ++j) {
        const std::uint32_t local = known.local_index[row[j]];
        out[std::size_t(j)] = {local, (cloud.smoothed[i] - cloud.smoothed[local]).SquaredNorm()};
    }
    return true;
}

} // namespace

CandidateGraph build_candidate_graph(const ComponentCloud& cloud, const KnnIndex& index,
                                     const PreprocessOptions& options, const Execution& exec) {
    const std::size_t n = cloud.smoothed.size();
    const int k = int(std::min<std::size_t>(std::size_t(options.k), n > 0 ? n - 1 : 0));
    const int rank = candidate_rank(options.k, n);
    const double min_cos = normal_filter_cosine(options);

    CandidateGraph g;
    g.pre_max_length.assign(n, 0.0);
    std::vector<std::vector<std::uint32_t>> kept(n);
    parallel_for(exec, n, [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        if (!known_row(cloud, std::uint32_t(i), k, found))
            index.neighbours_of(std::uint32_t(i), k, found);
        if (!found.empty())
            g.pre_max_length[i] = std::sqrt(
                found[std::size_t(std::min<int>(rank, int(found.size()))) - 1].squared_distance);
        for (const Neighbour& nb : found)
            if (cloud.normals[i].dot(cloud.normals[nb.index]) >= min_cos)
                kept[i].push_back(nb.index);
    });
    CsrGraph directed;
    directed.offsets.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        directed.offsets[i + 1] = directed.offsets[i] + kept[i].size();
    reserve_room_for_union(directed.adjacency, directed.offsets[n]);
    for (auto& row : kept) {
        directed.adjacency.insert(directed.adjacency.end(), row.begin(), row.end());
        std::vector<std::uint32_t>().swap(row);
    }
    g.graph = symmetric_union(std::move(directed), exec);

    g.max_length.assign(n, 0.0);
    parallel_for(exec, n, [&](std::size_t i) {
        for (const std::uint32_t* j = g.graph.begin(i); j != g.graph.end(i); ++j)
            g.max_length[i] =
                std::max(g.max_length[i],
                         edge_length(options.distance, cloud.smoothed[i], cloud.smoothed[*j],
                                     cloud.normals[i], cloud.normals[*j]));
    });
    return g;
}

namespace {

// The length of {i, j} if both ends accept it (len ≤ pre_max_length at both), else a negative
// value. One out-of-line function for both passes of face_split_candidates(): the same machine
// code, so the count and the fill cannot disagree (e.g. by contracting to FMA differently).
[[gnu::noinline]] double kept_length(const CandidateGraph& g, const ComponentCloud& cloud,
                                     DistanceMode mode, std::uint32_t i, std::uint32_t j) {
    const double len =
        edge_length(mode, cloud.smoothed[i], cloud.smoothed[j], cloud.normals[i], cloud.normals[j]);
    return len <= g.pre_max_length[i] && len <= g.pre_max_length[j] ? len : -1.0;
}

} // namespace

std::vector<CandidateEdge> face_split_candidates(const CandidateGraph& g,
                                                 const ComponentCloud& cloud, DistanceMode mode,
                                                 const Execution& exec) {
    const std::size_t n = g.graph.size();
    // Two passes (count, then fill at each row's offset) so that the list is allocated once, at
    // its exact size: per-row vectors appended to a growing one held up to four times its bytes,
    // the peak of RsR on large clouds. The lengths are computed twice; that is cheaper.
    std::vector<std::uint64_t> offsets(n + 1, 0);
    parallel_for(exec, n, [&](std::size_t i) {
        for (const std::uint32_t* j = g.graph.begin(i); j != g.graph.end(i); ++j)
            if (*j > i && kept_length(g, cloud, mode, std::uint32_t(i), *j) >= 0) ++offsets[i + 1];
    });
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    std::vector<CandidateEdge> all(offsets[n]);
    parallel_for(exec, n, [&](std::size_t i) {
        std::uint64_t at = offsets[i];
        for (const std::uint32_t* j = g.graph.begin(i); j != g.graph.end(i); ++j) {
            if (*j <= i) continue;
            const double len = kept_length(g, cloud, mode, std::uint32_t(i), *j);
            if (len < 0) continue;
            if (at == offsets[i + 1])
                throw std::logic_error("face_split_candidates: count changed");
            all[at++] = {len, std::uint32_t(i), *j};
        }
        if (at != offsets[i + 1]) throw std::logic_error("face_split_candidates: count changed");
    });
    // (length, i, j) orders every pair of candidates, so any sort gives this one list: the
    // parallel quicksort (in place: no second copy of the list at RsR's peak) for any thread count.
    const auto before = [](const CandidateEdge& a, const CandidateEdge& b) {
        if (a.length != b.length) return a.length < b.length;
        return a.i != b.i ? a.i < b.i : a.j < b.j;
    };
    __gnu_parallel::sort(all.begin(), all.end(), before,
                         __gnu_parallel::balanced_quicksort_tag(thread_count(exec)));
    return all;
}

} // namespace hrsr::rsr
