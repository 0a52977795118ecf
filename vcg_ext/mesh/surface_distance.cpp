#include "mesh/surface_distance.h"

#include "errors.h"
#include "mesh/vcg_mesh.h"

#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/point_sampling.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <algorithm>
#include <cmath>

namespace hrsr {

namespace {

using FaceGrid = vcg::GridStaticPtr<VcgFace, double>;

struct Samples {
    std::vector<Vec3> points; ///< area samples, then vertices
    std::size_t area_samples = 0;
};

/// `count` random points uniform by area, then every vertex used by a triangle.
Samples sample_surface(VcgMesh& m, const std::vector<Triangle>& triangles, std::size_t count,
                       unsigned seed) {
    using Sampling = vcg::tri::SurfaceSampling<VcgMesh, vcg::tri::TrivialSampler<VcgMesh>>;
    Samples s;
    double area = 0;
    for (const VcgFace& f : m.face) area += vcg::DoubleArea(f);
    if (count > 0 && area > 0) {
        Sampling::SamplingRandomGenerator().initialize(seed);
        vcg::tri::TrivialSampler<VcgMesh> sampler(s.points);
        Sampling::Montecarlo(m, sampler, int(std::min<std::size_t>(count, 1u << 30)));
        s.area_samples = s.points.size();
    }
    std::vector<std::uint8_t> used(m.vert.size(), 0);
    for (const Triangle& t : triangles)
        for (std::uint32_t v : t)
            if (!used[v]) {
                used[v] = 1;
                s.points.push_back(m.vert[v].P());
            }
    return s;
}

OneSidedDistance distances(const Samples& s, FaceGrid& grid, double max_distance,
                           const Execution& exec) {
    const std::vector<Vec3>& samples = s.points;
    std::vector<double> d(samples.size());
    parallel_for(exec, samples.size(), [&](std::size_t i) {
        vcg::tri::EmptyTMark<VcgMesh> marker;
        vcg::face::PointDistanceBaseFunctor<double> point_distance;
        double distance = max_distance;
        Vec3 closest;
        grid.GetClosest(point_distance, marker, samples[i], max_distance, distance, closest);
        d[i] = distance;
    });
    OneSidedDistance r;
    r.area_samples = s.area_samples;
    r.vertices = d.size() - s.area_samples;
    // The mean over the area samples (over the vertices if the surface has no area).
    const std::size_t n = s.area_samples > 0 ? s.area_samples : d.size();
    double sum = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (i < n) sum += d[i];
        r.max = std::max(r.max, d[i]);
    }
    r.mean = n == 0 ? 0 : sum / double(n);
    return r;
}

vcg::Box3d bounding_box(const std::vector<Vec3>& positions) {
    vcg::Box3d box;
    for (const Vec3& p : positions) box.Add(p);
    return box;
}

} // namespace

SurfaceDistance surface_distance(const Surface& a, const Surface& b,
                                 const SurfaceDistanceOptions& o, const Execution& exec) {
    if (a.triangles.empty() || b.triangles.empty())
        throw InvalidInput("a surface distance needs triangles on both meshes");
    VcgMesh ma, mb;
    build_vcg_mesh(a.positions, {}, a.triangles, ma);
    build_vcg_mesh(b.positions, {}, b.triangles, mb);
    const Samples sa = sample_surface(ma, a.triangles, o.area_samples, o.seed);
    const Samples sb = sample_surface(mb, b.triangles, o.area_samples, o.seed + 1);

    vcg::Box3d box = bounding_box(a.positions);
    box.Add(bounding_box(b.positions));
    // No sample is farther from the other surface than the joint diagonal.
    const double max_distance = 2 * box.Diag() + 1;
    FaceGrid ga, gb;
    ga.Set(ma.face.begin(), ma.face.end());
    gb.Set(mb.face.begin(), mb.face.end());
    SurfaceDistance r;
    r.a_to_b = distances(sa, gb, max_distance, exec);
    r.b_to_a = distances(sb, ga, max_distance, exec);
    return r;
}

} // namespace hrsr
