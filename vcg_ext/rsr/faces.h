// Face labels on the darts of a rotation system (ALGORITHM.md §5.4): "are these two corners
// in the same face", "split a face by a new edge", "merge two faces by a handle edge".
#pragma once

#include "rsr/rotation_system.h"

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
    /// After insert_edge joined two different faces: they become one face.
    void merge(DartRef vw, DartRef wv);

    /// Marks the face on the left of u→v as a recorded output triangle. Such a face must stay a
    /// face: no later edge may enter it (a handle merging it would make the triangle a non-face).
    void mark_recorded_triangle(std::uint32_t u, std::uint32_t v);
    bool is_recorded_triangle(std::uint32_t label) const {
        return label < recorded_.size() && recorded_[label];
    }

    /// Number of darts of the face containing d (walks it).
    std::size_t length(DartRef d) const;
    /// The vertices of the face containing d, in face order starting at d's origin.
    std::vector<std::uint32_t> vertices(DartRef d) const;

private:
    DartRef step(DartRef d) const;
    /// The next unused label; InvalidInput once kFaceBits bits are spent.
    std::uint32_t new_label();
    void relabel(DartRef start, std::uint32_t label);
    void label(const std::vector<DartRef>& face, std::uint32_t label);

    RotationSystem& rs_;
    std::uint32_t next_label_ = 0;
    std::size_t count_ = 0;
    std::vector<bool> recorded_;           ///< per label
    std::vector<DartRef> side_a_, side_b_; ///< split()'s walks (scratch, at most half a face)
};

} // namespace hrsr::rsr
