#include "rsr/ear_triangulation.h"

#include "geometry.h"
#include "rsr/face_split.h"

#include <queue>
#include <tuple>

namespace hrsr::rsr {

namespace {

struct Ear {
    double score;
    std::uint32_t i, u, w; ///< apex i, cut edge {u, w}
    bool operator>(const Ear& o) const {
        return std::tie(score, i, u, w) > std::tie(o.score, o.i, o.u, o.w);
    }
};

class EarCutter {
public:
    EarCutter(Embedding& embedding, const ComponentCloud& cloud,
              const std::vector<double>& max_length, DistanceMode mode)
        : embedding_(embedding), rs_(embedding.rotation), faces_(embedding.faces), cloud_(cloud),
          max_length_(max_length), mode_(mode) {}

    // Pushes every ear with apex i whose cut is short enough.
    void explore(std::uint32_t i) {
        for (std::uint32_t j = 0; j < rs_.degree(i); ++j) {
            const std::uint32_t u = rs_.dart(i, j).to, w = rs_.dart(i, rs_.next(i, j)).to;
            if (u == w || rs_.adjacent(u, w)) continue;
            if (ccw_angle(rs_.dart(i, j).angle, rs_.dart(i, rs_.next(i, j)).angle) >= M_PI)
                continue;
            const double score = edge_length(mode_, cloud_.smoothed[u], cloud_.smoothed[w],
                                             cloud_.normals[u], cloud_.normals[w]);
            if (score <= max_length_[u] && score <= max_length_[w]) queue_.push({score, i, u, w});
        }
    }

    // Pops ears until none is left; returns the vertices whose neighbourhood changed.
    bool cut_next(std::uint32_t& u, std::uint32_t& w) {
        while (!queue_.empty()) {
            const Ear ear = queue_.top();
            queue_.pop();
            if (!valid(ear)) continue;
            cut(ear);
            u = ear.u;
            w = ear.w;
            return true;
        }
        return false;
    }

    EarStats stats;

private:
    bool valid(const Ear& e) const {
        const std::uint32_t iu = rs_.find(e.i, e.u);
        if (rs_.adjacent(e.u, e.w) || iu == kNotFound || rs_.dart(e.i, rs_.next(e.i, iu)).to != e.w)
            return false;
        if (triangles_on_edge(rs_, e.i, e.u) >= 2 || triangles_on_edge(rs_, e.i, e.w) >= 2)
            return false;
        if (ccw_angle(rs_.angle(e.i, e.u), rs_.angle(e.i, e.w)) > M_PI) return false;
        // D-12, the specific side: at u, i is just counter-clockwise of w; at w, i is just
        // clockwise of u. Then the edge {u, w} stays inside the face being triangulated.
        if (rs_.successor_as_if_inserted(e.u, e.w) != e.i) return false;
        if (rs_.dart(e.w, rs_.wedge(e.w, e.u)).to != e.i) return false;
        if (ccw_angle(rs_.angle(e.u, e.w), rs_.angle(e.u, e.i)) >= M_PI) return false;
        if (ccw_angle(rs_.angle(e.w, e.i), rs_.angle(e.w, e.u)) >= M_PI) return false;
        return faces_.face_of_wedge(e.u, e.w) ==
               faces_.face_of_wedge(e.w, e.u); // a split, never a merge
    }

    void cut(const Ear& e) {
        const auto [d1, d2] = rs_.insert_edge(e.u, e.w);
        faces_.split(d1, d2);
        embedding_.record_triangle(e.i, e.u, e.w);
        ++stats.ears;
        std::size_t recorded = 1;
        // The far side of the new edge may already be a triangle (x, w, u): close it too, in
        // increasing id order, if it is a face of the rotation and its edges have room (D-10).
        std::vector<std::uint32_t> common;
        for (const Dart& d : rs_.darts(e.u))
            if (d.to != e.i && rs_.adjacent(e.w, d.to)) common.push_back(d.to);
        std::sort(common.begin(), common.end());
        for (std::uint32_t x : common) {
            if (triangles_on_edge(rs_, x, e.u) >= 2 || triangles_on_edge(rs_, x, e.w) >= 2 ||
                triangles_on_edge(rs_, e.u, e.w) >= 2)
                continue;
            // (x, w, u) is a face when each corner follows on: succ_w(u) = x, succ_u(x) = w and
            // succ_x(w) = u. The spec names the first two; without the third a 3-cycle that is
            // not a face was recorded (one wrongly wound triangle in the coarse bunny at p = 0.5).
            const std::uint32_t wu = rs_.find(e.w, e.u), ux = rs_.find(e.u, x),
                                xw = rs_.find(x, e.w);
            if (rs_.dart(e.w, rs_.next(e.w, wu)).to != x ||
                rs_.dart(e.u, rs_.next(e.u, ux)).to != e.w ||
                rs_.dart(x, rs_.next(x, xw)).to != e.u)
                continue;
            embedding_.record_triangle(x, e.w, e.u);
            ++stats.closing_triangles;
            ++recorded;
        }
        embedding_.edge_inserted(Phase::Ears, e.u, e.w, recorded);
    }

    Embedding& embedding_;
    RotationSystem& rs_;
    Faces& faces_;
    const ComponentCloud& cloud_;
    const std::vector<double>& max_length_;
    DistanceMode mode_;
    std::priority_queue<Ear, std::vector<Ear>, std::greater<Ear>> queue_;
};

} // namespace

EarStats triangulate_ears(Embedding& embedding, const ComponentCloud& cloud,
                          const std::vector<double>& max_length, DistanceMode mode,
                          const std::vector<std::uint32_t>& roots) {
    EarCutter cutter(embedding, cloud, max_length, mode);
    const std::size_t n = embedding.rotation.vertex_count();
    std::vector<std::uint8_t> to_visit(n, 1);
    for (std::uint32_t r : roots) {
        to_visit[r] = 0;
        cutter.explore(r);
    }
    std::uint32_t cursor = 0; // smallest vertex that may still be unvisited
    for (;;) {
        std::uint32_t u, w;
        while (cutter.cut_next(u, w)) {
            to_visit[u] = to_visit[w] = 0;
            cutter.explore(u);
            cutter.explore(w);
        }
        while (cursor < n && !to_visit[cursor]) ++cursor;
        if (cursor == n) break;
        to_visit[cursor] = 0;
        cutter.explore(cursor);
    }
    return cutter.stats;
}

} // namespace hrsr::rsr
