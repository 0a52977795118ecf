// Face labels on the darts of a rotation system (ALGORITHM.md §5.4): "are these two corners
// in the same face", "split a face by a new edge", "merge two faces by a handle edge".
#pragma once

#include "rsr/rotation_system.h"

#include <stdexcept>
#include <vector>

namespace hrsr::rsr {

class Faces {
public:
    explicit Faces(RotationSystem& rotation) : rs_(rotation) {}

    /// Labels every face of the current graph by tracing it (a spanning tree has one face).
    void label_all();
    std::size_t count() const { return count_; }

    /// Label of the face that owns the wedge at v containing the direction of w.
    std::uint32_t face_of_wedge(std::uint32_t v, std::uint32_t w) const {
        return rs_.dart(v, rs_.wedge(v, w)).face;
    }

    /// After insert_edge put v→w and w→v inside one face: splits it in two. The smaller new face
    /// is relabelled (found by walking both in lock-step), so the total cost is O(n log n).
    void split(DartRef vw, DartRef wv);

    /// The darts split() walks, kept by a caller that splits on its own thread.
    struct SplitWalks {
        std::vector<DartRef> a, b;
    };
    /// split() for threads that work on disjoint sets of vertices (D-51): the smaller side takes
    /// `label` (from reserve_labels()) and the count is left to count_splits(). The walks read
    /// the rotation of each vertex they reach; before they would reach one with inside(v) false
    /// they stop, nothing has changed and the result is false. v and w must be inside.
    template <class Inside>
    bool split_inside(DartRef vw, DartRef wv, std::uint32_t label, SplitWalks& walks,
                      const Inside& inside);
    /// The first of `n` labels that nobody else will take (for split_inside()).
    std::uint32_t reserve_labels(std::size_t n);
    void count_splits(std::size_t n) { count_ += n; }
    /// After insert_edge joined two different faces: they become one face.
    void merge(DartRef vw, DartRef wv);

    /// Marks the face on the left of u→v as a recorded output triangle. Such a face must stay a
    /// face: no later edge may enter it (a handle merging it would make the triangle a non-face).
    void mark_recorded_triangle(std::uint32_t u, std::uint32_t v);
    bool is_recorded_triangle(std::uint32_t label) const {
        return label < recorded_.size() && recorded_[label] != 0;
    }

    /// Number of darts of the face containing d (walks it).
    std::size_t length(DartRef d) const;
    /// The vertices of the face containing d, in face order starting at d's origin.
    std::vector<std::uint32_t> vertices(DartRef d) const;

private:
    DartRef step(DartRef d) const { return rs_.next_in_face(d); }
    /// Walks both sides of a split in lock-step until one closes: 0 if the side of vw is the
    /// smaller, 1 if that of wv, −1 if the walks stopped before a vertex not inside.
    template <class Inside>
    int walk_sides(DartRef vw, DartRef wv, SplitWalks& walks, std::size_t bound,
                   const Inside& inside) const;
    /// Gives the smaller side (from walk_sides) `new_label`, the other new dart the old one.
    void label_sides(DartRef vw, DartRef wv, int smaller, const SplitWalks& walks,
                     std::uint32_t new_label);
    /// The first of the next n unused labels; InvalidInput once kFaceBits bits are spent.
    std::uint32_t take_labels(std::size_t n);
    void relabel(DartRef start, std::uint32_t label);
    void label(const std::vector<DartRef>& face, std::uint32_t label);

    RotationSystem& rs_;
    std::uint32_t next_label_ = 0;
    std::size_t count_ = 0;
    std::vector<std::uint8_t> recorded_; ///< per label (bytes: threads of D-51 set their own)
    SplitWalks walks_;                   ///< split()'s scratch (at most half a face each)
};

template <class Inside>
int Faces::walk_sides(DartRef vw, DartRef wv, SplitWalks& walks, std::size_t bound,
                      const Inside& inside) const {
    const auto same = [](DartRef x, DartRef y) { return x.v == y.v && x.i == y.i; };
    // The darts after the new ones are old darts of the face being split.
    DartRef a = step(vw), b = step(wv);
    walks.a.assign(1, vw);
    walks.b.assign(1, wv);
    for (std::size_t n = 0;; ++n) {
        if (same(a, vw)) return 0; // the side of v→w closed first: it is the smaller one
        if (same(b, wv)) return 1;
        if (n > bound) throw std::logic_error("rotation system: a face does not close");
        walks.a.push_back(a);
        walks.b.push_back(b);
        if (!inside(rs_.dart(a).to) || !inside(rs_.dart(b).to)) return -1;
        a = step(a);
        b = step(b);
    }
}

template <class Inside>
bool Faces::split_inside(DartRef vw, DartRef wv, std::uint32_t label, SplitWalks& walks,
                         const Inside& inside) {
    // The edges inserted meanwhile by other threads are not counted yet: the bound allows them.
    const int smaller =
        walk_sides(vw, wv, walks, 2 * (rs_.edge_count() + rs_.vertex_count()), inside);
    if (smaller < 0) return false;
    label_sides(vw, wv, smaller, walks, label);
    return true;
}

} // namespace hrsr::rsr
