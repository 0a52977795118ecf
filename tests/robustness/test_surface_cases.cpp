// Issue 7, item 1: awkward but legitimate geometry through the core (both methods): open
// patches, sheets closer than the spacing, crossing planes, several objects, a far outlier,
// inconsistent normals. Every result is a valid mesh with the expected topology, or warned about.
#include "mesh/self_intersections.h"
#include "robustness.h"
#include "samplers.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

using testing::attempt;
using testing::Attempt;
using testing::expect_closed;
using testing::expect_valid_mesh;
using testing::kMethods;
using testing::name;

// What every method guarantees on the planar cases below: a valid mesh without an intersecting
// pair (exact test).
void expect_no_fold_left(const Attempt& a, const PointSet& in, const std::string& context) {
    expect_valid_mesh(a, in, context);
    if (a.kind != Attempt::Mesh) return;
    std::vector<Vec3> written;
    for (std::uint32_t i : a.mesh.vertex_input_index) written.push_back(in.positions[i]);
    EXPECT_TRUE(self_intersecting_pairs(written, a.mesh.triangles, {}).empty()) << context;
}

// A flat grid (a disc with boundary): one component, one boundary loop, χ = 1, every point.
// HRsR since D-34 (border slivers peeled, border splits, notches closed): before it folded the
// grid's straight border over itself and D-32 cut the strip out (docs/STATUS.md, gap 15).
void expect_planar_disc(const PointSet& grid, Method m) {
    for (bool normals : {true, false}) {
        const PointSet& in = normals ? grid : testing::without_normals(grid);
        const Attempt a = attempt(in, m);
        expect_no_fold_left(a, in, name(m));
        const MeshStats& s = a.report.mesh;
        EXPECT_EQ(s.vertices, grid.size()) << name(m);
        ASSERT_EQ(s.components.size(), 1u) << name(m);
        EXPECT_EQ(s.boundary_loops, 1u) << name(m);
        EXPECT_EQ(s.euler(), 1) << name(m);
    }
}

TEST(SurfaceCases, PlanarGridIsADiscWithOneBoundaryLoop) {
    for (Method m : kMethods) expect_planar_disc(testing::sample_plane(40), m);
}

PointSet two_sheets(double gap, bool facing_away) {
    PointSet s = testing::sample_plane(40), top = testing::sample_plane(40, 1.0, 9);
    for (Vec3& p : top.positions) p[2] = gap;
    if (facing_away)
        for (Vec3& n : s.normals) n = -n;
    testing::append(s, top);
    return s;
}

// Two sheets 0.5 spacings apart. With normals pointing away from each other (the two sides of a
// thin plate) each sheet is its own disc; with parallel normals the input cannot tell the sheets
// apart and one manifold sheet over all points comes out. Both are flagged or valid, never broken.
TEST(SurfaceCases, TwoSheetsCloserThanTheSpacing) {
    for (Method m : kMethods) {
        const PointSet plate = two_sheets(0.5, true);
        const Attempt a = attempt(plate, m);
        expect_no_fold_left(a, plate, name(m));
        EXPECT_EQ(a.report.mesh.vertices, plate.size()) << name(m);
        ASSERT_EQ(a.report.mesh.components.size(), 2u) << name(m);
        for (const ComponentTopology& c : a.report.mesh.components) {
            EXPECT_EQ(c.vertices, 1600u) << name(m);
            EXPECT_EQ(c.boundary_loops, 1u) << name(m);
            EXPECT_EQ(c.euler(), 1) << name(m);
        }
        EXPECT_TRUE(a.has_warning("closer than the point spacing")) << name(m);

        const PointSet stacked = two_sheets(0.5, false);
        const Attempt b = attempt(stacked, m);
        expect_no_fold_left(b, stacked, name(m));
        EXPECT_EQ(b.report.mesh.vertices, stacked.size()) << name(m);
    }
}

// Two planes crossing at right angles: the mesh stays manifold (a point where sheets touch gets a
// vertex copy per sheet) and keeps nearly every point. Where triangles of one plane cross the
// other, D-32 takes points out: with RsR only near the line where the planes cross; with HRsR
// (r_v 98.97 % in session 13) also two points 4.5 and 10.5 spacings from it. No intersecting
// pair is left. RsR keeps the planes apart (two pieces of genus 0); HRsR's coarse RsR joins
// them across the line with handles (docs/STATUS.md, surfaces that touch): at every p from 1/8
// to 0.7 one main piece of genus 1–4 (session 31; at 400 coarse points, before D-47, genus 3
// and three scraps, which is what a count of at least two pieces had passed on).
TEST(SurfaceCases, CrossingPlanes) {
    PointSet s = testing::sample_plane(40), other = testing::sample_plane(40, 1.0, 9);
    for (std::size_t i = 0; i < other.size(); ++i) {
        const Vec3 p = other.positions[i];
        other.positions[i] = Vec3(p[0], 19.5, p[1] - 19.5);
        other.normals[i] = Vec3(0, 1, 0);
    }
    testing::append(s, other);
    for (Method m : kMethods) {
        const Attempt a = attempt(s, m);
        expect_valid_mesh(a, s, name(m));
        expect_no_fold_left(a, s, name(m));
        EXPECT_GT(a.report.vertex_reference_ratio, m == Method::Rsr ? 0.99 : 0.98) << name(m);
        if (m == Method::Rsr) {
            ASSERT_EQ(a.report.mesh.components.size(), 2u);
            for (const ComponentTopology& c : a.report.mesh.components) EXPECT_EQ(c.genus(), 0);
            for (std::uint32_t i : a.report.dropped_fold) {
                const Vec3& p = s.positions[i];
                EXPECT_LT(std::max(std::abs(p[1] - 19.5), std::abs(p[2])), 2.5) << i;
            }
        }
    }
}

// Two spheres and a torus far apart: three components, RsR closes all with their genus.
TEST(SurfaceCases, SeveralObjectsGiveSeveralComponents) {
    PointSet s = testing::sample_sphere(2000);
    testing::append(s,
                    testing::sample_sphere(2000, 1.0, Vec3(5, 0, 0), testing::Density::Uniform, 5));
    PointSet torus = testing::sample_torus(3000);
    for (Vec3& p : torus.positions) p += Vec3(0, 5, 0);
    testing::append(s, torus);
    for (Method m : kMethods) {
        const Attempt a = attempt(s, m);
        expect_valid_mesh(a, s, name(m));
        EXPECT_EQ(a.report.mesh.vertices, s.size()) << name(m);
        ASSERT_EQ(a.report.mesh.components.size(), 3u) << name(m);
        EXPECT_EQ(a.report.preprocess.components_kept, 3u) << name(m);
    }
    const Attempt rsr = attempt(s, Method::Rsr);
    std::vector<long> genus;
    for (const ComponentTopology& c : rsr.report.mesh.components) {
        EXPECT_TRUE(c.closed());
        genus.push_back(c.genus());
    }
    EXPECT_EQ(genus, (std::vector<long>{0, 0, 1}));
}

// One point 1000 diagonals away: dropped as a small component, the sphere comes out as without
// it (the normalisation changes, the result does not).
TEST(SurfaceCases, AFarOutlierIsDroppedAndChangesNothing) {
    const PointSet clean = testing::sample_sphere(3000);
    PointSet s = clean;
    s.positions.emplace_back(2000, 2000, 2000);
    s.normals.emplace_back(0, 0, 1);
    for (Method m : kMethods) {
        const Attempt a = attempt(s, m), b = attempt(clean, m);
        expect_closed(a, s, 0, 3000, name(m));
        // RsR drops it in pre-processing; HRsR in the hand-off, after collapsing (§7).
        if (m == Method::Rsr)
            EXPECT_EQ(a.report.preprocess.fate.back(), PointFate::SmallComponent);
        else
            EXPECT_EQ(a.report.dropped_small_coarse_component, std::vector<std::uint32_t>{3000});
        EXPECT_EQ(a.report.mesh.faces, b.report.mesh.faces) << name(m);
    }
}

// Half the input normals flipped (every other point): trusted as given, the cloud is two
// interleaved surfaces of opposite orientation. Not silent: a warning names the remedy, which
// gives the sphere.
TEST(SurfaceCases, HalfTheNormalsFlippedIsWarnedAboutAndReestimationFixesIt) {
    PointSet s = testing::sample_sphere(3000);
    for (std::size_t i = 0; i < s.size(); i += 2) s.normals[i] = -s.normals[i];
    for (Method m : kMethods) {
        const Attempt a = attempt(s, m);
        expect_valid_mesh(a, s, name(m));
        EXPECT_TRUE(a.has_warning("inconsistently oriented (re-estimate them)")) << name(m);
        EXPECT_TRUE(a.report.preprocess.input_normals_look_inconsistent) << name(m);
        EXPECT_GT(a.report.preprocess.opposed_input_normals, 300u);
        ReconstructionOptions o;
        o.rsr.preprocess.normals = NormalSource::Reestimate;
        expect_closed(attempt(s, m, o), s, 0, 3000, name(m));
    }
    // Consistent normals do not warn.
    const PointSet good = testing::sample_sphere(3000);
    const Attempt a = attempt(good, Method::Hrsr);
    EXPECT_EQ(a.report.preprocess.opposed_input_normals, 0u);
    EXPECT_FALSE(a.has_warning("re-estimate"));
    EXPECT_FALSE(a.report.preprocess.input_normals_look_inconsistent);
}

} // namespace
} // namespace hrsr
