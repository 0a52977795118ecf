// Where a reconstruction's folds are before any repair (issue 16 item 1): the intersecting
// triangle pairs (exact test, input coordinates) of a default run with fold_repair_rounds = 0,
// by how many rings of the mesh apart their faces are (0: they share a vertex), and how many of
// the distant ones lie at a thin part (an input point facing the other way within three median
// edge lengths of the first face). Not part of the hrsr CLI.
//   fold_sources CLOUD [hrsr|rsr]
// Exit codes: 0 success, 1 bad input, 2 usage.
#include "io/point_set_reader.h"
#include "knn.h"
#include "mesh/self_intersections.h"
#include "reconstruction.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using hrsr::Triangle;
using hrsr::Vec3;

constexpr int kFar = 7; ///< rings searched before a pair counts as distant

// Rings between the vertex sets of two faces (kFar when further), over `adjacent`.
int rings_apart(const Triangle& a, const Triangle& b,
                const std::vector<std::vector<std::uint32_t>>& adjacent, std::vector<int>& stamp,
                int query) {
    std::vector<std::uint32_t> frontier(a.begin(), a.end());
    for (std::uint32_t v : frontier) stamp[v] = query;
    for (int ring = 0; ring < kFar; ++ring) {
        for (std::uint32_t v : frontier)
            if (std::find(b.begin(), b.end(), v) != b.end()) return ring;
        std::vector<std::uint32_t> next;
        for (std::uint32_t v : frontier)
            for (std::uint32_t w : adjacent[v])
                if (stamp[w] != query) {
                    stamp[w] = query;
                    next.push_back(w);
                }
        frontier.swap(next);
    }
    return kFar;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3 ||
        (argc == 3 && std::string(argv[2]) != "hrsr" && std::string(argv[2]) != "rsr")) {
        std::fprintf(stderr, "usage: fold_sources CLOUD [hrsr|rsr]\n");
        return 2;
    }
    try {
        const hrsr::PointSet cloud = hrsr::io::read_point_set(argv[1]);
        hrsr::ReconstructionOptions options;
        if (argc == 3 && std::string(argv[2]) == "rsr") options.method = hrsr::Method::Rsr;
        options.rsr.fold_repair_rounds = 0;
        hrsr::ReconstructionReport report;
        const hrsr::Reconstruction r = hrsr::reconstruct(cloud, options, {}, report);
        std::vector<Vec3> positions;
        for (std::uint32_t i : r.vertex_input_index) positions.push_back(cloud.positions[i]);
        const std::vector<hrsr::TrianglePair> pairs =
            hrsr::self_intersecting_pairs(positions, r.triangles, {});
        std::vector<std::vector<std::uint32_t>> adjacent(positions.size());
        std::vector<double> lengths;
        for (const Triangle& t : r.triangles)
            for (int k = 0; k < 3; ++k) {
                adjacent[t[k]].push_back(t[(k + 1) % 3]);
                adjacent[t[(k + 1) % 3]].push_back(t[k]);
                lengths.push_back((positions[t[k]] - positions[t[(k + 1) % 3]]).Norm());
            }
        std::nth_element(lengths.begin(), lengths.begin() + long(lengths.size() / 2),
                         lengths.end());
        const double median = lengths.empty() ? 0 : lengths[lengths.size() / 2];
        const hrsr::KnnIndex index(cloud.positions);
        std::vector<int> stamp(positions.size(), -1), by_rings(kFar + 1, 0);
        std::vector<std::uint32_t> near;
        int thin = 0;
        for (std::size_t p = 0; p < pairs.size(); ++p) {
            const Triangle& a = r.triangles[pairs[p].first];
            const int rings = rings_apart(a, r.triangles[pairs[p].second], adjacent, stamp, int(p));
            ++by_rings[std::size_t(rings)];
            if (rings < kFar || cloud.normals.empty()) continue;
            const Vec3 centre = (positions[a[0]] + positions[a[1]] + positions[a[2]]) / 3.0;
            const Vec3 facing =
                r.vertex_normals[a[0]] + r.vertex_normals[a[1]] + r.vertex_normals[a[2]];
            index.within(centre, 3 * median, near);
            thin += std::any_of(near.begin(), near.end(),
                                [&](std::uint32_t i) { return cloud.normals[i].dot(facing) < 0; });
        }
        std::printf("intersecting pairs before any repair: %zu\n", pairs.size());
        for (int k = 0; k <= kFar; ++k)
            std::printf("  %s %d ring%s apart: %d\n", k == kFar ? "at least" : "", k,
                        k == 1 ? "" : "s", by_rings[std::size_t(k)]);
        std::printf("  of those at least %d apart, at a thin part: %d\n", kFar, thin);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fold_sources: %s\n", e.what());
        return 1;
    }
    return 0;
}
