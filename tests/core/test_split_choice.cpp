// The split pair of §8.4 against the energy written out pair by pair: choose_split scores each
// pair from per-split tables of ranges (D-19), which must add up to the same E = E_D + E_A.
#include "hrsr/split_choice.h"
#include "mesh/split_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

namespace hrsr::reexpand {
namespace {

using Corners = std::array<Vec3, 3>;

Vec3 unit_normal(const Corners& t) {
    const Vec3 n = (t[1] - t[0]) ^ (t[2] - t[0]);
    return n.Norm() > 0 ? n / n.Norm() : Vec3(0, 0, 0);
}

// E_A's term: the penalty under 3°, else w · shortest edge · |π/3 − smallest angle|.
double min_angle_term(const Corners& t) {
    double smallest = M_PI, shortest = 1e300;
    for (int k = 0; k < 3; ++k) {
        const Vec3 u = t[(k + 1) % 3] - t[k], v = t[(k + 2) % 3] - t[k];
        shortest = std::min(shortest, u.Norm());
        const double c = u.Norm() > 0 && v.Norm() > 0
                             ? std::clamp(u.dot(v) / (u.Norm() * v.Norm()), -1.0, 1.0)
                             : 1.0;
        smallest = std::min(smallest, std::acos(c));
    }
    if (smallest < constants::kMinAngleThresholdDegrees * M_PI / 180.0)
        return constants::kMinAnglePenalty;
    return constants::kMinAngleWeight * shortest * std::abs(M_PI / 3.0 - smallest);
}

struct Reference {
    double energy = 0, worst = 0;
    void triangle(const Corners& t) { energy += min_angle_term(t); }
    void joint(const Corners& a, const Corners& b, double length) {
        const double c = unit_normal(a).dot(unit_normal(b));
        energy += (c - 1) * (c - 1) * std::max(length, 1e-8);
        worst = std::max(worst, 1 - c);
    }
    // A chain of triangles, consecutive ones sharing an edge of the given length; a missing
    // triangle (the boundary gap) breaks it.
    void chain(const std::vector<std::optional<Corners>>& ts, const std::vector<double>& shared) {
        for (std::size_t k = 0; k < ts.size(); ++k) {
            if (!ts[k]) continue;
            triangle(*ts[k]);
            if (k > 0 && ts[k - 1]) joint(*ts[k - 1], *ts[k], shared[k - 1]);
        }
    }
};

// Pair (i, j): the new vertex takes the wedges from spoke j counter-clockwise to spoke i, with
// new triangles (p_new, p_old, q_j) and (p_old, p_new, q_i) at the ends of both chains.
Reference score_by_walking(const Vec3& p_old, const Vec3& p_new, const std::vector<Vec3>& q,
                           const std::vector<bool>& face, std::size_t i, std::size_t j) {
    const std::size_t d = q.size();
    const Corners out{p_new, p_old, q[j]}, in{p_old, p_new, q[i]};
    auto side = [&](const Vec3& centre, std::size_t from, std::size_t to, const Corners& first,
                    const Corners& last) {
        std::vector<std::optional<Corners>> ts{first};
        std::vector<double> shared;
        for (std::size_t w = from; w != to; w = (w + 1) % d) {
            shared.push_back((q[w] - centre).Norm());
            ts.push_back(face[w] ? std::optional<Corners>(Corners{centre, q[w], q[(w + 1) % d]})
                                 : std::nullopt);
        }
        shared.push_back((q[to] - centre).Norm());
        ts.push_back(last);
        return std::make_pair(ts, shared);
    };
    Reference r;
    r.joint(in, out, (p_new - p_old).Norm());
    // The new triangles' own terms once; the chains then add only their wedges and joints.
    r.triangle(out);
    r.triangle(in);
    for (const auto& [ts, shared] : {side(p_new, j, i, out, in), side(p_old, i, j, in, out)}) {
        Reference inner;
        inner.chain(ts, shared);
        r.energy += inner.energy - min_angle_term(*ts.front()) - min_angle_term(*ts.back());
        r.worst = std::max(r.worst, inner.worst);
    }
    return r;
}

// A fan of d triangles around vertex 0, wavy out of its plane, with wedge `gap` left out when
// `open` (vertex 0 is then on the border).
struct FanFixture {
    std::vector<Vec3> positions{Vec3(0, 0, 0)};
    std::vector<Triangle> triangles;
};

FanFixture wavy_fan(std::size_t d, bool open, std::size_t gap, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> jitter(-0.3, 0.3), radius(0.6, 1.4);
    FanFixture f;
    for (std::size_t k = 0; k < d; ++k) {
        const double a = (double(k) + 0.4 * jitter(rng)) * 2 * M_PI / double(d);
        const double r = radius(rng);
        f.positions.emplace_back(r * std::cos(a), r * std::sin(a), jitter(rng));
    }
    for (std::uint32_t k = 0; k < d; ++k)
        if (!open || k != gap) f.triangles.push_back({0, 1 + k, 1 + std::uint32_t((k + 1) % d)});
    return f;
}

TEST(SplitChoice, ChoosesThePairOfLeastEnergyWrittenOutPairByPair) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> offset(-0.25, 0.25);
    std::size_t compared = 0, open_fans = 0;
    for (int round = 0; round < 400; ++round) {
        const std::size_t d = 3 + std::size_t(round % 10);
        const bool open = round % 3 == 0;
        const std::size_t gap = std::size_t(round) % d;
        const FanFixture f = wavy_fan(d, open, gap, rng);
        const SplitMesh mesh(f.positions, f.triangles, 64, 64);
        const Star star = mesh.star(0);
        ASSERT_EQ(star.neighbours.size(), d);
        std::vector<Vec3> q;
        std::vector<bool> face;
        for (std::size_t k = 0; k < d; ++k) {
            q.push_back(mesh.position(star.neighbours[k]));
            face.push_back(star.wedges[k] != nullptr);
        }
        // The new vertex across from the gap, so that no border split (D-34) is a candidate.
        Vec3 p_new(offset(rng), offset(rng), offset(rng));
        if (open) {
            const Vec3 middle = (q[gap] + q[(gap + 1) % d]) / 2;
            const Vec3 away(-middle[0], -middle[1], 0);
            p_new = away / away.Norm() * 0.2 + Vec3(0, 0, offset(rng));
            ++open_fans;
        }
        const Vec3 p_old = mesh.position(0);
        // The reference's choice: least energy among pairs under the dihedral guard, if any;
        // ties to the first pair in star order.
        std::optional<std::pair<std::size_t, std::size_t>> best, best_guarded;
        double best_energy = 0, best_guarded_energy = 0;
        for (std::size_t i = 0; i < d; ++i)
            for (std::size_t j = 0; j < d; ++j) {
                if (i == j) continue;
                const Reference r = score_by_walking(p_old, p_new, q, face, i, j);
                if (!best || r.energy < best_energy) {
                    best = {i, j};
                    best_energy = r.energy;
                }
                if (r.worst < constants::kDihedralGuard &&
                    (!best_guarded || r.energy < best_guarded_energy)) {
                    best_guarded = {i, j};
                    best_guarded_energy = r.energy;
                }
            }
        const auto [i, j] = best_guarded ? *best_guarded : *best;
        const double energy = best_guarded ? best_guarded_energy : best_energy;
        const SplitChoice choice = choose_split(mesh, 0, star, p_old, p_new);
        ASSERT_TRUE(choice.found);
        EXPECT_EQ(choice.omit, SplitMesh::BorderSplit::None) << round;
        EXPECT_EQ(choice.a, star.neighbours[i]) << round;
        EXPECT_EQ(choice.b, star.neighbours[j]) << round;
        EXPECT_NEAR(choice.energy, energy, 1e-12 * std::max(1.0, energy)) << round;
        ++compared;
    }
    EXPECT_EQ(compared, 400u);
    EXPECT_GT(open_fans, 100u);
}

} // namespace
} // namespace hrsr::reexpand
