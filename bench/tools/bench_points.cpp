// Point clouds for the benchmarks, from meshes (not part of the hrsr CLI):
//   bench_points vertices MESH.ply OUT.ply           the mesh's vertices (normals kept if any)
//   bench_points sample MESH.ply N OUT.ply [SEED]    N points uniform by area (vcglib's Montecarlo
//                                                    sampler), each with its triangle's unit normal
//   bench_points surface SHAPE N DENSITY NOISE NORMALS OUT.ply
//                                                    N points of an analytic surface (tests'
//                                                    samplers): SHAPE sphere|torus|double_torus|
//                                                    triple_torus, DENSITY uniform|graded, NOISE
//                                                    σ in % of the bounding-box diagonal, NORMALS
//                                                    normals|none (exact normals or a bare cloud)
// Exit codes: 0 success, 1 bad input or output, 2 usage.
#include "errors.h"
#include "io/mesh_reader.h"
#include "io/ply_writer.h"
#include "mesh_samples.h"
#include "samplers.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

int usage() {
    std::fprintf(stderr, "usage: bench_points vertices MESH.ply OUT.ply | "
                         "bench_points sample MESH.ply N OUT.ply [SEED] | "
                         "bench_points surface SHAPE N uniform|graded NOISE_PERCENT "
                         "normals|none OUT.ply\n");
    return 2;
}

void write_vertices(const std::string& in, const std::string& out) {
    const hrsr::io::MeshFile m = hrsr::io::read_mesh(in);
    hrsr::io::write_ply(out, m.points.positions, m.points.normals, {}, m.points.precision);
}

void write_samples(const std::string& in, std::size_t n, const std::string& out, unsigned seed) {
    const hrsr::PointSet s = hrsr::testing::sample_mesh_surface(in, n, seed);
    hrsr::io::write_ply(out, s.positions, s.normals, {}, hrsr::CoordinatePrecision::Float);
}

void write_surface(const std::vector<std::string>& a) {
    char* end = nullptr;
    const unsigned long long n = std::strtoull(a[2].c_str(), &end, 10);
    if (*end != '\0' || n == 0 || n > (1ull << 28)) throw hrsr::InvalidInput("bad N " + a[2]);
    if (a[3] != "uniform" && a[3] != "graded") throw hrsr::InvalidInput("bad density " + a[3]);
    const double noise_percent = std::stod(a[4]);
    if (!(noise_percent >= 0)) throw hrsr::InvalidInput("bad noise " + a[4]);
    if (a[5] != "normals" && a[5] != "none") throw hrsr::InvalidInput("bad normals " + a[5]);
    hrsr::PointSet s = hrsr::testing::sample_surface(
        a[1], std::size_t(n),
        a[3] == "graded" ? hrsr::testing::Density::Graded : hrsr::testing::Density::Uniform);
    hrsr::testing::add_noise(s, noise_percent / 100.0 * hrsr::testing::bounding_box_diagonal(s));
    if (a[5] == "none") s.normals.clear();
    hrsr::io::write_ply(a[6], s.positions, s.normals, {}, hrsr::CoordinatePrecision::Double);
}

} // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> a(argv + 1, argv + argc);
    try {
        if (a.size() == 3 && a[0] == "vertices") {
            write_vertices(a[1], a[2]);
        } else if ((a.size() == 4 || a.size() == 5) && a[0] == "sample") {
            char* end = nullptr;
            const unsigned long long n = std::strtoull(a[2].c_str(), &end, 10);
            if (*end != '\0' || n == 0 || n > (1ull << 30)) return usage();
            const unsigned seed = a.size() == 5 ? unsigned(std::stoul(a[4])) : 1u;
            write_samples(a[1], std::size_t(n), a[3], seed);
        } else if (a.size() == 7 && a[0] == "surface") {
            write_surface(a);
        } else {
            return usage();
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_points: %s\n", e.what());
        return 1;
    }
    return 0;
}
