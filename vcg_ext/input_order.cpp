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

// Vertices renumbered: first vertices of points by input index, then copies by input index.
void renumber_vertices(Reconstruction& mesh, std::size_t points) {
    const std::size_t n = mesh.vertex_input_index.size();
    std::vector<std::uint8_t> seen(points, 0);
    std::vector<std::pair<bool, std::uint32_t>> key(n); // (a copy, input index)
    for (std::size_t v = 0; v < n; ++v) {
        const std::uint32_t i = mesh.vertex_input_index[v];
        key[v] = {seen[i] != 0, i};
        seen[i] = 1;
    }
    std::vector<std::uint32_t> by_key(n);
    std::iota(by_key.begin(), by_key.end(), 0u);
    std::stable_sort(by_key.begin(), by_key.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::vector<std::uint32_t> new_index(n);
    Reconstruction out;
    out.vertex_input_index.reserve(n);
    out.vertex_normals.reserve(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        new_index[by_key[k]] = k;
        out.vertex_input_index.push_back(mesh.vertex_input_index[by_key[k]]);
        out.vertex_normals.push_back(mesh.vertex_normals[by_key[k]]);
    }
    out.triangles = std::move(mesh.triangles);
    for (Triangle& t : out.triangles)
        for (std::uint32_t& v : t) v = new_index[v];
    mesh = std::move(out);
}

} // namespace

void restore_input_order(const SpatialOrder& order, Reconstruction& mesh,
                         ReconstructionReport& report) {
    for (std::uint32_t& i : mesh.vertex_input_index) i = order.input_index[i];
    renumber_vertices(mesh, order.input_index.size());
    map_and_sort(order, report.not_in_triangle);
    map_and_sort(order, report.dropped_fold);
    map_and_sort(order, report.dropped_small_coarse_component);
    restore_point_fates(order, report.preprocess);
}

} // namespace hrsr
