#include "rsr/faces.h"

#include "errors.h"

#include <stdexcept>

namespace hrsr::rsr {

namespace {
bool same(DartRef a, DartRef b) {
    return a.v == b.v && a.i == b.i;
}
} // namespace

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
                relabel({v, i}, take_labels(1));
                ++count_;
            }
}

// The darts of both sides are kept as they are walked: the side that closes first is the
// smaller, and its darts, all walked by then, take the new label without a second walk.
void Faces::split(DartRef vw, DartRef wv) {
    const int smaller =
        walk_sides(vw, wv, walks_, 2 * rs_.edge_count(), [](std::uint32_t) { return true; });
    label_sides(vw, wv, smaller, walks_, take_labels(1));
    ++count_;
}

void Faces::label_sides(DartRef vw, DartRef wv, int smaller, const SplitWalks& walks,
                        std::uint32_t new_label) {
    // The dart after v→w is old (no face of a simple graph is one dart long: walks.a[1] exists).
    const std::uint32_t old_label = rs_.dart(walks.a[1]).face;
    if (smaller == 0) {
        label(walks.a, new_label);
        rs_.dart(wv).face = old_label;
    } else {
        label(walks.b, new_label);
        rs_.dart(vw).face = old_label;
    }
}

std::uint32_t Faces::reserve_labels(std::size_t n) {
    const std::uint32_t first = take_labels(n);
    if (recorded_.size() < next_label_) recorded_.resize(next_label_, 0);
    return first;
}

std::uint32_t Faces::take_labels(std::size_t n) {
    // D-51 reserves labels for candidates that are not inserted too (docs/ALGORITHM.md).
    if (n > std::size_t(kNoFace - next_label_))
        throw InvalidInput("a piece of the cloud has more faces than the rotation system can "
                           "label (2^" +
                           std::to_string(kFaceBits) + "); reconstruct the cloud in parts");
    const std::uint32_t first = next_label_;
    next_label_ += std::uint32_t(n);
    return first;
}

void Faces::label(const std::vector<DartRef>& face, std::uint32_t label) {
    for (DartRef d : face) rs_.dart(d).face = label;
}

void Faces::mark_recorded_triangle(std::uint32_t u, std::uint32_t v) {
    const std::uint32_t label = rs_.dart(u, rs_.find(u, v)).face;
    if (label >= recorded_.size()) recorded_.resize(std::size_t(label) + 1, 0);
    recorded_[label] = 1;
}

void Faces::merge(DartRef vw, DartRef wv) {
    const std::uint32_t a = rs_.dart(step(vw)).face, b = rs_.dart(step(wv)).face;
    relabel(vw, std::min(a, b));
    --count_;
}

} // namespace hrsr::rsr
