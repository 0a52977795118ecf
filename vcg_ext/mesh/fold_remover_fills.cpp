// D-32's fills (fold_remover.h): a vertex's fan, or a disc of fans grown towards what stood in
// the way, taken out and its hole triangulated again with the first fill that fits.
#include "mesh/fold_remover.h"

#include "geometry.h"
#include "mesh/triangle_against_faces.h"

#include <cmath>
#include <limits>

namespace hrsr::folds {

namespace {

// The most vertices a fold takes out with it before its hole is left open instead.
constexpr std::size_t kMaxRegionVertices = 8;
// How far from a face cut inside the mesh a disc that closes its hole again may reach, in the
// face's longest edges (1.5: the dragon sample's holes close as with no limit, and no point far
// from the crossing line of two planes goes; 2 took points 7 spacings away).
constexpr double kClosingReach = 1.5;

// The hole of `faces` around v (each face holds v once): its link edges chained from the one
// corner that starts no chain... or, for an inner vertex, from the first face's. Fails (nullopt)
// where the link is not one simple path or cycle: a vertex of several fans, a repeated corner.
std::optional<Hole> link_of(std::uint32_t v, const std::vector<Triangle>& faces) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const Triangle& t : faces) {
        const auto k = std::size_t(std::find(t.begin(), t.end(), v) - t.begin());
        if (k == 3 || std::count(t.begin(), t.end(), v) != 1) return std::nullopt;
        edges.emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
    }
    const auto from = [&](std::uint32_t a) {
        return std::find_if(edges.begin(), edges.end(),
                            [a](const auto& e) { return e.first == a; });
    };
    std::optional<std::uint32_t> start;
    for (const auto& e : edges) {
        const auto same_source = std::count_if(edges.begin(), edges.end(),
                                               [&](const auto& o) { return o.first == e.first; });
        const auto same_target = std::count_if(edges.begin(), edges.end(),
                                               [&](const auto& o) { return o.second == e.second; });
        if (same_source > 1 || same_target > 1) return std::nullopt;
        const bool is_target = std::any_of(edges.begin(), edges.end(),
                                           [&](const auto& o) { return o.second == e.first; });
        if (!is_target) {
            if (start) return std::nullopt; // two chains: two fans
            start = e.first;
        }
    }
    Hole hole;
    hole.closed = !start;
    std::uint32_t corner = start.value_or(edges.front().first);
    hole.corners.push_back(corner);
    for (std::size_t used = 0; used < edges.size(); ++used) {
        const auto e = from(corner);
        if (e == edges.end()) return std::nullopt;
        corner = e->second;
        if (corner == hole.corners.front()) break;
        hole.corners.push_back(corner);
    }
    // Every edge used once, and no corner twice (the chain closed only at its start).
    const std::size_t expected = hole.closed ? edges.size() : edges.size() + 1;
    std::vector<std::uint32_t> sorted = hole.corners;
    std::sort(sorted.begin(), sorted.end());
    if (hole.corners.size() != expected ||
        std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() ||
        std::binary_search(sorted.begin(), sorted.end(), v))
        return std::nullopt;
    return hole;
}

} // namespace

std::size_t Remover::close_around(const std::vector<std::uint32_t>& corners) {
    const std::size_t m = corners.size();
    for (const bool facing : {true, false})
        for (std::size_t k = 0; k < m; ++k) {
            const std::uint32_t v = corners[k], next = corners[(k + 1) % m],
                                last = corners[(k + m - 1) % m];
            std::vector<Triangle> fan;
            for (std::uint32_t f : faces_of(v)) fan.push_back(triangles_[f]);
            if (fan.empty()) continue; // v went with another fill
            const std::optional<Hole> link = link_of(v, fan);
            // Two corners: the fill would have no triangle, v's one face would just go.
            if (link && !link->closed && link->corners.size() >= 3 &&
                link->corners.front() == last && link->corners.back() == next && refill(v, facing))
                return 1;
        }
    Vec3 sum(0, 0, 0);
    double longest = 0;
    for (std::size_t k = 0; k < m; ++k) {
        sum += positions_[corners[k]];
        longest =
            std::max(longest, (positions_[corners[k]] - positions_[corners[(k + 1) % m]]).Norm());
    }
    const Reach reach{sum / double(m), kClosingReach * longest};
    for (std::uint32_t v : corners)
        if (!faces_of(v).empty())
            if (const std::size_t removed = refill_region(v, &reach)) return removed;
    return 0;
}

bool Remover::close_hole(const Hole& hole) {
    blocker_ = kNoFace;
    for (const bool facing : {true, false})
        if (const std::optional<std::vector<Triangle>> fill = first_fitting_fill(hole, facing)) {
            for (const Triangle& t : *fill) add(t);
            return true;
        }
    return false;
}

std::size_t Remover::refill_region(std::uint32_t v, const Reach* reach) {
    std::vector<std::uint32_t> region{v};
    for (std::size_t size = 1; size <= kMaxRegionVertices; ++size) {
        std::vector<std::uint32_t> faces;
        for (std::uint32_t r : region)
            for (std::uint32_t f : faces_of(r)) faces.push_back(f);
        std::sort(faces.begin(), faces.end());
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
        for (std::uint32_t f : faces) alive_[f] = 0; // while the fills are tested
        set_faces_out(faces);
        const std::optional<DiscBorder> border = disc_border(faces);
        std::optional<std::vector<Triangle>> fill;
        blocker_ = kNoFace;
        for (const bool facing : {true, false})
            if (border && !fill) fill = first_fitting_fill(border->hole, facing);
        // Closing a hole (a reach is given), a fill without a triangle closes nothing.
        if (reach && fill && fill->empty()) fill.reset();
        for (std::uint32_t f : faces) alive_[f] = 1;
        set_faces_out({});
        if (!border) return 0;
        if (fill) {
            replace(faces, *fill, border->inner, border->hole.corners);
            return border->inner.size();
        }
        const std::uint32_t next = nearest_corner(border->hole.corners, region);
        if (reach && (positions_[next] - reach->centre).Norm() > reach->radius) return 0;
        region.push_back(next);
    }
    return 0;
}

std::optional<DiscBorder> Remover::disc_border(const std::vector<std::uint32_t>& faces) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (std::uint32_t f : faces)
        for (int k = 0; k < 3; ++k)
            directed.emplace_back(triangles_[f][k], triangles_[f][(k + 1) % 3]);
    std::sort(directed.begin(), directed.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> shared; // sorted by source
    std::vector<std::uint32_t> vertices;
    std::size_t inner_edges_twice = 0, mesh_border = 0;
    for (const auto& [a, b] : directed) {
        vertices.push_back(a);
        if (std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a)))
            ++inner_edges_twice;
        else if (has_edge(a, b))
            shared.emplace_back(a, b);
        else
            ++mesh_border;
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    // A disc: V − E + F = 1.
    const std::size_t edges = shared.size() + mesh_border + inner_edges_twice / 2;
    if (shared.empty() || vertices.size() + faces.size() != edges + 1) return std::nullopt;
    DiscBorder d;
    d.hole.closed = mesh_border == 0;
    if (!chain(shared, d.hole)) return std::nullopt;
    // The vertices that go: those with no standing face (a corner of the border keeps its
    // standing faces; so does a vertex where the disc touches the rest at one point).
    for (std::uint32_t v : vertices)
        if (faces_of(v).empty()) d.inner.push_back(v);
    return d;
}

bool Remover::chain(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges, Hole& hole) {
    const auto from = [&](std::uint32_t a) {
        const auto e = std::lower_bound(edges.begin(), edges.end(), std::make_pair(a, 0u));
        return e != edges.end() && e->first == a ? e : edges.end();
    };
    std::uint32_t corner = edges.front().first;
    if (!hole.closed) {
        std::vector<std::uint32_t> targets;
        for (const auto& e : edges) targets.push_back(e.second);
        std::sort(targets.begin(), targets.end());
        std::size_t starts = 0;
        for (const auto& e : edges)
            if (!std::binary_search(targets.begin(), targets.end(), e.first)) {
                corner = e.first;
                ++starts;
            }
        if (starts != 1) return false;
    }
    hole.corners.push_back(corner);
    for (std::size_t used = 0; used < edges.size(); ++used) {
        const auto e = from(corner);
        if (e == edges.end() || (e + 1 != edges.end() && (e + 1)->first == corner)) return false;
        corner = e->second;
        hole.corners.push_back(corner);
    }
    if (hole.closed) {
        if (hole.corners.back() != hole.corners.front()) return false;
        hole.corners.pop_back();
    }
    std::vector<std::uint32_t> sorted = hole.corners;
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

std::uint32_t Remover::nearest_corner(const std::vector<std::uint32_t>& corners,
                                      const std::vector<std::uint32_t>& region) const {
    Vec3 target = positions_[region.front()];
    if (blocker_ != kNoFace) {
        const Triangle& b = triangles_[blocker_];
        target = (positions_[b[0]] + positions_[b[1]] + positions_[b[2]]) / 3.0;
    }
    std::uint32_t best = corners.front();
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::uint32_t c : corners) {
        const double d = (positions_[c] - target).SquaredNorm();
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

bool Remover::inner_vertex(std::uint32_t v) const {
    std::vector<Triangle> fan;
    any_face(v, [&](const Triangle& t) {
        fan.push_back(t);
        return false;
    });
    if (fan.empty()) return false;
    const std::optional<Hole> link = link_of(v, fan);
    return link && link->closed;
}

bool Remover::refill(std::uint32_t v, bool facing, FillSearch search) {
    const std::vector<std::uint32_t> fan = faces_of(v);
    std::vector<Triangle> fan_triangles;
    for (std::uint32_t f : fan) fan_triangles.push_back(triangles_[f]);
    const std::optional<Hole> hole = link_of(v, fan_triangles);
    if (!hole || (hole->closed && hole->corners.size() < 3)) return false;
    for (std::uint32_t f : fan) alive_[f] = 0; // while the fills are tested
    set_faces_out(fan);
    const std::optional<std::vector<Triangle>> fill = first_fitting_fill(*hole, facing, search);
    for (std::uint32_t f : fan) alive_[f] = 1;
    set_faces_out({});
    if (!fill) return false;
    replace(fan, *fill, {v}, hole->corners);
    return true;
}

void Remover::replace(const std::vector<std::uint32_t>& faces, const std::vector<Triangle>& fill,
                      const std::vector<std::uint32_t>& removed,
                      const std::vector<std::uint32_t>& corners) {
    for (std::uint32_t f : faces) retire(f);
    for (const Triangle& t : fill) add(t);
    reinserted_ += reinsert(removed, corners);
}

std::optional<std::vector<Triangle>> Remover::first_fitting_fill(const Hole& hole, bool facing,
                                                                 FillSearch search) {
    const std::size_t m = hole.corners.size();
    if (m == 2) return std::vector<Triangle>(); // one face at a border vertex: it just goes
    // An open hole's last side is new, or a border edge whose face lies on its other side
    // (the fill then closes the notch).
    const std::uint32_t first = hole.corners.front(), last = hole.corners.back();
    if (!hole.closed && has_edge(last, first) &&
        (!has_directed_edge(first, last) || has_directed_edge(last, first)))
        return std::nullopt;
    if (m <= kMaxOptimisedHole) {
        // The best by angle alone first (cheap), then the best among triangles that cross
        // no standing face.
        for (const bool avoid_crossings : {false, true}) {
            if (avoid_crossings && search == FillSearch::by_angle) break;
            std::vector<Triangle> best = best_fill(hole, facing, avoid_crossings);
            if (!best.empty() && fits(hole, best, facing)) return best;
        }
        return std::nullopt;
    }
    for (std::size_t apex = 0; apex < m; ++apex) {
        std::vector<Triangle> fan;
        for (std::size_t i = 1; i + 1 < m; ++i)
            fan.push_back({hole.corners[apex], hole.corners[(apex + i) % m],
                           hole.corners[(apex + i + 1) % m]});
        if (fits(hole, fan, facing)) return fan;
    }
    return std::nullopt;
}

std::vector<Triangle> Remover::best_fill(const Hole& hole, bool facing, bool avoid_crossings) {
    const std::vector<std::uint32_t>& c = hole.corners;
    const std::size_t m = c.size();
    const auto diagonal_free = [&](std::size_t i, std::size_t j) {
        return j == i + 1 || (i == 0 && j == m - 1) || !has_edge(c[i], c[j]);
    };
    if (avoid_crossings) gather_standing(corners_box(hole.corners));
    std::vector<double> best(m * m, -1);
    std::vector<std::size_t> apex(m * m, 0);
    for (std::size_t i = 0; i + 1 < m; ++i) best[i * m + i + 1] = 4; // above any angle
    for (std::size_t span = 2; span < m; ++span)
        for (std::size_t i = 0; i + span < m; ++i) {
            const std::size_t j = i + span;
            if (!diagonal_free(i, j)) continue;
            for (std::size_t k = i + 1; k < j; ++k) {
                const Triangle t{c[i], c[k], c[j]};
                const double sub = std::min(best[i * m + k], best[k * m + j]);
                if (sub <= best[i * m + j] || sub <= 0) continue; // cannot do better
                // The angle first: the tests, the intersection one above all, only for a
                // triangle that would improve the fill.
                const double q = std::min(sub, angle(t));
                if (q <= best[i * m + j]) continue;
                if (proper(t, facing) && !repeats_a_face(t) &&
                    (!avoid_crossings || !crosses_gathered(welded(t)))) {
                    best[i * m + j] = q;
                    apex[i * m + j] = k;
                }
            }
        }
    std::vector<Triangle> fill;
    if (best[m - 1] <= 0) return fill;
    std::vector<std::pair<std::size_t, std::size_t>> todo{{0, m - 1}};
    while (!todo.empty()) {
        const auto [i, j] = todo.back();
        todo.pop_back();
        if (j < i + 2) continue;
        const std::size_t k = apex[i * m + j];
        fill.push_back({c[i], c[k], c[j]});
        todo.emplace_back(i, k);
        todo.emplace_back(k, j);
    }
    return fill;
}

bool Remover::proper(const Triangle& t, bool facing) const {
    if (geometry_.degenerate(welded(t))) return false;
    return !facing || faces_its_normals(t);
}

bool Remover::fits(const Hole& hole, const std::vector<Triangle>& fill, bool facing) {
    const std::size_t m = hole.corners.size();
    const auto side = [&](std::uint32_t a, std::uint32_t b) {
        const auto i = std::size_t(std::find(hole.corners.begin(), hole.corners.end(), a) -
                                   hole.corners.begin());
        const auto j = std::size_t(std::find(hole.corners.begin(), hole.corners.end(), b) -
                                   hole.corners.begin());
        const std::size_t d = i > j ? i - j : j - i;
        return d == 1 || d == m - 1;
    };
    for (std::size_t i = 0; i < fill.size(); ++i) {
        const Triangle& t = fill[i];
        if (!proper(t, facing) || repeats_a_face(t)) return false;
        for (int k = 0; k < 3; ++k)
            if (!side(t[k], t[(k + 1) % 3]) && has_edge(t[k], t[(k + 1) % 3])) return false;
        // Two corners of a hole may be copies of one point: no two new faces on the same
        // positions either.
        for (std::size_t j = 0; j < i; ++j)
            if (same_positions(t, fill[j]) || geometry_.intersect(welded(t), welded(fill[j])))
                return false;
        if (intersects_standing(welded(t))) return false; // blocker_ is set
    }
    return true;
}

bool Remover::intersects_standing(const Triangle& t) {
    gather_standing(geometry_.box(t));
    return intersects_gathered(t);
}

void Remover::gather_standing(const Box& box) {
    gathered_box_ = box;
    crossing_answers_ = nullptr;
    near_.gather(grid_, geometry_, box, [&](std::uint32_t f) { return alive_[f] != 0; });
}

void Remover::set_faces_out(std::vector<std::uint32_t> faces) {
    std::sort(faces.begin(), faces.end());
    faces_out_ = std::move(faces);
    crossing_answers_ = nullptr;
}

bool Remover::crosses_gathered(const Triangle& t) {
    if (crossing_memo_version_ != mesh_version_) {
        crossing_memo_.clear();
        crossing_memo_version_ = mesh_version_;
        crossing_answers_ = nullptr;
    }
    if (!crossing_answers_) { // the faces out or the box changed: look up their answers once
        const Box& b = gathered_box_;
        crossing_answers_ =
            &crossing_memo_[{faces_out_, {b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]}}];
    }
    const auto [it, inserted] = crossing_answers_->try_emplace(t, kNoFace);
    if (!inserted) {
        if (it->second != kNoFace) blocker_ = it->second;
        return it->second != kNoFace;
    }
    if (!intersects_gathered(t)) return false;
    it->second = blocker_;
    return true;
}

bool Remover::intersects_gathered(const Triangle& t) {
    const Box box = geometry_.box(t);
    const TriangleAgainstFaces against(geometry_, t);
    for (const auto& [f, b] : near_.found())
        if (box.overlaps(b) && against.intersects(geometry_.triangle(f))) {
            blocker_ = f;
            return true;
        }
    return false;
}

} // namespace hrsr::folds
