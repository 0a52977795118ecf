// The face split's parallel look-ahead (rsr/face_split.cpp) must give what taking the candidates
// one by one gives (look-ahead 1), and its tiles in parallel (D-51) what they give one after
// another: the same triangles, the same rotation and the same counts, for any thread count.
#include "errors.h"
#include "geometry.h"
#include "knn.h"
#include "options.h"
#include "rsr/candidate_graph.h"
#include "rsr/face_split.h"
#include "rsr/spanning_tree.h"
#include "rsr_invariants.h"
#include "samplers.h"
#include "spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace hrsr {
namespace {

struct Split {
    rsr::CandidateGraph graph;                        ///< whose edges were the candidates
    std::unique_ptr<const std::vector<Vec3>> normals; ///< those the rotation measures with
    std::unique_ptr<rsr::RotationSystem> embedded;    ///< the rotation after the phase
    std::unique_ptr<rsr::Faces> faces_of;             ///< its faces
    std::vector<rsr::LocalTriangle> triangles;
    rsr::FaceSplitStats stats;
    std::size_t candidates = 0;
    std::size_t tree_edge_candidates = 0; ///< candidates already edges before the phase
};

// The neighbours of each vertex, in rotation order.
std::vector<std::vector<std::uint32_t>> neighbours(const rsr::RotationSystem& rotation) {
    std::vector<std::vector<std::uint32_t>> out(rotation.vertex_count());
    for (std::uint32_t v = 0; v < rotation.vertex_count(); ++v)
        for (const rsr::Dart& d : rotation.darts(v)) out[v].push_back(d.to);
    return out;
}

// RsR's stages up to the face split (as reconstruct_component runs them), then the face split.
// `tiles`: in in_tile_order()'s order (as RsR takes them), else in length order.
Split split(const rsr::ComponentCloud& cloud, const KnnIndex& index, int threads,
            std::size_t look_ahead, bool tiles = false, rsr::Observer* observer = nullptr) {
    const PreprocessOptions pre;
    Split s;
    s.graph = rsr::build_candidate_graph(cloud, index, pre, {});
    const rsr::CandidateGraph& graph = s.graph;
    auto candidates = rsr::face_split_candidates(graph, cloud, pre.distance, {});
    if (tiles) candidates = rsr::in_tile_order(std::move(candidates), {});
    const SpanningForest tree = rsr::candidate_spanning_tree(graph, cloud);
    s.normals = std::make_unique<const std::vector<Vec3>>(rsr::fix_leaf_normals(tree, cloud));
    const std::vector<Vec3>& normals = *s.normals;
    s.embedded = std::make_unique<rsr::RotationSystem>(cloud.smoothed, normals);
    rsr::RotationSystem& rotation = *s.embedded;
    for (std::uint32_t v : tree.order)
        if (tree.parent[v] != SpanningForest::kRoot) rotation.insert_edge(tree.parent[v], v);
    s.candidates = candidates.size();
    for (const rsr::CandidateEdge& c : candidates)
        s.tree_edge_candidates += tree.parent[c.i] == c.j || tree.parent[c.j] == c.i;
    s.faces_of = std::make_unique<rsr::Faces>(rotation);
    rsr::Faces& faces = *s.faces_of;
    faces.label_all();
    if (observer) observer->tree_built(rotation, faces);
    rsr::GeometryCheck geometry(index, cloud.smoothed, normals, rotation);
    rsr::Embedding e{rotation, faces, geometry, s.triangles, observer};
    s.stats = rsr::split_faces(e, candidates, {threads, nullptr}, look_ahead);
    return s;
}

void expect_same(const Split& a, const Split& b) {
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(neighbours(*a.embedded), neighbours(*b.embedded));
    EXPECT_EQ(a.faces_of->count(), b.faces_of->count());
    EXPECT_EQ(a.stats.inserted, b.stats.inserted);
    EXPECT_EQ(a.stats.rejected_topology, b.stats.rejected_topology);
    EXPECT_EQ(a.stats.rejected_geometry, b.stats.rejected_geometry);
    EXPECT_EQ(a.stats.rejected_triangles, b.stats.rejected_triangles);
}

// A noisy graded double torus: every kind of rejection occurs, and candidates whose wedges share
// a face before their batch are often split apart by an earlier candidate of the same batch.
TEST(FaceSplit, LookingAheadInParallelTakesTheCandidatesAsOneByOne) {
    PointSet s = testing::sample_double_torus(12000, testing::Density::Graded);
    testing::add_noise(s, 0.004 * testing::bounding_box_diagonal(s));
    const rsr::ComponentCloud cloud{s.positions, s.positions, s.normals, s.size(), {}, {}};
    const KnnIndex index(cloud.smoothed);
    const Split one_by_one = split(cloud, index, 1, 1);
    ASSERT_GT(one_by_one.stats.inserted, 10000u);
    EXPECT_GT(one_by_one.stats.rejected_topology, 0u);
    EXPECT_GT(one_by_one.stats.rejected_geometry, 0u);
    EXPECT_GT(one_by_one.stats.rejected_triangles, 0u);
    // Every candidate is inserted or rejected once, but for the tree's edges (passed over).
    const rsr::FaceSplitStats& n = one_by_one.stats;
    EXPECT_GT(one_by_one.tree_edge_candidates, 1000u);
    EXPECT_EQ(n.inserted + n.rejected_topology + n.rejected_geometry + n.rejected_triangles +
                  one_by_one.tree_edge_candidates,
              one_by_one.candidates);
    for (std::size_t look_ahead : {std::size_t(64), rsr::kFaceSplitLookAhead})
        for (int threads : {1, 2, 8}) {
            SCOPED_TRACE(::testing::Message()
                         << "look-ahead " << look_ahead << ", " << threads << " threads");
            expect_same(split(cloud, index, threads, look_ahead), one_by_one);
        }
}

// D-51: a cloud of several tiles takes each step's tiles at once and what they defer after them.
// The result must not depend on the thread count, nor on an observer (which takes the tiles one
// after another); the labels must be those of the faces traced from scratch, and the embedding
// stays one of genus 0 (χ = 2). A graded noisy double torus of 33k points (three tiles), in
// spatial order as RsR sees its clouds (D-40): its tiles defer some 3,000 candidates.
TEST(FaceSplit, TilesOfAStepGiveOneSplitForAnyThreadCount) {
    PointSet sampled = testing::sample_double_torus(60000, testing::Density::Graded);
    testing::add_noise(sampled, 0.002 * testing::bounding_box_diagonal(sampled));
    const PointSet s = reordered(sampled, spatial_order(sampled.positions, {}));
    const rsr::ComponentCloud cloud{s.positions, s.positions, s.normals, s.size(), {}, {}};
    const KnnIndex index(cloud.smoothed);
    const Split one = split(cloud, index, 1, rsr::kFaceSplitLookAhead, true);
    const rsr::FaceSplitStats& n = one.stats;
    ASSERT_GT(n.inserted, 50000u);
    EXPECT_GT(n.deferred, 100u);
    EXPECT_LT(n.deferred, n.inserted / 5);
    EXPECT_EQ(n.inserted + n.rejected_topology + n.rejected_geometry + n.rejected_triangles +
                  one.tree_edge_candidates,
              one.candidates);
    testing::InvariantChecker::check_faces(*one.embedded, *one.faces_of);
    EXPECT_EQ(long(one.embedded->vertex_count()) - long(one.embedded->edge_count()) +
                  long(one.faces_of->count()),
              2);
    for (int threads : {2, 8}) {
        SCOPED_TRACE(::testing::Message() << threads << " threads");
        const Split many = split(cloud, index, threads, rsr::kFaceSplitLookAhead, true);
        expect_same(many, one);
        EXPECT_EQ(many.stats.deferred, n.deferred);
    }
    testing::InvariantChecker checker(5000);
    SCOPED_TRACE("observed");
    expect_same(split(cloud, index, 2, rsr::kFaceSplitLookAhead, true, &checker), one);
}

// D-51's label blocks: consecutive, and a clear error (not a wrapped label) once the 2^30 labels
// of a dart would run out.
TEST(FaceSplit, LabelBlocksAreConsecutiveAndBoundedByTheDartsBits) {
    const std::vector<Vec3> positions{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    const std::vector<Vec3> normals(3, Vec3(0, 0, 1));
    rsr::RotationSystem rotation(positions, normals);
    rotation.insert_edge(0, 1);
    rotation.insert_edge(1, 2);
    rsr::Faces faces(rotation);
    faces.label_all(); // one face: label 0
    EXPECT_EQ(faces.reserve_labels(5), 1u);
    EXPECT_EQ(faces.reserve_labels(0), 6u);
    EXPECT_FALSE(faces.is_recorded_triangle(5));
    EXPECT_THROW(faces.reserve_labels(rsr::kNoFace), InvalidInput);
    // One label more than 6 … kNoFace − 1 (taking them all would allocate a flag for each).
    EXPECT_THROW(faces.reserve_labels(rsr::kNoFace - 6 + 1), InvalidInput);
    EXPECT_EQ(faces.reserve_labels(1), 6u); // nothing was taken by the refusals
}

// The look-ahead rejects a candidate at a vertex surrounded by triangles without its angles: no
// vertex not adjacent has a wedge in the face of one of its wedges. Checked on every candidate of
// such a vertex after the phase (the rotation is final; every triangle there was one before).
TEST(FaceSplit, AVertexSurroundedByTrianglesSharesNoFaceWithOneNotAdjacent) {
    PointSet s = testing::sample_double_torus(12000, testing::Density::Graded);
    testing::add_noise(s, 0.004 * testing::bounding_box_diagonal(s));
    const rsr::ComponentCloud cloud{s.positions, s.positions, s.normals, s.size(), {}, {}};
    const KnnIndex index(cloud.smoothed);
    const Split after = split(cloud, index, 2, rsr::kFaceSplitLookAhead);
    const rsr::RotationSystem& rotation = *after.embedded;
    const CsrGraph& graph = after.graph.graph;
    std::size_t surrounded = 0, checked = 0;
    for (std::uint32_t v = 0; v < rotation.vertex_count(); ++v) {
        if (!rsr::surrounded_by_triangles(rotation, v)) continue;
        ++surrounded;
        for (const std::uint32_t* w = graph.begin(v); w != graph.end(v); ++w)
            if (!rotation.adjacent(v, *w)) {
                ++checked;
                EXPECT_NE(after.faces_of->face_of_wedge(v, *w),
                          after.faces_of->face_of_wedge(*w, v))
                    << v << " to " << *w;
            }
    }
    EXPECT_GT(surrounded, rotation.vertex_count() / 2);
    EXPECT_GT(checked, 10 * surrounded);
}

// The geometry check tests a candidate against each edge near it with the candidate's plane
// worked out once (SegmentCrossings): every answer must be segments_cross's, also where a point
// lies on the other segment or the two are collinear (integer grids), and with normals apart.
TEST(FaceSplit, OneSegmentAgainstManyAnswersAsThePairTest) {
    std::mt19937 rng(20261130);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> grid(-2, 2);
    const auto normal = [&](double tilt) {
        Vec3 n(tilt * unit(rng), tilt * unit(rng), 1.0);
        return n / n.Norm();
    };
    std::size_t crossing = 0, apart = 0;
    for (int on_grid : {0, 1})
        for (double tilt : {0.0, 0.3, 1.5})
            for (int set = 0; set < 200; ++set) {
                const auto point = [&] {
                    return on_grid ? Vec3(grid(rng), grid(rng), 0.0)
                                   : Vec3(unit(rng), unit(rng), 0.2 * unit(rng));
                };
                const Vec3 a = point(), b = point(), na = normal(tilt), nb = normal(tilt);
                if (a == b) continue;
                const SegmentCrossings ab({a, b, na, nb});
                for (int other = 0; other < 30; ++other) {
                    const Vec3 c = point(), d = point(), nc = normal(tilt), nd = normal(tilt);
                    if (c == d || c == a || c == b || d == a || d == b) continue;
                    const bool expected = segments_cross({a, b, na, nb}, {c, d, nc, nd});
                    ASSERT_EQ(ab.crossed_by({c, d, nc, nd}), expected)
                        << "set " << set << ", grid " << on_grid << ", tilt " << tilt;
                    ++(expected ? crossing : apart);
                }
            }
    EXPECT_GT(crossing, 5000u);
    EXPECT_GT(apart, 5000u);
}

// The candidates are sorted in parallel: the list must be the ascending (length, i, j) one for any
// thread count.
TEST(FaceSplit, CandidatesAreInOneOrderForAnyThreadCount) {
    const PointSet s = testing::sample_torus(20000);
    const rsr::ComponentCloud cloud{s.positions, s.positions, s.normals, s.size(), {}, {}};
    const KnnIndex index(cloud.smoothed);
    const PreprocessOptions pre;
    const rsr::CandidateGraph graph = rsr::build_candidate_graph(cloud, index, pre, {});
    const auto one = rsr::face_split_candidates(graph, cloud, pre.distance, {1, nullptr});
    ASSERT_GT(one.size(), 100000u);
    for (std::size_t c = 1; c < one.size(); ++c) {
        const auto& a = one[c - 1];
        const auto& b = one[c];
        ASSERT_TRUE(a.length < b.length ||
                    (a.length == b.length && (a.i < b.i || (a.i == b.i && a.j < b.j))))
            << "at " << c;
    }
    for (int threads : {2, 8}) {
        const auto many =
            rsr::face_split_candidates(graph, cloud, pre.distance, {threads, nullptr});
        ASSERT_EQ(many.size(), one.size());
        for (std::size_t c = 0; c < one.size(); ++c)
            ASSERT_TRUE(many[c].length == one[c].length && many[c].i == one[c].i &&
                        many[c].j == one[c].j)
                << threads << " threads, at " << c;
    }
}

// D-50: each of the eight steps (an equal part of the length order) holds the candidates it held,
// tile by tile (16,384 consecutive points), then those across tiles, each group in length
// order; the same for any thread count; a component of one tile keeps the length order.
TEST(FaceSplit, InTileOrderTakesEachStepTileByTile) {
    const PreprocessOptions pre;
    const auto by_length = [&](const PointSet& s) {
        const rsr::ComponentCloud cloud{s.positions, s.positions, s.normals, s.size(), {}, {}};
        const KnnIndex index(cloud.smoothed);
        const rsr::CandidateGraph graph = rsr::build_candidate_graph(cloud, index, pre, {});
        return rsr::face_split_candidates(graph, cloud, pre.distance, {});
    };
    const auto before = [](const rsr::CandidateEdge& a, const rsr::CandidateEdge& b) {
        return a.length < b.length ||
               (a.length == b.length && (a.i < b.i || (a.i == b.i && a.j < b.j)));
    };
    const auto same = [](const rsr::CandidateEdge& a, const rsr::CandidateEdge& b) {
        return a.length == b.length && a.i == b.i && a.j == b.j;
    };
    const auto tile = [](const rsr::CandidateEdge& e) {
        const std::uint32_t t = e.i >> rsr::kFaceSplitTileBits;
        return t == e.j >> rsr::kFaceSplitTileBits ? t : std::numeric_limits<std::uint32_t>::max();
    };

    const auto candidates = by_length(testing::sample_torus(40000)); // three tiles
    const auto tiled = rsr::in_tile_order(candidates, {1, nullptr});
    const std::size_t n = candidates.size();
    ASSERT_EQ(tiled.size(), n);
    std::size_t across = 0, moved = 0;
    for (std::size_t step = 0; step < rsr::kFaceSplitSteps; ++step) {
        const std::size_t first = n * step / rsr::kFaceSplitSteps;
        const std::size_t last = n * (step + 1) / rsr::kFaceSplitSteps;
        for (std::size_t c = first; c < last; ++c) {
            across += tile(tiled[c]) == std::numeric_limits<std::uint32_t>::max();
            moved += !same(tiled[c], candidates[c]);
            if (c > first) {
                ASSERT_TRUE(
                    tile(tiled[c - 1]) < tile(tiled[c]) ||
                    (tile(tiled[c - 1]) == tile(tiled[c]) && before(tiled[c - 1], tiled[c])))
                    << "at " << c;
            }
        }
        std::vector<rsr::CandidateEdge> step_back(tiled.begin() + std::ptrdiff_t(first),
                                                  tiled.begin() + std::ptrdiff_t(last));
        std::sort(step_back.begin(), step_back.end(), before);
        for (std::size_t c = first; c < last; ++c)
            ASSERT_TRUE(same(step_back[c - first], candidates[c])) << "step " << step << ", " << c;
    }
    EXPECT_GT(across, 0u);
    EXPECT_GT(moved, n / 10);
    for (int threads : {2, 8}) {
        const auto again = rsr::in_tile_order(candidates, {threads, nullptr});
        for (std::size_t c = 0; c < n; ++c)
            ASSERT_TRUE(same(again[c], tiled[c])) << threads << " threads, at " << c;
    }

    const auto one_tile = by_length(testing::sample_torus(12000));
    const auto kept = rsr::in_tile_order(one_tile, {2, nullptr});
    ASSERT_EQ(kept.size(), one_tile.size());
    for (std::size_t c = 0; c < kept.size(); ++c) ASSERT_TRUE(same(kept[c], one_tile[c])) << c;
}

// HRsR's hand-off passes its kNN rows of the whole coarse cloud; a component takes the rows that
// lie in it and queries the others. The graph must be the one its own queries give: here a torus
// with a sphere touching it (rows across the two) and entries of points dropped afterwards.
TEST(CandidateGraph, KnownRowsGiveTheGraphTheComponentsQueriesGive) {
    const PointSet torus = testing::sample_torus(6000);
    const PointSet sphere = testing::sample_sphere(3000, 0.3, Vec3(1.6, 0, 0));
    std::vector<Vec3> positions = torus.positions, normals = torus.normals;
    std::vector<std::uint32_t> component(torus.size(), 0);
    positions.insert(positions.end(), sphere.positions.begin(), sphere.positions.end());
    normals.insert(normals.end(), sphere.normals.begin(), sphere.normals.end());
    component.resize(positions.size(), 1);
    const PreprocessOptions pre;
    KnnTable table;
    {
        const KnnIndex whole(positions);
        table = knn_table(whole, pre.k, {});
    }
    for (std::size_t e = 0; e < table.index.size(); e += 997) table.index[e] = kNoNeighbour;
    std::vector<std::uint32_t> local_index(positions.size());
    for (std::uint32_t i = 0; i < positions.size(); ++i)
        local_index[i] = component[i] == 0 ? i : i - std::uint32_t(torus.size());

    for (std::uint32_t c : {0U, 1U}) {
        rsr::ComponentCloud cloud;
        std::vector<std::uint32_t> cloud_index;
        for (std::uint32_t i = 0; i < positions.size(); ++i) {
            if (component[i] != c) continue;
            cloud_index.push_back(i);
            cloud.positions.push_back(positions[i]);
            cloud.smoothed.push_back(positions[i]);
            cloud.normals.push_back(normals[i]);
        }
        cloud.represented_points = cloud.smoothed.size();
        std::size_t inside = 0;
        for (std::uint32_t i : cloud_index) {
            const std::uint32_t* row = table.row(i);
            inside += std::all_of(row, row + table.k, [&](std::uint32_t e) {
                return e != kNoNeighbour && component[e] == c;
            });
        }
        EXPECT_GT(inside, cloud_index.size() / 2) << "component " << c;
        EXPECT_LT(inside, cloud_index.size()) << "component " << c;

        const KnnIndex index(cloud.smoothed);
        const rsr::CandidateGraph queried = rsr::build_candidate_graph(cloud, index, pre, {});
        cloud.known_neighbours = {&table, cloud_index.data(), component.data(), local_index.data(),
                                  c};
        for (int threads : {1, 2}) {
            const rsr::CandidateGraph known =
                rsr::build_candidate_graph(cloud, index, pre, {threads, nullptr});
            EXPECT_EQ(known.graph.offsets, queried.graph.offsets) << "component " << c;
            EXPECT_EQ(known.graph.adjacency, queried.graph.adjacency) << "component " << c;
            EXPECT_EQ(known.pre_max_length, queried.pre_max_length) << "component " << c;
            EXPECT_EQ(known.max_length, queried.max_length) << "component " << c;
        }
    }
}

} // namespace
} // namespace hrsr
