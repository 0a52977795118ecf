#include "rsr/faces.h"

#include "errors.h"

#include <stdexcept>

namespace hrsr::rsr {

namespace {
bool same(DartRef a, DartRef b) {
    return a.v == b.v && a.i == b.i;
}
} // namespace

DartRef Faces::step(DartRef d) const {
    return rs_.next_in_face(d);
}

// Walks are bounded by the number of darts: a rotation system that does not close its faces is
// a bug, reported instead of looping forever.
std::size_t Faces::length(DartRef d) const {
    const std::size_t bound = 2 * rs_.edge_count();
    std::size_t n = 1;
    for (DartRef e = step(d); !same(e, d); e = step(e))
        if (++n > bound) throw std::logic_error("rotation system: a face does not close");
    return n;
}

std::vector<std::uint32_t> Faces::vertices(DartRef d) const {
    std::vector<std::uint32_t> result{d.v};
    for (DartRef e = step(d); !same(e, d); e = step(e)) {
        result.push_back(e.v);
        if (result.size() > 2 * rs_.edge_count())
            throw std::logic_error("rotation system: a face does not close");
    }
    return result;
}

void Faces::relabel(DartRef start, std::uint32_t label) {
    const std::size_t bound = 2 * rs_.edge_count();
    std::size_t n = 0;
    DartRef e = start;
    do {
        rs_.dart(e).face = label;
        e = step(e);
        if (++n > bound) throw std::logic_error("rotation system: a face does not close");
    } while (!same(e, start));
}

void Faces::label_all() {
    count_ = 0;
    for (std::uint32_t v = 0; v < rs_.vertex_count(); ++v)
        for (std::uint32_t i = 0; i < rs_.degree(v); ++i) rs_.dart(v, i).face = kNoFace;
    for (std::uint32_t v = 0; v < rs_.vertex_count(); ++v)
        for (std::uint32_t i = 0; i < rs_.degree(v); ++i)
            if (rs_.dart(v, i).face == kNoFace) {
                relabel({v, i}, new_label());
                ++count_;
            }
}

// The darts of both sides are kept as they are walked: the side that closes first is the
// smaller, and its darts, all walked by then, take the new label without a second walk.
void Faces::split(DartRef vw, DartRef wv) {
    // The darts after the new ones are old darts of the face being split.
    DartRef a = step(vw), b = step(wv);
    const std::uint32_t old_label = rs_.dart(a).face;
    const std::size_t bound = 2 * rs_.edge_count();
    side_a_.assign(1, vw);
    side_b_.assign(1, wv);
    for (std::size_t n = 0;; ++n) {
        if (same(a, vw)) { // the side of v→w closed first: it is the smaller one
            label(side_a_, new_label());
            rs_.dart(wv).face = old_label;
            break;
        }
        if (same(b, wv)) {
            label(side_b_, new_label());
            rs_.dart(vw).face = old_label;
            break;
        }
        if (n > bound) throw std::logic_error("rotation system: a face does not close");
        side_a_.push_back(a);
        side_b_.push_back(b);
        a = step(a);
        b = step(b);
    }
    ++count_;
}

std::uint32_t Faces::new_label() {
    if (next_label_ >= kNoFace) // a piece of some 350 million points
        throw InvalidInput("a piece of the cloud has more faces than the rotation system can "
                           "label (2^" +
                           std::to_string(kFaceBits) + "); reconstruct the cloud in parts");
    return next_label_++;
}

void Faces::label(const std::vector<DartRef>& face, std::uint32_t label) {
    for (DartRef d : face) rs_.dart(d).face = label;
}

void Faces::mark_recorded_triangle(std::uint32_t u, std::uint32_t v) {
    const std::uint32_t label = rs_.dart(u, rs_.find(u, v)).face;
    if (label >= recorded_.size()) recorded_.resize(std::size_t(label) + 1, false);
    recorded_[label] = true;
}

void Faces::merge(DartRef vw, DartRef wv) {
    const std::uint32_t a = rs_.dart(step(vw)).face, b = rs_.dart(step(wv)).face;
    relabel(vw, std::min(a, b));
    --count_;
}

} // namespace hrsr::rsr
