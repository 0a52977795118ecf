// The index spaces of index_types.h do not mix: a mapping typed on both sides takes only its own
// key, and no space converts to another.
#include "index_types.h"

#include <gtest/gtest.h>

#include <type_traits>

namespace hrsr {
namespace {

static_assert(!std::is_convertible_v<InputIndex, VertexIndex>);
static_assert(!std::is_convertible_v<PointIndex, InputIndex>);
static_assert(!std::is_convertible_v<CoarseIndex, PointIndex>);
static_assert(!std::is_convertible_v<VertexIndex, FaceIndex>);
static_assert(!std::is_convertible_v<std::uint32_t, PointIndex>); // only explicitly
static_assert(!std::is_convertible_v<PointIndex, std::uint32_t>);
static_assert(sizeof(PointIndex) == sizeof(std::uint32_t)); // a table costs what it did

// operator[] of IndexVector<Key, …> accepts Key and nothing else.
template <class Table, class Key, class = void>
struct Indexable : std::false_type {};
template <class Table, class Key>
struct Indexable<Table, Key, std::void_t<decltype(std::declval<Table&>()[std::declval<Key>()])>>
    : std::true_type {};
using InputOfPoint = IndexVector<PointIndex, InputIndex>;
static_assert(Indexable<InputOfPoint, PointIndex>::value);
static_assert(!Indexable<InputOfPoint, CoarseIndex>::value);
static_assert(!Indexable<InputOfPoint, InputIndex>::value);
static_assert(!Indexable<InputOfPoint, std::uint32_t>::value);
static_assert(!Indexable<IndexView<CoarseIndex, PointIndex>, PointIndex>::value);
static_assert(std::is_same_v<decltype(std::declval<InputOfPoint&>()[PointIndex(0)]), InputIndex&>);

TEST(IndexTypes, MappingsReadThroughTheirKeys) {
    InputOfPoint input_of;
    for (std::uint32_t i : {4u, 7u, 9u}) input_of.push_back(InputIndex(i));
    EXPECT_EQ(input_of[PointIndex(1)], InputIndex(7));
    EXPECT_EQ(input_of.next_key(), PointIndex(3));
    std::uint32_t keys = 0;
    for (PointIndex p : input_of.keys()) EXPECT_EQ(p, PointIndex(keys++));
    EXPECT_EQ(keys, 3u);
    EXPECT_EQ(raw(input_of.values()), (std::vector<std::uint32_t>{4, 7, 9}));

    const std::vector<std::uint32_t> plain{2, 0};
    const IndexView<VertexIndex, PointIndex> node_of(plain);
    EXPECT_EQ(node_of[VertexIndex(0)], PointIndex(2));
    EXPECT_LT(PointIndex(0), PointIndex(2));
    EXPECT_EQ(std::hash<PointIndex>()(PointIndex(5)), std::hash<std::uint32_t>()(5u));
}

} // namespace
} // namespace hrsr
