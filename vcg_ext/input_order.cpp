#include "input_order.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace hrsr {

namespace {

void map_and_sort(const SpatialOrder& order, std::vector<std::uint32_t>& indices) {
    for (std::uint32_t& i : indices) i = order.input_index[i];
    std::sort(indices.begin(), indices.end());
}

// Per-point lists of the preprocessing report, indexed and valued in the input's numbers.
void restore_point_fates(const SpatialOrder& order, PreprocessReport& report) {
    const std::vector<std::uint32_t>& input = order.input_index;
    if (report.fate.size() == input.size()) {
        std::vector<PointFate> fate(input.size());
        for (std::size_t i = 0; i < input.size(); ++i) fate[input[i]] = report.fate[i];
        report.fate = std::move(fate);
    }
    if (report.duplicate_of.size() == input.size()) {
        std::vector<std::uint32_t> duplicate_of(input.size());
        for (std::size_t i = 0; i < input.size(); ++i)
            duplicate_of[input[i]] = input[report.duplicate_of[i]];
        report.duplicate_of = std::move(duplicate_of);
    }
}

// Vertices renumbered: first vertices of points by input index, then copies by input index
// (each point's in vertex order). A point's first vertex is numbered by the points before it
// that have one (a bit per point, counted by words), not by sorting every vertex: linear, and
// the mapping by blocks in parallel.
void renumber_vertices(Reconstruction& mesh, std::size_t points, const Execution& exec) {
    const std::size_t n = mesh.vertex_input_index.size();
    std::vector<std::uint64_t> has_vertex((points + 63) / 64, 0);
    std::vector<std::uint32_t> copies; // few: one per extra fan of a non-manifold point
    for (std::uint32_t v = 0; v < n; ++v) {
        const std::uint32_t i = mesh.vertex_input_index[v];
        const std::uint64_t bit = std::uint64_t(1) << (i % 64);
        if (has_vertex[i / 64] & bit)
            copies.push_back(v);
        else
            has_vertex[i / 64] |= bit;
    }
    std::vector<std::uint32_t> before_word(has_vertex.size() + 1, 0);
    for (std::size_t w = 0; w < has_vertex.size(); ++w)
        before_word[w + 1] = before_word[w] + std::uint32_t(__builtin_popcountll(has_vertex[w]));
    const std::uint32_t firsts = before_word.back();
    std::stable_sort(copies.begin(), copies.end(), [&](std::uint32_t a, std::uint32_t b) {
        return mesh.vertex_input_index[a] < mesh.vertex_input_index[b];
    });
    std::vector<std::uint32_t> new_index(n);
    parallel_for_blocks(exec, n, kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t v = first; v < end; ++v) {
            const std::uint32_t i = mesh.vertex_input_index[v];
            const std::uint64_t lower = (std::uint64_t(1) << (i % 64)) - 1;
            new_index[v] = before_word[i / 64] +
                           std::uint32_t(__builtin_popcountll(has_vertex[i / 64] & lower));
        }
    });
    for (std::uint32_t k = 0; k < copies.size(); ++k) new_index[copies[k]] = firsts + k;
    Reconstruction out;
    out.vertex_input_index.resize(n);
    out.vertex_normals.resize(n);
    parallel_for_blocks(exec, n, kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t v = first; v < end; ++v) {
            out.vertex_input_index[new_index[v]] = mesh.vertex_input_index[v];
            out.vertex_normals[new_index[v]] = mesh.vertex_normals[v];
        }
    });
    out.triangles = std::move(mesh.triangles);
    parallel_for_blocks(exec, out.triangles.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t t = first; t < end; ++t)
                                for (std::uint32_t& v : out.triangles[t]) v = new_index[v];
                        });
    mesh = std::move(out);
}

} // namespace

void restore_input_order(const SpatialOrder& order, Reconstruction& mesh,
                         ReconstructionReport& report, const Execution& exec) {
    for (std::uint32_t& i : mesh.vertex_input_index) i = order.input_index[i];
    renumber_vertices(mesh, order.input_index.size(), exec);
    map_and_sort(order, report.not_in_triangle);
    map_and_sort(order, report.dropped_fold);
    map_and_sort(order, report.dropped_small_coarse_component);
    restore_point_fates(order, report.preprocess);
}

} // namespace hrsr
