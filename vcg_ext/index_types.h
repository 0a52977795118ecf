// Distinct index types for the index spaces the pipeline maps between: a mapping from one space
// to another is typed on both sides, so passing a node where an input index belongs, or
// indexing the wrong table, does not compile. Inner loops that stay within one space
// (the rotation system, the collapse, the re-expansion's mesh) keep plain std::uint32_t; the
// types start where two spaces meet.
//
// The spaces (ALGORITHM.md §1):
//   InputIndex   a point of the user's PointSet (the public API's vertex_input_index, fates);
//   PointIndex   a point of the pre-processed cloud (PreparedCloud), = a collapse node of HRsR;
//   CoarseIndex  a point of HRsR's coarse cloud (the collapse survivors RsR runs on);
//   VertexIndex  a vertex of the mesh at hand (the output's, or fold repair's);
//   FaceIndex    a triangle of that mesh, by its position in the triangle list.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace hrsr {

/// An index into the space named by Tag; converts to and from std::uint32_t only explicitly.
template <class Tag>
class Index {
public:
    Index() = default;
    constexpr explicit Index(std::uint32_t value) : value_(value) {}
    constexpr std::uint32_t value() const { return value_; }

    friend constexpr bool operator==(Index a, Index b) { return a.value_ == b.value_; }
    friend constexpr bool operator!=(Index a, Index b) { return a.value_ != b.value_; }
    friend constexpr bool operator<(Index a, Index b) { return a.value_ < b.value_; }

private:
    std::uint32_t value_ = 0;
};

using InputIndex = Index<struct InputTag>;
using PointIndex = Index<struct PointTag>;
using CoarseIndex = Index<struct CoarseTag>;
using VertexIndex = Index<struct VertexTag>;
using FaceIndex = Index<struct FaceTag>;

/// The keys 0 … n − 1 of a space, for range-for.
template <class Key>
class KeyRange {
public:
    explicit KeyRange(std::size_t n) : n_(std::uint32_t(n)) {}
    class iterator {
    public:
        explicit iterator(std::uint32_t i) : i_(i) {}
        Key operator*() const { return Key(i_); }
        iterator& operator++() {
            ++i_;
            return *this;
        }
        bool operator!=(const iterator& o) const { return i_ != o.i_; }

    private:
        std::uint32_t i_;
    };
    iterator begin() const { return iterator(0); }
    iterator end() const { return iterator(n_); }

private:
    std::uint32_t n_;
};

/// A table over the index space Key: operator[] takes only a Key. Holds its values contiguously
/// (a std::vector), so a mapping costs what the plain vector did.
template <class Key, class Value>
class IndexVector {
public:
    IndexVector() = default;
    IndexVector(std::size_t size, const Value& value) : values_(size, value) {}

    Value& operator[](Key k) { return values_[k.value()]; }
    const Value& operator[](Key k) const { return values_[k.value()]; }
    std::size_t size() const { return values_.size(); }
    bool empty() const { return values_.empty(); }
    void reserve(std::size_t n) { values_.reserve(n); }
    void resize(std::size_t n, const Value& value) { values_.resize(n, value); }
    void push_back(const Value& v) { values_.push_back(v); }
    /// The key the next push_back will have.
    Key next_key() const { return Key(std::uint32_t(values_.size())); }
    auto begin() const { return values_.begin(); }
    auto end() const { return values_.end(); }
    KeyRange<Key> keys() const { return KeyRange<Key>(size()); }
    /// The values in key order (for code that walks them or hands them on as a whole).
    const std::vector<Value>& values() const { return values_; }

    friend bool operator==(const IndexVector& a, const IndexVector& b) {
        return a.values_ == b.values_;
    }

private:
    std::vector<Value> values_;
};

/// A read-only typed view of a plain std::uint32_t table made by code shared with other users
/// (e.g. same_position_representatives, the welded ids fold repair maps vertices through).
template <class Key, class Value>
class IndexView {
public:
    explicit IndexView(const std::vector<std::uint32_t>& values) : values_(values) {}
    Value operator[](Key k) const { return Value(values_[k.value()]); }
    std::size_t size() const { return values_.size(); }

private:
    const std::vector<std::uint32_t>& values_;
};

/// The plain values, for the public API (it stays std::uint32_t: one space per field there).
template <class Tag>
std::vector<std::uint32_t> raw(const std::vector<Index<Tag>>& indices) {
    std::vector<std::uint32_t> out;
    out.reserve(indices.size());
    for (Index<Tag> i : indices) out.push_back(i.value());
    return out;
}

} // namespace hrsr

template <class Tag>
struct std::hash<hrsr::Index<Tag>> {
    std::size_t operator()(hrsr::Index<Tag> i) const noexcept {
        return std::hash<std::uint32_t>()(i.value());
    }
};
