#include "hrsr/split_choice.h"

#include "geometry.h"
#include "mesh/small_holes_fill.h"

#include <algorithm>
#include <cmath>

namespace hrsr::reexpand {

namespace {

struct Tri {
    Vec3 p[3];
    Vec3 normal() const {
        const Vec3 n = (p[1] - p[0]) ^ (p[2] - p[0]);
        const double length = n.Norm();
        return length > 0 ? n / length : Vec3(0, 0, 0); // degenerate: zero normal, no NaN
    }
};

// f(t) of E_A: the penalty below the threshold, else w · shortest edge · |π/3 − smallest angle|.
// acos is decreasing, so the smallest angle is the acos of the largest cosine: one acos per
// triangle instead of three (the profile's top entry), with the very same value.
double angle_term(const Tri& t) {
    double max_cos = -1, min_edge = 1e300;
    for (int k = 0; k < 3; ++k) {
        const Vec3 u = t.p[(k + 1) % 3] - t.p[k], v = t.p[(k + 2) % 3] - t.p[k];
        const double nu = u.Norm(), nv = v.Norm();
        min_edge = std::min(min_edge, nu);
        // A zero-length side makes the angle 0 (cosine 1). D-18: the true smallest angle.
        const double c = (nu > 0 && nv > 0) ? std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0) : 1.0;
        max_cos = std::max(max_cos, c);
    }
    const double min_angle = std::acos(max_cos);
    if (min_angle < constants::kMinAngleThresholdDegrees * M_PI / 180.0)
        return constants::kMinAnglePenalty;
    return constants::kMinAngleWeight * min_edge * std::abs(M_PI / 3.0 - min_angle);
}

struct Score {
    double energy = 0;
    double worst_dihedral = 0; ///< max of 1 − n_t · n_t' over adjacent pairs
};

// E_D's term for two adjacent triangles with unit normals nt, nu sharing an edge of `length`.
struct Joint {
    double energy = 0, dihedral = 0;
    Joint() = default;
    Joint(const Vec3& nt, const Vec3& nu, double length) {
        const double c = nt.dot(nu);
        energy = (c - 1) * (c - 1) * length;
        dihedral = 1 - c;
    }
};

// The wedge triangles (centre, q_k, q_k+1) of one side do not depend on the pair being scored:
// their normals, min-angle terms, spoke lengths and the joints between consecutive wedges are
// computed once per split, not once per pair.
struct Fan {
    std::vector<Vec3> normal;
    std::vector<double> angle;
    std::vector<double> spoke_length; ///< |q_k − centre|, at least 1e-8 (D-2 units)
    std::vector<Joint> joint;         ///< at spoke k: wedges k−1 and k, when both are faces
    // Refills the vectors (their storage is reused: one Fan per side per thread).
    void assign(const Vec3& centre, const std::vector<Vec3>& q, const std::vector<SFace*>& wedges) {
        normal.clear();
        angle.clear();
        spoke_length.clear();
        joint.clear();
        const std::size_t d = q.size();
        for (std::size_t w = 0; w < d; ++w) {
            const Tri t{{centre, q[w], q[(w + 1) % d]}};
            normal.push_back(wedges[w] ? t.normal() : Vec3(0, 0, 0));
            angle.push_back(wedges[w] ? angle_term(t) : 0.0);
            spoke_length.push_back(std::max((q[w] - centre).Norm(), 1e-8));
        }
        joint.resize(d);
        for (std::size_t w = 0; w < d; ++w) {
            const std::size_t before = (w + d - 1) % d;
            if (wedges[w] && wedges[before])
                joint[w] = Joint(normal[before], normal[w], spoke_length[w]);
        }
    }
};

// The two new triangles (c', c, q_j) and (c, c', q_i) depend on one spoke each: their normals
// and min-angle terms are computed once per spoke, not once per pair. At one spoke the two are
// the same corners in the other turn: the same sides, and at each corner the same two side
// vectors (their dot product and lengths commute exactly), so one min-angle term serves both.
struct NewTriangles {
    std::vector<Vec3> out_normal, in_normal;
    std::vector<double> angle;
    void assign(const Vec3& p_old, const Vec3& p_new, const std::vector<Vec3>& q) {
        out_normal.clear();
        in_normal.clear();
        angle.clear();
        for (const Vec3& spoke : q) {
            const Tri t_out{{p_new, p_old, spoke}}, t_in{{p_old, p_new, spoke}};
            out_normal.push_back(t_out.normal());
            in_normal.push_back(t_in.normal());
            angle.push_back(angle_term(t_out));
        }
    }
};

// A fan's wedges from spoke `from` counter-clockwise up to spoke `to` (not included), for every
// such range at once: the sum of their min-angle terms and of the joints between consecutive
// wedges of the range, and the worst of those joints. A gap (a wedge that is no face) adds no
// term, and its joints were never made (Fan::joint), so no adjacency is scored across it.
struct FanRanges {
    std::size_t d = 0;
    std::vector<double> energy, worst; ///< [from · d + to]

    void assign(const Fan& fan, const std::vector<SFace*>& wedges) {
        d = wedges.size();
        energy.assign(d * d, 0);
        worst.assign(d * d, 0);
        for (std::size_t from = 0; from < d; ++from) {
            double e = 0, m = 0;
            // w runs from `from` round the fan; no division (the profile's top lines).
            for (std::size_t length = 1, w = from; length < d; ++length) {
                if (wedges[w]) e += fan.angle[w];
                if (length > 1) { // the joint with the wedge before, inside the range
                    e += fan.joint[w].energy;
                    m = std::max(m, fan.joint[w].dihedral);
                }
                w = w + 1 == d ? 0 : w + 1;
                energy[from * d + w] = e;
                worst[from * d + w] = m;
            }
        }
    }
};

// Everything a pair's score reads that does not depend on the pair: built once per split, so
// that a pair costs a few look-ups (D-19: the d(d − 1) pairs each walked all d wedges before).
struct SplitTerms {
    const std::vector<SFace*>* wedges = nullptr; ///< the star's: null where a wedge is no face
    Fan new_fan, old_fan;                        ///< wedges around p_new and around p_old
    NewTriangles spokes;
    double new_edge = 0; ///< |p_new − p_old| (at least 1e-8): the edge the new triangles share
    FanRanges new_ranges, old_ranges;
    // The joints at the ends of each side's chain, between a new triangle and the first or last
    // wedge of the side: per spoke, not per pair. Where that wedge is no face the joint is left
    // at zero energy and zero dihedral, which adds nothing to a score.
    std::vector<Joint> new_first, new_last, old_first, old_last;

    // Refills the terms (their storage is reused: one per thread).
    void assign(const Vec3& p_old, const Vec3& p_new, const std::vector<Vec3>& q,
                const std::vector<SFace*>& star_wedges) {
        wedges = &star_wedges;
        new_fan.assign(p_new, q, star_wedges);
        old_fan.assign(p_old, q, star_wedges);
        spokes.assign(p_old, p_new, q);
        new_edge = std::max((p_new - p_old).Norm(), 1e-8);
        new_ranges.assign(new_fan, star_wedges);
        old_ranges.assign(old_fan, star_wedges);
        const std::size_t d = q.size();
        for (auto* joints : {&new_first, &new_last, &old_first, &old_last}) joints->assign(d, {});
        for (std::size_t k = 0; k < d; ++k) {
            const std::size_t before = (k + d - 1) % d;
            if (star_wedges[k]) { // wedge k starts a side at spoke k
                new_first[k] =
                    Joint(spokes.out_normal[k], new_fan.normal[k], new_fan.spoke_length[k]);
                old_first[k] =
                    Joint(spokes.in_normal[k], old_fan.normal[k], old_fan.spoke_length[k]);
            }
            if (star_wedges[before]) { // wedge k − 1 ends a side at spoke k
                new_last[k] =
                    Joint(new_fan.normal[before], spokes.in_normal[k], new_fan.spoke_length[k]);
                old_last[k] =
                    Joint(old_fan.normal[before], spokes.out_normal[k], old_fan.spoke_length[k]);
            }
        }
    }

    // Chains of triangles around the two split vertices; consecutive ones share a spoke. h_in
    // comes from spoke i, h_out goes to spoke j: the new vertex keeps the wedges from j to i, c
    // those from i to j. A border split (D-34) leaves out one of the new triangles, and its
    // terms.
    Score score(std::size_t i, std::size_t j,
                SplitMesh::BorderSplit omit = SplitMesh::BorderSplit::None) const {
        const std::size_t d = wedges->size();
        const bool with_out = omit != SplitMesh::BorderSplit::Out;
        const bool with_in = omit != SplitMesh::BorderSplit::In;
        Score s;
        auto add = [&](const Joint& joint) {
            s.energy += joint.energy;
            s.worst_dihedral = std::max(s.worst_dihedral, joint.dihedral);
        };
        if (with_out) s.energy += spokes.angle[j];
        if (with_in) s.energy += spokes.angle[i];
        if (with_in && with_out) // D-18: the true shared edge
            add(Joint(spokes.in_normal[i], spokes.out_normal[j], new_edge));
        s.energy += new_ranges.energy[j * d + i] + old_ranges.energy[i * d + j];
        s.worst_dihedral =
            std::max({s.worst_dihedral, new_ranges.worst[j * d + i], old_ranges.worst[i * d + j]});
        if (with_out) add(new_first[j]);
        if (with_in) add(new_last[i]);
        if (with_in) add(old_first[i]);
        if (with_out) add(old_last[j]);
        return s;
    }
};

// D-34: where the new vertex lies in c's boundary gap (seen from c in the plane of c's fan), a
// border split may put it on the border: next to the spoke after the gap (`Out`) when it is
// nearer that spoke's side of the gap, next to the spoke before it (`In`) otherwise.
SplitMesh::BorderSplit border_side(const Star& star, const std::vector<Vec3>& q, const Vec3& p_old,
                                   const Vec3& p_new, const Vec3& fan_normal) {
    const std::size_t d = q.size();
    const double length = fan_normal.Norm();
    if (!star.boundary || length <= 0) return SplitMesh::BorderSplit::None;
    std::size_t gap = 0;
    while (gap < d && star.wedges[gap]) ++gap;
    if (gap == d) return SplitMesh::BorderSplit::None;
    const TangentFrame f = tangent_frame(fan_normal / length);
    const auto angle = [&](const Vec3& p) {
        const Vec3 e = p - p_old;
        return std::atan2(e.dot(f.t2), e.dot(f.t1));
    };
    const auto ccw = [](double from, double to) { // in [0, 2π)
        double a = to - from;
        while (a < 0) a += 2 * M_PI;
        while (a >= 2 * M_PI) a -= 2 * M_PI;
        return a;
    };
    const double start = angle(q[gap]);
    const double width = ccw(start, angle(q[(gap + 1) % d]));
    const double at = ccw(start, angle(p_new));
    if (at >= width) return SplitMesh::BorderSplit::None;
    return at >= 0.5 * width ? SplitMesh::BorderSplit::Out : SplitMesh::BorderSplit::In;
}

} // namespace

SplitChoice choose_split(const SplitMesh& mesh, std::uint32_t c, const Star& star,
                         const Vec3& p_old, const Vec3& p_new) {
    const std::size_t d = star.neighbours.size();
    SplitChoice best, best_guarded;
    if (d < 2) return best;
    // Scratch reused from split to split: no allocation per split (there were about fifty).
    thread_local std::vector<Vec3> q;
    thread_local SplitTerms terms;
    q.clear();
    for (std::uint32_t v : star.neighbours) q.push_back(mesh.position(v));
    terms.assign(p_old, p_new, q, star.wedges);
    Vec3 fan_normal(0, 0, 0);
    for (const Vec3& n : terms.old_fan.normal) fan_normal += n;
    auto consider = [&](std::size_t i, std::size_t j, SplitMesh::BorderSplit omit) {
        const Score s = terms.score(i, j, omit);
        const SplitChoice candidate{true, star.neighbours[i], star.neighbours[j], s.energy, omit};
        if (!best.found || s.energy < best.energy) best = candidate;
        if (s.worst_dihedral < constants::kDihedralGuard &&
            (!best_guarded.found || s.energy < best_guarded.energy))
            best_guarded = candidate;
    };
    using B = SplitMesh::BorderSplit;
    // The border walk only where a border split could be taken at all.
    B side = border_side(star, q, p_old, p_new, fan_normal);
    if (side != B::None && mesh.border_loop_edges(c, kMaxFilledLoop) <= kMaxFilledLoop)
        side = B::None;
    for (std::size_t i = 0; i < d; ++i)
        for (std::size_t j = 0; j < d; ++j) {
            if (i == j) continue;
            consider(i, j, B::None);
            if (side == B::Out && !star.wedges[(j + d - 1) % d]) consider(i, j, B::Out);
            if (side == B::In && !star.wedges[i]) consider(i, j, B::In);
        }
    // Dihedral guard: avoid a fold-back when some candidate has none.
    return best_guarded.found ? best_guarded : best;
}

} // namespace hrsr::reexpand
