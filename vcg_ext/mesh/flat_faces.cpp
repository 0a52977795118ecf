#include "mesh/flat_faces.h"

#include "mesh/exact_predicates.h"
#include "mesh/split_mesh.h"

#include <optional>
#include <stdexcept>

namespace hrsr {

namespace {

class FlatFaces {
public:
    FlatFaces(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
              const Execution& exec)
        : positions_(positions),
          mesh_(positions, triangles, positions.size(), triangles.size(), exec) {}

    // Clears f if it can; false leaves it as it is.
    bool clear(SFace* f, FlatFaceStats& stats) {
        const int z = longest_edge(f);
        if (!is_border(f, z)) {
            if (!flip_fits(f, z)) return false;
            mesh_.flip(f, z);
            ++stats.flipped;
            return true;
        }
        if (!removable(f, z)) return false;
        mesh_.remove_face(f);
        ++stats.removed;
        return true;
    }

    std::vector<SFace*> live_faces() { return mesh_.live_faces(); }
    std::vector<Triangle> triangles() const { return mesh_.triangles(); }

private:
    const Vec3& at(const SFace* f, int k) const { return positions_[mesh_.vertex_of(f, k)]; }

    // The edge opposite the corner that lies between the other two, decided exactly: along a
    // line, every coordinate that is not the same for all three points orders them as the line
    // does (rounded lengths could tie and pick an end).
    int longest_edge(const SFace* f) const {
        const Vec3 &p0 = at(f, 0), &p1 = at(f, 1), &p2 = at(f, 2);
        for (int axis = 0; axis < 3; ++axis) {
            const double x0 = p0[axis], x1 = p1[axis], x2 = p2[axis];
            if (x0 == x1 && x1 == x2) continue;
            const auto between = [](double lo, double x, double hi) {
                return (lo <= x && x <= hi) || (hi <= x && x <= lo);
            };
            if (between(x1, x0, x2)) return 1; // corner 0 in the middle: edge 1 → 2
            if (between(x0, x1, x2)) return 2;
            return 0;
        }
        return 0; // all three at one position: no flip or removal will fit
    }

    // The flip joins m to the far corner o of the face g across edge z: (m, a, o) and
    // (m, o, b) must be proper triangles (o off the line) and the diagonal new.
    bool flip_fits(SFace* f, int z) const {
        const SFace* g = f->FFp(z);
        const Vec3& m = at(f, (z + 2) % 3);
        const Vec3& o = positions_[mesh_.vertex_of(g, (f->FFi(z) + 2) % 3)];
        return !exact::collinear(m, at(f, z), o) && !exact::collinear(m, o, at(f, (z + 1) % 3)) &&
               mesh_.can_flip(f, z);
    }

    // On the border (edge z): both other edges must be interior, so that each end of edge z
    // keeps a face, and m must be interior, so that its faces stay one fan once f is gone.
    bool removable(const SFace* f, int z) const {
        if (is_border(f, (z + 1) % 3) || is_border(f, (z + 2) % 3)) return false;
        return !mesh_.star(mesh_.vertex_of(f, (z + 2) % 3)).boundary;
    }

    const std::vector<Vec3>& positions_;
    SplitMesh mesh_;
};

} // namespace

FlatFaceStats clear_flat_faces(const std::vector<Vec3>& positions, std::vector<Triangle>& triangles,
                               const Execution& exec) {
    FlatFaceStats stats;
    // By face number: one exact test per face, by blocks (each listing its own, in order).
    std::vector<std::vector<std::size_t>> flat_in_block(block_count(triangles.size(), kCheapBlock));
    parallel_for_blocks(
        exec, triangles.size(), kCheapBlock,
        [&](std::size_t block, std::size_t first, std::size_t end) {
            for (std::size_t f = first; f < end; ++f) {
                const Triangle& t = triangles[f];
                if (exact::collinear(positions[t[0]], positions[t[1]], positions[t[2]]))
                    flat_in_block[block].push_back(f);
            }
        });
    std::vector<std::size_t> flat_at;
    for (const std::vector<std::size_t>& block : flat_in_block)
        flat_at.insert(flat_at.end(), block.begin(), block.end());
    stats.found = flat_at.size();
    if (stats.found == 0) return stats;

    // The mesh after D-32 is a consistently oriented manifold; should it not be, the faces stay
    // as they are (counted as left) rather than the reconstruction failing here.
    std::optional<FlatFaces> built;
    try {
        built.emplace(positions, triangles, without_progress(exec));
    } catch (const std::logic_error&) {
        stats.left = stats.found;
        return stats;
    }
    FlatFaces& mesh = *built;
    const std::vector<SFace*> faces = mesh.live_faces(); // in the order of `triangles`
    std::vector<SFace*> flat;
    for (std::size_t f : flat_at) flat.push_back(faces[f]);
    // A clearing can open the way for another (a flip next to a run of flat faces), so the
    // list is walked until a pass clears nothing; each pass clears or keeps every face.
    for (bool progress = true; progress;) {
        progress = false;
        std::vector<SFace*> kept;
        // A flip rewrites only f and the face across, which is never flat (o off the line).
        for (SFace* f : flat)
            if (mesh.clear(f, stats))
                progress = true;
            else
                kept.push_back(f);
        flat.swap(kept);
    }
    stats.left = flat.size();
    triangles = mesh.triangles();
    return stats;
}

} // namespace hrsr
