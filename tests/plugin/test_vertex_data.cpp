// filter_hrsr/vertex_data.cpp on layers made in code, against the installed MeshLab's library:
// every custom attribute type the filter knows keeps its name, type and each vertex's value
// (MeshLab's own filters and PLY importer make only float and Point3f ones, which the
// meshlabserver and meshlab_host tests cover); an unknown type is named, not copied; the
// per-vertex components are enabled on the mesh only when the input layer has them.
#include "vertex_data.h"

#include <vcg/complex/allocate.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <typeindex>
#include <vector>

namespace hrsr::plugin {
namespace {

using Allocator = vcg::tri::Allocator<CMeshO>;

struct NotAKnownType { // a plugin's own attribute type
    int a, b;
};

class VertexData : public ::testing::Test {
protected:
    void SetUp() override {
        in_ = document_.addNewMesh("", "cloud");
        out_ = document_.addNewMesh("", "mesh");
        Allocator::AddVertices(in_->cm, kPoints);
        for (std::size_t i = 0; i < kPoints; ++i)
            in_->cm.vert[i].P() = CMeshO::CoordType(float(i), 0, 0);
        // mesh vertex k from input point (7 k) mod kPoints: out of order, some points twice
        for (std::size_t k = 0; k < kVertices; ++k)
            sources_.push_back(&in_->cm.vert[7 * k % kPoints]);
        Allocator::AddVertices(out_->cm, kVertices);
    }
    std::size_t source(std::size_t k) const { return 7 * k % kPoints; }

    /// Adds the attribute `name` of type T to the input, value `value_of(i)` at point i, and
    /// after the copy expects exactly that type on the mesh with `value_of(source(k))` at k.
    template <typename T, typename F>
    void add(const std::string& name, F value_of) {
        auto h = Allocator::AddPerVertexAttribute<T>(in_->cm, name);
        for (std::size_t i = 0; i < kPoints; ++i) h[i] = value_of(i);
        checks_.push_back([this, name, value_of] {
            SCOPED_TRACE(name);
            ASSERT_TRUE(vcg::tri::HasPerVertexAttribute(out_->cm, name));
            vcg::PointerToAttribute key;
            key._name = name;
            EXPECT_TRUE(out_->cm.vert_attr.find(key)->_type == std::type_index(typeid(T)));
            auto copied = Allocator::FindPerVertexAttribute<T>(out_->cm, name);
            for (std::size_t k = 0; k < kVertices; ++k)
                ASSERT_TRUE(copied[k] == T(value_of(source(k)))) << "vertex " << k;
        });
    }

    static constexpr std::size_t kPoints = 50, kVertices = 80;
    MeshDocument document_;
    MeshModel *in_ = nullptr, *out_ = nullptr;
    std::vector<CVertexO*> sources_;
    std::vector<std::function<void()>> checks_;
};

TEST_F(VertexData, EveryKnownAttributeTypeKeepsNameTypeAndValues) {
    auto d = [](std::size_t i) { return double(i); };
    add<float>("f", [](std::size_t i) { return 0.5f * float(i) - 3; });
    add<double>("d", [](std::size_t i) { return 1e300 / double(i + 1); });
    add<std::int8_t>("i8", [](std::size_t i) { return std::int8_t(-int(i)); });
    add<std::uint8_t>("u8", [](std::size_t i) { return std::uint8_t(200 + i); });
    add<std::int16_t>("i16", [](std::size_t i) { return std::int16_t(-300 * int(i)); });
    add<std::uint16_t>("u16", [](std::size_t i) { return std::uint16_t(1000 * i); });
    add<std::int32_t>("i32", [](std::size_t i) { return std::int32_t(-70000 * int(i)); });
    add<std::uint32_t>("u32", [](std::size_t i) { return std::uint32_t(4000000000u - i); });
    add<std::int64_t>("i64",
                      [](std::size_t i) { return -(std::int64_t(1) << 40) * std::int64_t(i); });
    add<std::uint64_t>("u64", [](std::size_t i) { return (std::uint64_t(1) << 50) + i; });
    add<bool>("b", [](std::size_t i) { return i % 3 == 0; });
    add<char>("c", [](std::size_t i) { return char('A' + i % 26); });
    add<vcg::Point2f>("p2f", [=](std::size_t i) { return vcg::Point2f(float(i), -float(i)); });
    add<vcg::Point2d>("p2d", [=](std::size_t i) { return vcg::Point2d(d(i) / 3, 1); });
    add<vcg::Point2i>("p2i", [](std::size_t i) { return vcg::Point2i(int(i), 2); });
    add<vcg::Point3f>("p3f", [](std::size_t i) { return vcg::Point3f(float(i), 1, 2); });
    add<vcg::Point3d>("p3d", [=](std::size_t i) { return vcg::Point3d(d(i) / 7, 1e-300, -d(i)); });
    add<vcg::Point3i>("p3i", [](std::size_t i) { return vcg::Point3i(1, int(i), 3); });
    add<vcg::Point4f>("p4f", [](std::size_t i) { return vcg::Point4f(float(i), 1, 2, 3); });
    add<vcg::Point4d>("p4d", [=](std::size_t i) { return vcg::Point4d(d(i) / 9, 1, 2, 3); });
    add<vcg::Point4i>("p4i", [](std::size_t i) { return vcg::Point4i(int(i), 1, 2, 3); });
    add<vcg::Color4b>("rgba", [](std::size_t i) {
        return vcg::Color4b((unsigned char)i, 1, 2, (unsigned char)(255 - i));
    });
    Allocator::AddPerVertexAttribute<NotAKnownType>(in_->cm, "mine");
    Allocator::AddPerVertexAttribute<float>(in_->cm); // unnamed: a temporary one

    const std::vector<std::string> left_out = copy_vertex_data(*in_, sources_, *out_);
    EXPECT_EQ(left_out, std::vector<std::string>{"mine"});
    for (const auto& check : checks_) check();
    EXPECT_FALSE(vcg::tri::HasPerVertexAttribute(out_->cm, "mine"));
    EXPECT_EQ(out_->cm.vert_attr.size(), checks_.size()); // the unnamed one is not copied
}

TEST_F(VertexData, ComponentsAreCopiedAndEnabledOnlyWhereTheInputHasThem) {
    in_->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTTEXCOORD);
    for (std::size_t i = 0; i < kPoints; ++i) {
        in_->cm.vert[i].C() = vcg::Color4b((unsigned char)i, 2, 3, 4);
        in_->cm.vert[i].T() = vcg::TexCoord2f(float(i) / 64, 0.25f);
        in_->cm.vert[i].T().N() = 1;
        in_->cm.vert[i].Q() = float(i); // allocated, but not in the layer's data mask
    }
    in_->cm.textures = {"a.png", "b.png"};
    EXPECT_TRUE(copy_vertex_data(*in_, sources_, *out_).empty());
    EXPECT_TRUE(out_->hasDataMask(MeshModel::MM_VERTCOLOR));
    EXPECT_TRUE(out_->hasDataMask(MeshModel::MM_VERTTEXCOORD));
    EXPECT_FALSE(out_->hasDataMask(MeshModel::MM_VERTQUALITY));
    EXPECT_FALSE(out_->hasDataMask(MeshModel::MM_VERTRADIUS));
    EXPECT_EQ(out_->cm.textures, in_->cm.textures);
    for (std::size_t k = 0; k < kVertices; ++k) {
        const CVertexO &v = out_->cm.vert[k], &from = in_->cm.vert[source(k)];
        ASSERT_EQ(v.cC(), from.cC()) << k;
        ASSERT_EQ(v.cT().U(), from.cT().U()) << k;
        ASSERT_EQ(v.cT().V(), from.cT().V()) << k;
        ASSERT_EQ(v.cT().N(), 1) << k;
    }
}

TEST_F(VertexData, ALayerWithoutComponentsGivesAMeshWithout) {
    const int before = out_->dataMask();
    EXPECT_TRUE(copy_vertex_data(*in_, sources_, *out_).empty());
    EXPECT_EQ(out_->dataMask(), before);
    EXPECT_TRUE(out_->cm.vert_attr.empty());
    EXPECT_TRUE(out_->cm.textures.empty());
}

} // namespace
} // namespace hrsr::plugin
