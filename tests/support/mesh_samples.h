// Points sampled uniformly by area on a mesh file, each with its triangle's unit normal
// (vcglib's Montecarlo sampler, seeded): the clouds of bench_points' `sample` and of the tests on
// the shared reference meshes.
#pragma once

#include "errors.h"
#include "io/mesh_reader.h"
#include "mesh/vcg_mesh.h"
#include "point_set.h"

#include <vcg/complex/algorithms/point_sampling.h>

#include <string>
#include <vector>

namespace hrsr::testing {

/// Keeps each sample's position and the normal of the triangle it lies on.
class NormalSampler {
public:
    using MeshType = hrsr::VcgMesh;
    std::vector<Vec3> positions, normals;

    void AddFace(const hrsr::VcgFace& f, const Vec3& b) {
        positions.push_back(f.cP(0) * b[0] + f.cP(1) * b[1] + f.cP(2) * b[2]);
        normals.push_back(f.cN());
    }
    void AddVert(const hrsr::VcgVertex&) {}
    void AddEdge(const hrsr::VcgMesh::EdgeType&, double) {}
    void AddTextureSample(const hrsr::VcgFace&, const Vec3&, const vcg::Point2i&, float) {}
};

/// `n` points of the mesh in `path`, uniform by area; the same points for the same seed. Float
/// precision, as a PLY file of them stores.
inline PointSet sample_mesh_surface(const std::string& path, std::size_t n, unsigned seed = 1) {
    const io::MeshFile file = io::read_mesh(path);
    if (file.triangles.empty()) throw InvalidInput(path + ": the mesh has no triangles");
    hrsr::VcgMesh m;
    build_vcg_mesh(file.points.positions, {}, file.triangles, m);
    using Sampling = vcg::tri::SurfaceSampling<hrsr::VcgMesh, NormalSampler>;
    Sampling::SamplingRandomGenerator().initialize(seed);
    NormalSampler sampler;
    Sampling::Montecarlo(m, sampler, int(n));
    PointSet s;
    s.positions = std::move(sampler.positions);
    s.normals = std::move(sampler.normals);
    for (Vec3& p : s.positions)
        for (int k = 0; k < 3; ++k) p[k] = double(float(p[k]));
    for (Vec3& v : s.normals)
        for (int k = 0; k < 3; ++k) v[k] = double(float(v[k]));
    s.precision = CoordinatePrecision::Float;
    return s;
}

} // namespace hrsr::testing
