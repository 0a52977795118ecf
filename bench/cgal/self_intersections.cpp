// Self-intersecting triangle pairs of a mesh by hrsr's exact test and by CGAL's
// Polygon_mesh_processing::self_intersections, with the time of each full search, for
// bench/self_intersections_agreement.sh:  cgal_self_intersections MESH.ply
// Prints one line: triangles, ours (copies at one position welded, as `hrsr check`), ours by
// index, CGAL's, whether ours by index equal CGAL's pairs, and the seconds of each search.
// Exit codes: 0 agreement, 1 disagreement or bad input, 2 usage.
#include "mesh/self_intersections.h"
#include "io/mesh_reader.h"

#include "cgal_self_intersections.h"

#include <chrono>
#include <cstdio>
#include <exception>

namespace {

template <class Work>
double seconds(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: cgal_self_intersections MESH.ply\n");
        return 2;
    }
    try {
        const hrsr::io::MeshFile mesh = hrsr::io::read_mesh(argv[1]);
        const std::vector<hrsr::Vec3>& p = mesh.points.positions;
        std::vector<hrsr::TrianglePair> ours, by_index;
        std::optional<hrsr::testing::CgalIntersections> cgal;
        const double t_ours =
            seconds([&] { ours = hrsr::self_intersecting_pairs(p, mesh.triangles, {}); });
        const double t_index =
            seconds([&] { by_index = hrsr::intersecting_pairs_by_index(p, mesh.triangles, {}); });
        const double t_cgal =
            seconds([&] { cgal = hrsr::testing::cgal_self_intersections(p, mesh.triangles); });
        if (!cgal) {
            std::fprintf(stderr, "%s: CGAL's Surface_mesh refused a face\n", argv[1]);
            return 1;
        }
        const bool equal = by_index == cgal->pairs;
        std::printf("triangles %zu ours %zu by_index %zu cgal %zu cgal_degenerate %zu equal %s "
                    "seconds_ours %.3f seconds_by_index %.3f seconds_cgal %.3f\n",
                    mesh.triangles.size(), ours.size(), by_index.size(), cgal->pairs.size(),
                    cgal->degenerate, equal ? "yes" : "no", t_ours, t_index, t_cgal);
        return equal ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
