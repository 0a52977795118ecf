// The rotation system of a graph embedded on a surface (ALGORITHM.md §5.3): for every vertex,
// its neighbours in counter-clockwise order around its normal, ordered by (angle, id) (D-4).
// Each directed edge (dart) v→w carries the label of the face on its left and the number of
// triangles recorded on the edge {v, w}.
#pragma once

#include "geometry.h"

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace hrsr::rsr {

/// Face labels have kFaceBits bits (Faces throws before it would run out of them).
inline constexpr int kFaceBits = 30;
inline constexpr std::uint32_t kNoFace = (std::uint32_t(1) << kFaceBits) - 1;
inline constexpr std::uint32_t kNotFound = std::numeric_limits<std::uint32_t>::max();

/// 16 bytes: the face split's geometry checks read the darts of every point near a candidate,
/// and on large clouds those reads miss the cache (docs/BENCHMARKS.md, session 39).
struct Dart {
    std::uint32_t to;
    std::uint32_t face : kFaceBits;
    std::uint32_t triangles : 2; ///< triangles recorded on this edge (0, 1 or 2)
    double angle;                ///< rotation angle of `to` around the dart's origin
};
static_assert(sizeof(Dart) == 16);

/// A dart named by its origin and its current position in the origin's rotation (positions
/// shift when edges are inserted at that vertex).
struct DartRef {
    std::uint32_t v;
    std::uint32_t i;
};

class RotationSystem {
public:
    /// Vertices with these positions and unit normals (the angles are measured with them).
    RotationSystem(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals);

    std::size_t vertex_count() const { return rotation_.size(); }
    std::size_t edge_count() const { return edges_; }
    std::uint32_t degree(std::uint32_t v) const { return std::uint32_t(rotation_[v].size()); }
    const Dart& dart(std::uint32_t v, std::uint32_t i) const { return rotation_[v][i]; }
    Dart& dart(std::uint32_t v, std::uint32_t i) { return rotation_[v][i]; }
    const Dart& dart(DartRef d) const { return rotation_[d.v][d.i]; }
    Dart& dart(DartRef d) { return rotation_[d.v][d.i]; }
    const std::vector<Dart>& darts(std::uint32_t v) const { return rotation_[v]; }

    /// Rotation angle of the direction from v to w, in v's tangent frame.
    double angle(std::uint32_t v, std::uint32_t w) const;
    /// Position of neighbour w in v's rotation, or kNotFound.
    std::uint32_t find(std::uint32_t v, std::uint32_t w) const;
    bool adjacent(std::uint32_t v, std::uint32_t w) const { return find(v, w) != kNotFound; }

    /// Counter-clockwise successor / predecessor positions in v's rotation.
    std::uint32_t next(std::uint32_t v, std::uint32_t i) const {
        return i + 1 == degree(v) ? 0 : i + 1;
    }
    std::uint32_t prev(std::uint32_t v, std::uint32_t i) const {
        return (i == 0 ? degree(v) : i) - 1;
    }

    /// Position of the dart that owns the wedge at v containing the direction of w, i.e. the
    /// neighbour just clockwise of w "as if w were inserted" (pred_v(w), §5.3). degree(v) > 0.
    std::uint32_t wedge(std::uint32_t v, std::uint32_t w) const;
    /// The neighbour just counter-clockwise of w's direction at v "as if inserted" (succ_v(w)).
    std::uint32_t successor_as_if_inserted(std::uint32_t v, std::uint32_t w) const;

    /// The dart after `d` in its face: after u→v comes v→pred_v(u) (§5.3).
    DartRef next_in_face(DartRef d) const;

    /// Inserts the edge {v, w} (absent, v ≠ w) at the positions its angles decide. The new darts
    /// have no face label and no triangles. Returns them (v→w, w→v), valid until the next insert.
    std::pair<DartRef, DartRef> insert_edge(std::uint32_t v, std::uint32_t w) {
        const auto darts = insert_darts(v, w);
        ++edges_;
        return darts;
    }

    /// insert_edge() for threads inserting at disjoint sets of vertices (D-51): the edge count is
    /// left to count_edges(), called once they are done.
    std::pair<DartRef, DartRef> insert_darts(std::uint32_t v, std::uint32_t w);
    /// Takes back the darts the last insert_darts() returned (nothing has moved them since).
    void erase_darts(std::pair<DartRef, DartRef> darts);
    void count_edges(std::size_t inserted) { edges_ += inserted; }

    /// Unit normal used for angles at v.
    const Vec3& normal(std::uint32_t v) const { return normals_[v]; }
    const Vec3& position(std::uint32_t v) const { return positions_[v]; }

private:
    std::uint32_t insertion_position(std::uint32_t v, double angle, std::uint32_t w) const;

    const std::vector<Vec3>& positions_;
    const std::vector<Vec3>& normals_;
    std::vector<TangentFrame> frames_;
    std::vector<std::vector<Dart>> rotation_;
    std::size_t edges_ = 0;
};

} // namespace hrsr::rsr
