#include "graph/neighbour_graph.h"
#include "knn.h"
#include "knn_tree.h"
#include "samplers.h"
#include "spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <string>

namespace hrsr {
namespace {

TEST(Knn, SortedByDistanceThenIndexWithoutSelf) {
    // A square grid: many neighbours at exactly equal distances.
    std::vector<Vec3> points;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) points.emplace_back(i, j, 0);
    const KnnIndex index(points);
    std::vector<Neighbour> found;
    for (std::uint32_t q = 0; q < points.size(); ++q) {
        index.neighbours_of(q, 8, found);
        ASSERT_EQ(found.size(), 8u);
        for (std::size_t a = 0; a < found.size(); ++a) {
            EXPECT_NE(found[a].index, q);
            EXPECT_DOUBLE_EQ(found[a].squared_distance,
                             (points[found[a].index] - points[q]).SquaredNorm());
            if (a > 0) {
                const auto& p = found[a - 1];
                EXPECT_TRUE(
                    p.squared_distance < found[a].squared_distance ||
                    (p.squared_distance == found[a].squared_distance && p.index < found[a].index));
            }
        }
    }
    // Interior point 55 = (5,5): 4 at distance 1 and 4 at sqrt 2, by index.
    index.neighbours_of(55, 8, found);
    std::vector<std::uint32_t> ids;
    for (const auto& f : found) ids.push_back(f.index);
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{45, 54, 56, 65, 44, 46, 64, 66}));
}

TEST(Knn, KIsClampedToTheOtherPoints) {
    const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
    const KnnIndex index(points);
    std::vector<Neighbour> found;
    index.neighbours_of(0, 10, found);
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0].index, 1u);
    EXPECT_EQ(found[1].index, 2u);
    const KnnTable table = knn_table(index, 10, {});
    EXPECT_EQ(table.k, 2);
    EXPECT_EQ(table.size(), 3u);
}

TEST(Knn, EmptyAndSinglePointAreSafe) {
    const std::vector<Vec3> none;
    const KnnIndex empty(none);
    std::vector<Neighbour> found;
    empty.nearest(Vec3(0, 0, 0), 3, found);
    EXPECT_TRUE(found.empty());
    EXPECT_EQ(knn_table(empty, 5, {}).size(), 0u);
    const std::vector<Vec3> one{{1, 2, 3}};
    const KnnIndex single(one);
    single.neighbours_of(0, 5, found);
    EXPECT_TRUE(found.empty());
}

TEST(Knn, TableRowsEqualSingleQueries) {
    const PointSet s = testing::sample_sphere(2000);
    const KnnIndex index(s.positions);
    const KnnTable table = knn_table(index, 12, {});
    std::vector<Neighbour> found;
    for (std::uint32_t i = 0; i < s.size(); i += 37) {
        index.neighbours_of(i, 12, found);
        for (int j = 0; j < 12; ++j) EXPECT_EQ(table.row(i)[j], found[std::size_t(j)].index);
    }
}

TEST(Knn, DistancesAtRanksEqualTheSortedNeighbours) {
    // A grid (ties at every rank), exact duplicates (more than a rank of them), and too few
    // points for the deepest rank.
    std::vector<Vec3> points;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) points.emplace_back(i, j, 0);
    for (int d = 0; d < 5; ++d) points.emplace_back(2, 2, 0);
    const KnnIndex index(points);
    const std::vector<int> ranks{1, 4, 9, 0, 40, 41, 60};
    std::vector<Neighbour> found;
    std::vector<double> at_ranks;
    for (std::uint32_t q = 0; q < points.size(); ++q) {
        index.neighbours_of(q, 60, found);
        index.squared_distances_at_ranks(q, ranks, at_ranks);
        ASSERT_EQ(at_ranks.size(), ranks.size());
        for (std::size_t r = 0; r < ranks.size(); ++r) {
            const bool exists = ranks[r] >= 1 && std::size_t(ranks[r]) <= found.size();
            EXPECT_EQ(at_ranks[r], exists ? found[std::size_t(ranks[r]) - 1].squared_distance
                                          : std::numeric_limits<double>::infinity())
                << "point " << q << " rank " << ranks[r];
        }
    }
    EXPECT_EQ(found.size(), points.size() - 1);
}

TEST(Knn, AtLeastDecidesAsTheSortedNeighboursDo) {
    // The test D-30 makes: at least count points (the point's own included) with
    // length > 2 · √d. A grid (ties at every distance), exact duplicates, a random sphere, counts
    // beyond the cloud, lengths on the ties.
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) points.emplace_back(i, j, 0);
    for (int d = 0; d < 3; ++d) points.emplace_back(3, 3, 0);
    const PointSet sphere = testing::sample_sphere(500);
    for (const Vec3& p : sphere.positions) points.push_back(p * 3.0 + Vec3(20, 0, 0));
    const KnnIndex index(points);
    std::vector<Neighbour> found;
    int decided_true = 0, decided_false = 0;
    for (std::uint32_t q = 0; q < points.size(); q += 3) {
        index.neighbours_of(q, int(points.size()), found);
        for (const double length : {0.5, 2.0, 2.0 * std::sqrt(2.0), 4.0, 5.3, 12.0}) {
            for (const std::size_t count : {std::size_t(1), std::size_t(5), std::size_t(30),
                                            points.size(), points.size() + 1}) {
                const auto nearer = [length](double squared) {
                    return length > 2.0 * std::sqrt(squared);
                };
                // The point itself at 0, then its neighbours in order.
                std::size_t expected = nearer(0.0) ? 1 : 0;
                for (const Neighbour& n : found) expected += nearer(n.squared_distance) ? 1 : 0;
                const bool answer =
                    index.at_least(points[q], length / 2 * (1 + 1e-9), count, nearer);
                EXPECT_EQ(answer, expected >= count)
                    << "point " << q << " length " << length << " count " << count;
                (answer ? decided_true : decided_false)++;
            }
        }
    }
    EXPECT_GT(decided_true, 100);
    EXPECT_GT(decided_false, 100);
    const std::vector<Vec3> none;
    EXPECT_FALSE(KnnIndex(none).at_least(Vec3(0, 0, 0), 1, 1, [](double) { return true; }));
    EXPECT_TRUE(KnnIndex(none).at_least(Vec3(0, 0, 0), 1, 0, [](double) { return true; }));
}

std::set<std::uint32_t> indices_of(const std::vector<Neighbour>& found) {
    std::set<std::uint32_t> ids;
    for (const Neighbour& n : found) ids.insert(n.index);
    return ids;
}

// A grid (ties at every distance) with more exact duplicates of one point than k, beside a random
// sphere.
std::vector<Vec3> grid_duplicates_and_sphere() {
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) points.emplace_back(i, j, 0);
    for (int d = 0; d < 12; ++d) points.emplace_back(3, 3, 0);
    for (const Vec3& p : testing::sample_sphere(600).positions)
        points.push_back(p * 3.0 + Vec3(20, 0, 0));
    return points;
}

TEST(Knn, WithinARadiusAreTheKNearestUnlessTiedAtTheKth) {
    const std::vector<Vec3> points = grid_duplicates_and_sphere();
    const KnnIndex index(points);
    std::vector<Neighbour> all, within, nearest;
    int short_radius = 0, tied = 0, found = 0;
    for (std::uint32_t q = 0; q < points.size(); q += 5) {
        index.neighbours_of(q, int(points.size()), all); // every other point, sorted
        for (const int k : {1, 6, 20}) {
            const double kth = std::sqrt(all[std::size_t(k) - 1].squared_distance);
            const bool tie =
                all[std::size_t(k)].squared_distance == all[std::size_t(k) - 1].squared_distance;
            const bool answered = index.neighbours_within(q, kth * (1 + 1e-9) + 1e-12, k, within);
            EXPECT_EQ(answered, !tie) << "point " << q << " k " << k;
            (tie ? tied : found)++;
            if (!answered) continue;
            index.neighbours_of(q, k, nearest);
            ASSERT_EQ(within.size(), nearest.size());
            for (std::size_t e = 0; e < within.size(); ++e) { // the same, in the same order
                EXPECT_EQ(within[e].index, nearest[e].index) << "point " << q << " k " << k;
                EXPECT_EQ(within[e].squared_distance, nearest[e].squared_distance);
            }
            // Fewer than k strictly nearer than the k-th: a radius short of it finds too few.
            const std::size_t nearer =
                std::size_t(std::count_if(all.begin(), all.end(), [&](const Neighbour& n) {
                    return n.squared_distance < all[std::size_t(k) - 1].squared_distance;
                }));
            if (kth > 0 && nearer < std::size_t(k)) {
                EXPECT_FALSE(index.neighbours_within(q, kth * (1 - 1e-6), k, within));
                ++short_radius;
            }
        }
    }
    EXPECT_GT(short_radius, 100);
    EXPECT_GT(tied, 20); // the grid's
    EXPECT_GT(found, 300);
}

// The rounds of §4.4: the same k asked of the same points, then of the points moved along
// normals. Whether by radius or by the k-nearest query, each round's are the moved points' own
// k nearest (a random cloud: no ties).
TEST(NeighbourReach, EveryRoundFindsTheKNearestOfThePointsAsTheyStand) {
    const PointSet sphere = testing::sample_sphere(3000);
    std::vector<Vec3> points = sphere.positions;
    const int k = 24;
    NeighbourReach reach;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> small(-0.002, 0.002); // spacing about 0.065
    std::vector<Neighbour> by_reach, by_query, afresh;
    const auto round = [&](const std::vector<Vec3>& at) {
        const KnnIndex index(at);
        reach.begin_round(at.size(), k);
        NeighbourReach fresh; // no radius yet: by the k-nearest query
        fresh.begin_round(at.size(), k);
        for (std::uint32_t i = 0; i < at.size(); ++i) {
            reach.neighbours(index, i, by_reach);
            index.neighbours_of(i, k, by_query);
            ASSERT_EQ(indices_of(by_reach), indices_of(by_query)) << "point " << i;
            // The same order whichever way they were found (the sums over them do not depend
            // on which rounds came before).
            fresh.neighbours(index, i, afresh);
            ASSERT_EQ(afresh.size(), by_reach.size());
            for (std::size_t e = 0; e < afresh.size(); ++e)
                ASSERT_EQ(afresh[e].index, by_reach[e].index) << "point " << i;
        }
    };
    round(points);
    EXPECT_EQ(reach.radii_known(), points.size());
    round(points); // the same points again: every query by radius
    for (int moves = 0; moves < 2; ++moves) {
        std::vector<double> shift(points.size());
        std::vector<Vec3> moved = points;
        for (std::size_t i = 0; i < points.size(); ++i) {
            shift[i] = small(random);
            moved[i] = points[i] + sphere.normals[i] * shift[i];
        }
        reach.moved(points, shift, {});
        EXPECT_GT(reach.radii_known(), points.size() * 9 / 10); // small moves: kept
        points = moved;
        round(points);
    }
    // One point moved far: the radii near it are forgotten (asked by the k-nearest query), the
    // others kept; every answer still exact.
    std::vector<double> shift(points.size(), 0.0);
    shift[0] = 0.5;
    std::vector<Vec3> moved = points;
    moved[0] = points[0] + sphere.normals[0] * shift[0];
    reach.moved(points, shift, {});
    EXPECT_LT(reach.radii_known(), points.size());
    EXPECT_GT(reach.radii_known(), points.size() / 2);
    round(moved);
    // Another k: the radii are forgotten, the answers exact.
    const KnnIndex index(moved);
    reach.begin_round(moved.size(), k + 5);
    EXPECT_EQ(reach.radii_known(), 0u);
    reach.neighbours(index, 17, by_reach);
    index.neighbours_of(17, k + 5, by_query);
    EXPECT_EQ(indices_of(by_reach), indices_of(by_query));
}

std::vector<std::uint32_t> indices_in_order(const std::vector<Neighbour>& found) {
    std::vector<std::uint32_t> ids;
    for (const Neighbour& n : found) ids.push_back(n.index);
    return ids;
}

// Where no radius is kept, a round tries the last radius its thread found (widened): whatever
// that guess, each point's neighbours are the k nearest in the walk's order, as found from
// vcglib's k-th distance. A grid (ties at every rank), copies of a point, a dense cluster beside
// sparse points and far outliers (a guess taken after them gathers too much and is given up),
// in spatial order as the pipeline has them, on 1, 2 and 8 threads.
TEST(NeighbourReach, AGuessedRadiusFindsWhatTheKNearestQueryFinds) {
    std::vector<Vec3> points = grid_duplicates_and_sphere();
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < 1500; ++i)
        points.emplace_back(3 + 0.05 * unit(random), 3 + 0.05 * unit(random), 0.05 * unit(random));
    for (int i = 0; i < 6; ++i) points.emplace_back(40.0 * (i + 1), -30.0 * i, 55.0);
    std::vector<Vec3> ordered;
    for (std::uint32_t i : spatial_order(points, {}).input_index) ordered.push_back(points[i]);
    const KnnIndex index(ordered);
    for (const int k : {1, 12, 40}) {
        std::vector<std::vector<Neighbour>> expected(ordered.size());
        std::vector<int> rank{k};
        std::vector<double> kth;
        for (std::uint32_t i = 0; i < ordered.size(); ++i) {
            index.squared_distances_at_ranks(i, rank, kth); // the path without a guess
            const double reach = std::sqrt(kth.front());
            if (!(reach > 0 && std::isfinite(reach) &&
                  index.neighbours_within(i, reach * (1 + 1e-9), k, expected[i], true)))
                index.neighbours_of(i, k, expected[i]);
        }
        for (const int threads : {1, 2, 8}) {
            NeighbourReach reach;
            reach.begin_round(ordered.size(), k);
            std::vector<std::vector<Neighbour>> found(ordered.size());
            parallel_for(Execution{threads, nullptr}, ordered.size(), [&](std::size_t i) {
                reach.neighbours(index, std::uint32_t(i), found[i]);
            });
            for (std::uint32_t i = 0; i < ordered.size(); ++i)
                ASSERT_EQ(indices_in_order(found[i]), indices_in_order(expected[i]))
                    << "k " << k << " threads " << threads << " point " << i;
        }
    }
}

// Point 2 has exactly k copies at 0 and the next point far: without a guess its k-th distance
// is 0 and its neighbours come sorted by index; the guess the point before leaves must not give
// them in the walk's order instead (vcglib's split can reverse copies in a leaf).
TEST(NeighbourReach, CopiesAtTheKthDistanceComeAsWithoutAGuess) {
    const std::vector<Vec3> points{{10, 0, 0}, {11, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    const KnnIndex index(points);
    std::vector<Neighbour> expected, found;
    index.neighbours_of(2, 2, expected);
    NeighbourReach reach;
    reach.begin_round(points.size(), 2);
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        reach.neighbours(index, i, found);
        if (i != 2) continue;
        ASSERT_EQ(found.size(), 2U);
        EXPECT_EQ(indices_in_order(found), indices_in_order(expected));
    }
}

TEST(Knn, WithinGivesUpPastWhatItMayGather) {
    const std::vector<Vec3> points = grid_duplicates_and_sphere();
    const KnnIndex index(points);
    std::vector<Neighbour> found;
    const std::uint32_t on_sphere = 200; // no ties
    EXPECT_TRUE(index.neighbours_within(on_sphere, 1e6, 10, found));
    EXPECT_EQ(found.size(), 10U);
    EXPECT_FALSE(index.neighbours_within(on_sphere, 1e6, 10, found, false, 50));
    // Every other point lies within the radius: gathering them all is allowed, one fewer not.
    EXPECT_TRUE(index.neighbours_within(on_sphere, 1e6, 10, found, false, points.size() - 1));
    EXPECT_FALSE(index.neighbours_within(on_sphere, 1e6, 10, found, false, points.size() - 2));
}

TEST(NeighbourGraph, SymmetricUnionIsSymmetricSortedAndLoopFree) {
    const PointSet s = testing::sample_torus(3000);
    const KnnIndex index(s.positions);
    const KnnTable table = knn_table(index, 10, {});
    const CsrGraph g = symmetric_union(table, s.size(), {});
    ASSERT_EQ(g.size(), s.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
        EXPECT_GE(g.degree(i), 10u);
        EXPECT_TRUE(std::is_sorted(g.begin(i), g.end(i)));
        EXPECT_EQ(std::adjacent_find(g.begin(i), g.end(i)), g.end(i)); // no repeats
        for (const std::uint32_t* j = g.begin(i); j != g.end(i); ++j) {
            EXPECT_NE(*j, i);
            EXPECT_TRUE(std::binary_search(g.begin(*j), g.end(*j), std::uint32_t(i)));
        }
        for (int j = 0; j < table.k; ++j) // every kNN relation is an edge
            EXPECT_TRUE(std::binary_search(g.begin(i), g.end(i), table.row(i)[j]));
    }
}

// Exactly the union, not just a symmetric superset: rows with repeats, self loops, empty rows,
// one-sided and mutual relations, against a set-based union, with 1 and 2 threads, with and
// without room in the input's buffer.
TEST(NeighbourGraph, SymmetricUnionOfAnyRelationIsExactlyTheUnion) {
    const std::size_t n = 500;
    std::mt19937 random(3);
    std::uniform_int_distribution<std::uint32_t> target(0, n - 1), length(0, 12);
    CsrGraph directed;
    std::vector<std::set<std::uint32_t>> expected(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        // A few rows longer than the ones sorted by rank (128 entries), and one point that many
        // rows name (more than 128 entries added to its row).
        const std::uint32_t d = i % 50 == 0 ? 0 : i % 97 == 1 ? 200 : length(random);
        for (std::uint32_t e = 0; e < d; ++e) {
            // Mostly near i (many mutual pairs), sometimes anywhere, sometimes i itself.
            std::uint32_t j = e % 5 == 4 ? target(random) : (i + target(random) % 7) % n;
            if (e % 11 == 10) j = i;
            if (e == 0 && i % 2 == 0 && i > 20) j = 7;
            directed.adjacency.push_back(j);
            if (e % 3 == 0) directed.adjacency.push_back(j); // a repeat
            if (j == i) continue;
            expected[i].insert(j);
            expected[j].insert(i);
        }
        directed.offsets.push_back(directed.adjacency.size());
    }
    // The same relation without repeats or self loops: its union is larger than it, so without
    // room the second-array path must run, with room the in-place one.
    CsrGraph plain;
    for (std::uint32_t i = 0; i < n; ++i) {
        std::set<std::uint32_t> row(directed.begin(i), directed.end(i));
        row.erase(i);
        plain.adjacency.insert(plain.adjacency.end(), row.begin(), row.end());
        plain.offsets.push_back(plain.adjacency.size());
    }
    for (int threads : {1, 2})
        for (const CsrGraph* relation : {&directed, &plain})
            for (bool room : {false, true}) {
                CsrGraph input = *relation;
                input.adjacency.shrink_to_fit();
                if (room) input.adjacency.reserve(2 * input.adjacency.size());
                const std::uint32_t* buffer = input.adjacency.data();
                const CsrGraph g = symmetric_union(std::move(input), Execution{threads, nullptr});
                const std::string context = std::string(relation == &plain ? "plain" : "repeats") +
                                            ", " + std::to_string(threads) + " threads, room " +
                                            std::to_string(room);
                if (relation == &plain) {
                    EXPECT_EQ(g.adjacency.data() == buffer, room) << "path, " << context;
                }
                ASSERT_EQ(g.size(), n);
                for (std::uint32_t i = 0; i < n; ++i)
                    EXPECT_EQ(std::vector<std::uint32_t>(g.begin(i), g.end(i)),
                              std::vector<std::uint32_t>(expected[i].begin(), expected[i].end()))
                        << "row " << i << ", " << context;
            }
}

// Two trees hold the same splits and leaves (the same slots) whatever their nodes' numbers.
void expect_same_structure(KdTreeWithSlots& a, std::size_t na, KdTreeWithSlots& b, std::size_t nb) {
    const auto &x = a._getNodes()[na], &y = b._getNodes()[nb];
    ASSERT_EQ(x.leaf, y.leaf);
    if (x.leaf) {
        ASSERT_EQ(x.start, y.start);
        ASSERT_EQ(x.size, y.size); // vcglib's 16 bits, truncated alike
        return;
    }
    ASSERT_EQ(x.dim, y.dim);
    ASSERT_EQ(x.splitValue, y.splitValue);
    expect_same_structure(a, x.firstChildId, b, y.firstChildId);
    expect_same_structure(a, x.firstChildId + 1, b, y.firstChildId + 1);
}

TEST(KnnTree, BuiltByLevelsInParallelIsVcglibsTree) {
    ASSERT_TRUE(KdTreeWithSlots::builds_by_levels()); // this vcglib's build can be split
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<std::vector<Vec3>> clouds(5);
    for (int i = 0; i < 150000; ++i)
        clouds[0].emplace_back(unit(random), unit(random), unit(random));
    // 50,000 copies of one point (splits with an empty side; a leaf of 65,536 copies or more,
    // whose size vcglib's 16 bits cannot hold, is built again: see the next test).
    clouds[1] = clouds[0];
    clouds[1].resize(100000);
    clouds[1].insert(clouds[1].end(), 50000, Vec3(0.5, 0.25, 0.75));
    std::shuffle(clouds[1].begin(), clouds[1].end(), random);
    // Flat and on a line: boxes without extent along some axes; a dense cluster in a sparse
    // cloud (unequal subtrees).
    for (int i = 0; i < 120000; ++i) clouds[2].emplace_back(unit(random), 0.5, unit(random) * 3);
    for (int i = 0; i < 100000; ++i)
        clouds[3].emplace_back(i % 7 == 0 ? unit(random) : 0.5 + unit(random) * 1e-4,
                               i % 7 == 0 ? unit(random) : 0.5, i % 7 == 0 ? unit(random) : 0.5);
    // A cube's corners and 60,000 copies of one point: the copies alone in a node at depth 5,
    // whose split leaves one side empty, where the top levels stop (6,000 copies of another
    // point in the other half make it a cloud built by levels).
    for (int c = 0; c < 8; ++c) clouds[4].emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    clouds[4].insert(clouds[4].end(), 60000, Vec3(0.25, 0.25, 0.25));
    clouds[4].insert(clouds[4].end(), 6000, Vec3(0.75, 0.75, 0.75));
    for (const std::vector<Vec3>& p : clouds) {
        KdTreeWithSlots vcglib(vcg::ConstDataWrapper<Vec3>(p.data(), int(p.size())),
                               kPointsPerLeaf);
        for (int threads : {2, 8}) {
            KdTreeWithSlots ours(p, Execution{threads, nullptr});
            // Built by levels: on the uniform cloud the root's right child's children come
            // before the left subtree's deep nodes, unlike in vcglib's depth-first numbering.
            if (&p == &clouds[0]) {
                EXPECT_LT(ours._getNodes()[2].firstChildId, vcglib._getNodes()[2].firstChildId);
            }
            ASSERT_EQ(ours._getNodes().size(), vcglib._getNodes().size());
            EXPECT_EQ(ours._getNumLevel(), vcglib._getNumLevel());
            EXPECT_EQ(ours._getAABBox().min, vcglib._getAABBox().min);
            EXPECT_EQ(ours._getAABBox().max, vcglib._getAABBox().max);
            EXPECT_TRUE(ours._getPoints() == vcglib._getPoints());
            EXPECT_TRUE(ours.slot_points() == vcglib.slot_points());
            expect_same_structure(ours, 0, vcglib, 0);
        }
        // And the queries agree with the index built on one thread.
        const KnnIndex one(p), two(p, Execution{2, nullptr});
        std::vector<Neighbour> a, b;
        for (std::uint32_t q = 0; q < p.size(); q += 997) {
            one.neighbours_of(q, 20, a);
            two.neighbours_of(q, 20, b);
            ASSERT_EQ(a.size(), b.size());
            for (std::size_t e = 0; e < a.size(); ++e) EXPECT_EQ(a[e].index, b[e].index);
        }
    }
}

// Every query of `index` over `p` answers as a brute-force search does (distances; the
// neighbours themselves wherever the k-th distance is not tied).
void expect_queries_answer_as_brute_force(const std::vector<Vec3>& p, const KnnIndex& index,
                                          const std::vector<std::uint32_t>& queries) {
    std::vector<Neighbour> found;
    for (std::uint32_t q : queries) {
        std::vector<double> all;
        for (std::uint32_t i = 0; i < p.size(); ++i)
            if (i != q) all.push_back((p[i] - p[q]).SquaredNorm());
        std::sort(all.begin(), all.end());
        index.neighbours_of(q, 12, found);
        ASSERT_EQ(found.size(), 12U) << q;
        std::set<std::uint32_t> distinct;
        for (std::size_t e = 0; e < found.size(); ++e) {
            EXPECT_NE(found[e].index, q);
            ASSERT_LT(found[e].index, p.size());
            distinct.insert(found[e].index);
            EXPECT_EQ(found[e].squared_distance, all[e]) << q << " " << e;
        }
        EXPECT_EQ(distinct.size(), 12U);
        index.nearest(p[q], 1, found);
        ASSERT_EQ(found.size(), 1U);
        EXPECT_EQ(found[0].squared_distance, 0.0);
    }
}

TEST(KnnTree, CopiesAtACoordinateNoFloatHoldsAreFoundByEveryQuery) {
    // vcglib's split compares with its split value in float: 0.3 rounds up, so every copy lies
    // below it and vcglib's split reads past the node, into the next one's points; its tree
    // then has leaves that overlap and queries that read past its arrays (`hrsr check` of a
    // mesh with 100 unwelded copies of a vertex crashed). The tree is built again without it.
    // Also 70,000 copies at 0.25 (a float): a leaf vcglib's 16 bits of size cannot hold.
    for (const auto& [copies, at] : {std::pair<std::size_t, double>{100, 0.3},
                                     {70000, 0.3},
                                     {70000, 0.25}}) { // vcglib's build, the build by levels
        std::vector<Vec3> p;
        for (int c = 0; c < 8; ++c) p.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        p.insert(p.end(), copies, Vec3(at, at, at));
        for (int i = 0; i < 40; ++i) p.emplace_back(0.1 * i, 0.7, 0.2);
        KdTreeWithSlots one(p, Execution{1, nullptr});
        for (int threads : {2, 8}) {
            KdTreeWithSlots more(p, Execution{threads, nullptr});
            ASSERT_EQ(more._getNodes().size(), one._getNodes().size());
            EXPECT_TRUE(more.slot_points() == one.slot_points());
            expect_same_structure(more, 0, one, 0);
        }
        const KnnIndex index(p, Execution{2, nullptr});
        expect_queries_answer_as_brute_force(
            p, index, {0, 3, 7, 8, 9, std::uint32_t(8 + copies / 2), std::uint32_t(p.size() - 1)});
    }
}

TEST(DisjointSets, UnitesAndFinds) {
    DisjointSets d(6);
    EXPECT_TRUE(d.unite(0, 1));
    EXPECT_TRUE(d.unite(2, 3));
    EXPECT_FALSE(d.unite(1, 0));
    EXPECT_TRUE(d.unite(1, 3));
    EXPECT_EQ(d.find(0), d.find(2));
    EXPECT_NE(d.find(4), d.find(0));
    EXPECT_NE(d.find(4), d.find(5));
}

} // namespace
} // namespace hrsr
