#include "hrsr/border_notches.h"

#include "options.h"

#include <cmath>
#include <queue>
#include <unordered_map>
#include <utility>

namespace hrsr {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr std::uint32_t kMany = 0xfffffffeu;

// The border and the faces of the vertices on it (the only ones an ear touches).
class Notches {
public:
    Notches(std::vector<Triangle>& triangles, const std::vector<BorderEdge>& border,
            const std::vector<Vec3>& points,
            const IndexVector<VertexIndex, PointIndex>& vertex_point)
        : triangles_(triangles), points_(points), vertex_point_(vertex_point),
          before_(vertex_point.size(), kNone), after_(vertex_point.size(), kNone) {
        // Along a border edge a → b, b comes after a.
        for (const auto& [a, b] : border) {
            after_[a] = after_[a] == kNone ? b : kMany;
            before_[b] = before_[b] == kNone ? a : kMany;
        }
        for (std::uint32_t f = 0; f < triangles_.size(); ++f)
            for (std::uint32_t v : triangles_[f])
                if (after_[v] != kNone) faces_[v].push_back(f);
    }

    std::size_t close(double max_gap) {
        using Entry = std::pair<double, std::uint32_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
        const auto push = [&](std::uint32_t v) {
            double gap = 0;
            if (notch(v, max_gap, gap)) queue.emplace(gap, v);
        };
        for (std::uint32_t v = 0; v < after_.size(); ++v) push(v);
        std::size_t ears = 0;
        while (!queue.empty()) {
            const auto [gap, v] = queue.top();
            queue.pop();
            double now = 0;
            if (!notch(v, max_gap, now) || now != gap) continue; // changed since it was queued
            const std::uint32_t u = before_[v], w = after_[v];
            add({v, u, w});
            ++ears;
            after_[u] = w;
            before_[w] = u;
            before_[v] = after_[v] = kNone;
            push(u);
            push(w);
        }
        return ears;
    }

private:
    const Vec3& position(std::uint32_t v) const {
        return points_[vertex_point_[VertexIndex(v)].value()];
    }

    // visit(triangle, corner of v) for the faces of border vertex v.
    template <class Visit>
    void for_each_face(std::uint32_t v, Visit&& visit) const {
        const auto it = faces_.find(v);
        if (it == faces_.end()) return;
        for (std::uint32_t f : it->second) {
            const Triangle& t = triangles_[f];
            visit(t, t[0] == v ? 0u : t[1] == v ? 1u : 2u);
        }
    }

    bool has_directed(std::uint32_t a, std::uint32_t b) const {
        bool found = false;
        for_each_face(
            a, [&](const Triangle& t, std::uint32_t k) { found = found || t[(k + 1) % 3] == b; });
        return found;
    }

    Vec3 normal(const Triangle& t) const {
        const Vec3 n = (position(t[1]) - position(t[0])) ^ (position(t[2]) - position(t[0]));
        const double length = n.Norm();
        return length > 0 ? n / length : Vec3(0, 0, 0);
    }

    // The face holding the directed edge a → b.
    Vec3 normal_of_face_with(std::uint32_t a, std::uint32_t b) const {
        Vec3 n(0, 0, 0);
        for_each_face(a, [&](const Triangle& t, std::uint32_t k) {
            if (t[(k + 1) % 3] == b) n = normal(t);
        });
        return n;
    }

    // Whether v's border loop has at most kMinNotchedLoop vertices: ears never take a loop
    // below that, so a hole in the data never shrinks to what D-28 closes.
    bool short_loop(std::uint32_t v) const {
        std::uint32_t x = v;
        for (std::size_t n = 0; n < constants::kMinNotchedLoop; ++n) {
            x = after_[x];
            if (x == kNone || x == kMany) return false;
            if (x == v) return true;
        }
        return false;
    }

    // v lies in a notch that its ear can close; `gap`: the angle its faces leave open.
    bool notch(std::uint32_t v, double max_gap, double& gap) const {
        const std::uint32_t u = before_[v], w = after_[v];
        if (u == kNone || u == kMany || w == kNone || w == kMany || u == w) return false;
        double around = 0;
        for_each_face(v, [&](const Triangle& t, std::uint32_t k) {
            const Vec3 a = position(t[(k + 1) % 3]) - position(v),
                       b = position(t[(k + 2) % 3]) - position(v);
            around += std::atan2((a ^ b).Norm(), a.dot(b));
        });
        gap = 2 * M_PI - around;
        // u and w lie on the border, so their faces are listed: {u, w} is an edge if one has it.
        if (!(gap < max_gap) || has_directed(u, w) || has_directed(w, u) || short_loop(v))
            return false;
        // The ear (v, u, w) holds the reverses of the border edges u → v and v → w: it must
        // face as the two faces holding them do.
        const Vec3 ear = normal({v, u, w});
        return ear.dot(normal_of_face_with(u, v)) > 0 && ear.dot(normal_of_face_with(v, w)) > 0;
    }

    void add(const Triangle& t) {
        const std::uint32_t f = std::uint32_t(triangles_.size());
        triangles_.push_back(t);
        for (std::uint32_t v : t) faces_[v].push_back(f);
    }

    std::vector<Triangle>& triangles_;
    const std::vector<Vec3>& points_;
    const IndexVector<VertexIndex, PointIndex>& vertex_point_;
    std::vector<std::uint32_t> before_, after_; ///< border neighbours (kMany: several)
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> faces_; ///< of border vertices
};

} // namespace

std::size_t close_border_notches(std::vector<Triangle>& triangles,
                                 const std::vector<BorderEdge>& border,
                                 const std::vector<Vec3>& points,
                                 const IndexVector<VertexIndex, PointIndex>& vertex_point,
                                 double max_gap) {
    Notches notches(triangles, border, points, vertex_point);
    return notches.close(max_gap);
}

} // namespace hrsr
