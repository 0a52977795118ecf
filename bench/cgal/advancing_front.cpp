// CGAL's Advancing Front surface reconstruction (Cohen-Steiner & Da, default parameters) on a
// point cloud, for bench/compare.sh:  cgal_advancing_front CLOUD OUT.ply
// Reads what hrsr reads (.ply/.xyz/.obj); writes a binary PLY whose vertices are the input points.
// Exit codes: 0 success, 1 bad input or output, 2 usage.
#include "io/ply_writer.h"
#include "io/point_set_reader.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdio>
#include <iterator>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: cgal_advancing_front CLOUD OUT.ply\n");
        return 2;
    }
    try {
        using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
        const hrsr::PointSet cloud = hrsr::io::read_point_set(argv[1]);
        std::vector<Kernel::Point_3> points;
        points.reserve(cloud.size());
        for (const hrsr::Vec3& p : cloud.positions) points.emplace_back(p[0], p[1], p[2]);
        std::vector<std::array<std::size_t, 3>> facets;
        CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                                     std::back_inserter(facets));
        std::vector<hrsr::io::Triangle> triangles;
        triangles.reserve(facets.size());
        for (const auto& f : facets)
            triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
        hrsr::io::write_ply(argv[2], cloud.positions, {}, triangles, cloud.precision);
        std::printf("cgal_advancing_front: %zu points, %zu triangles\n", points.size(),
                    triangles.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cgal_advancing_front: %s\n", e.what());
        return 1;
    }
    return 0;
}
