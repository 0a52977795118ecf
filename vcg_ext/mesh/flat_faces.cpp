#include "mesh/flat_faces.h"

#include "mesh/exact_predicates.h"
#include "mesh/split_mesh.h"

namespace hrsr {

namespace {

bool border(const SFace* f, int z) {
    return f->cFFp(z) == f;
}

class FlatFaces {
public:
    FlatFaces(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles)
        : positions_(positions), mesh_(positions, triangles, positions.size(), triangles.size()) {}

    bool flat(const SFace* f) const { return exact::collinear(at(f, 0), at(f, 1), at(f, 2)); }

    // Clears f if it can; false leaves it as it is.
    bool clear(SFace* f, FlatFaceStats& stats) {
        const int z = longest_edge(f);
        if (!border(f, z)) {
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

    // The edge opposite the corner that lies between the other two.
    int longest_edge(const SFace* f) const {
        int best = 0;
        double longest = -1;
        for (int z = 0; z < 3; ++z) {
            const double l = (at(f, (z + 1) % 3) - at(f, z)).SquaredNorm();
            if (l > longest) longest = l, best = z;
        }
        return best;
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
        if (border(f, (z + 1) % 3) || border(f, (z + 2) % 3)) return false;
        return !mesh_.star(mesh_.vertex_of(f, (z + 2) % 3)).boundary;
    }

    const std::vector<Vec3>& positions_;
    SplitMesh mesh_;
};

} // namespace

FlatFaceStats clear_flat_faces(const std::vector<Vec3>& positions,
                               std::vector<Triangle>& triangles) {
    FlatFaceStats stats;
    for (const Triangle& t : triangles)
        stats.found += exact::collinear(positions[t[0]], positions[t[1]], positions[t[2]]);
    if (stats.found == 0) return stats;

    FlatFaces mesh(positions, triangles);
    std::vector<SFace*> flat;
    for (SFace* f : mesh.live_faces())
        if (mesh.flat(f)) flat.push_back(f);
    // A clearing can open the way for another (a flip next to a run of flat faces), so the
    // list is walked until a pass clears nothing; each pass clears or keeps every face.
    for (bool progress = true; progress;) {
        progress = false;
        std::vector<SFace*> kept;
        for (SFace* f : flat) {
            if (!mesh.flat(f)) { // a flat face across a flipped edge is rewritten as a proper one
                ++stats.flipped;
                continue;
            }
            if (mesh.clear(f, stats))
                progress = true;
            else
                kept.push_back(f);
        }
        flat.swap(kept);
    }
    stats.left = flat.size();
    triangles = mesh.triangles();
    return stats;
}

} // namespace hrsr
