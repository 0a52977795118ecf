// Point clouds for the benchmarks, from meshes (not part of the hrsr CLI):
//   bench_points vertices MESH.ply OUT.ply           the mesh's vertices (normals kept if any)
//   bench_points sample MESH.ply N OUT.ply [SEED]    N points uniform by area (vcglib's Montecarlo
//                                                    sampler), each with its triangle's unit normal
// Exit codes: 0 success, 1 bad input or output, 2 usage.
#include "errors.h"
#include "io/mesh_reader.h"
#include "io/ply_writer.h"
#include "mesh/vcg_mesh.h"

#include <vcg/complex/algorithms/point_sampling.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

/// Keeps each sample's position and the normal of the triangle it lies on.
class NormalSampler {
public:
    using MeshType = hrsr::VcgMesh;
    std::vector<hrsr::Vec3> positions, normals;

    void AddFace(const hrsr::VcgFace& f, const hrsr::Vec3& b) {
        positions.push_back(f.cP(0) * b[0] + f.cP(1) * b[1] + f.cP(2) * b[2]);
        normals.push_back(f.cN());
    }
    void AddVert(const hrsr::VcgVertex&) {}
    void AddEdge(const hrsr::VcgMesh::EdgeType&, double) {}
    void AddTextureSample(const hrsr::VcgFace&, const hrsr::Vec3&, const vcg::Point2i&, float) {}
};

int usage() {
    std::fprintf(stderr, "usage: bench_points vertices MESH.ply OUT.ply | "
                         "bench_points sample MESH.ply N OUT.ply [SEED]\n");
    return 2;
}

void write_vertices(const std::string& in, const std::string& out) {
    const hrsr::io::MeshFile m = hrsr::io::read_mesh(in);
    hrsr::io::write_ply(out, m.points.positions, m.points.normals, {}, m.points.precision);
}

void write_samples(const std::string& in, std::size_t n, const std::string& out, unsigned seed) {
    const hrsr::io::MeshFile file = hrsr::io::read_mesh(in);
    if (file.triangles.empty()) throw hrsr::InvalidInput(in + ": the mesh has no triangles");
    hrsr::VcgMesh m;
    hrsr::build_vcg_mesh(file.points.positions, {}, file.triangles, m);
    using Sampling = vcg::tri::SurfaceSampling<hrsr::VcgMesh, NormalSampler>;
    Sampling::SamplingRandomGenerator().initialize(seed);
    NormalSampler sampler;
    Sampling::Montecarlo(m, sampler, int(n));
    hrsr::io::write_ply(out, sampler.positions, sampler.normals, {},
                        hrsr::CoordinatePrecision::Float);
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
        } else {
            return usage();
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_points: %s\n", e.what());
        return 1;
    }
    return 0;
}
