// `hrsr reconstruct` carries every per-point attribute to the vertex made from that point: the
// value on each output vertex equals the value of the input point the library says the vertex
// stands for (vertex_input_index), including vertex copies at non-manifold points and merged
// duplicates (their first occurrence); an hourglass's apex provides the copies. Without attributes,
// the output is unchanged.
#include "cli_runner.h"
#include "io/mesh_reader.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "reconstruction.h"
#include "samplers.h"
#include "temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace hrsr {
namespace {

using testing::Outcome;
using testing::slurp;

constexpr std::size_t kDuplicates = 15;

/// A value of `type` for point i, different for neighbouring points and covering the range.
double value_for(ScalarType type, std::size_t i, std::size_t column) {
    const std::uint64_t h = (i + 1) * 2654435761u + column * 40503u;
    switch (type) {
    case ScalarType::Int8:
        return double(std::int64_t(h % 256) - 128);
    case ScalarType::UInt8:
        return double(h % 256);
    case ScalarType::Int16:
        return double(std::int64_t(h % 65536) - 32768);
    case ScalarType::UInt16:
        return double(h % 65536);
    case ScalarType::Int32:
        return double(std::int64_t(h % 4294967296u) - 2147483648LL);
    case ScalarType::UInt32:
        return double(h % 4294967296u);
    case ScalarType::Float32:
        return double(float(double(h % 100000) / 7.0));
    case ScalarType::Float64:
        return double(h % 1000000007) / 3.0 + 1e9;
    }
    return 0;
}

/// `p` with attributes of every kind, and kDuplicates exact copies of its first points appended
/// with other values (which must never reach the output).
PointSet attributed(PointSet p) {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < kDuplicates; ++i) {
        p.positions.push_back(p.positions[i]);
        if (p.has_normals()) p.normals.push_back(p.normals[i]);
    }
    const std::vector<std::pair<const char*, ScalarType>> columns = {
        {"red", ScalarType::UInt8},
        {"green", ScalarType::UInt8},
        {"blue", ScalarType::UInt8},
        {"alpha", ScalarType::UInt8},
        {"intensity", ScalarType::UInt16},
        {"quality", ScalarType::Float32},
        {"confidence", ScalarType::Float64},
        {"label", ScalarType::Int32},
        {"classification", ScalarType::Int8},
        {"segment", ScalarType::Int16},
        {"id", ScalarType::UInt32}};
    for (std::size_t c = 0; c < columns.size(); ++c) {
        PointAttribute a(columns[c].first, columns[c].second);
        for (std::size_t i = 0; i < p.size(); ++i)
            a.append(value_for(a.type, i < n ? i : i + 7919, c)); // duplicates differ
        p.attributes.push_back(std::move(a));
    }
    return p;
}

PointSet attributed_sample() {
    return attributed(io::read_point_set(HRSR_SAMPLE));
}

class CliAttributes : public ::testing::Test {
protected:
    Outcome hrsr(const std::string& args) { return testing::run(HRSR_EXE, args, folder_.root()); }
    std::string path(const std::string& name) const { return folder_.path(name); }
    std::string write(const std::string& name, const PointSet& p) {
        io::write_ply(path(name), p.positions, p.normals, {}, p.precision, p.attributes);
        return path(name);
    }

    /// Every output vertex has the input's attributes (names, types) with the values of the
    /// point the library maps it to; returns that map.
    std::vector<std::uint32_t> expect_values_by_index(const PointSet& input, Method method,
                                                      const std::string& output) {
        ReconstructionOptions options;
        options.method = method;
        ReconstructionReport report;
        const Reconstruction expected = reconstruct(input, options, {}, report);
        const PointSet out = io::read_point_set(output);
        EXPECT_EQ(out.size(), expected.vertex_input_index.size());
        EXPECT_EQ(out.attributes.size(), input.attributes.size());
        if (out.size() != expected.vertex_input_index.size() ||
            out.attributes.size() != input.attributes.size())
            return {};
        std::size_t wrong = 0;
        for (std::size_t v = 0; v < out.size(); ++v) {
            const std::uint32_t i = expected.vertex_input_index[v];
            if (std::memcmp(&out.positions[v][0], &input.positions[i][0], 3 * sizeof(double)) != 0)
                ++wrong;
            for (std::size_t j = 0; j < input.attributes.size(); ++j) {
                const PointAttribute& got = out.attributes[j];
                const PointAttribute& want = input.attributes[j];
                EXPECT_EQ(got.name, want.name);
                EXPECT_EQ(got.type, want.type) << got.name;
                if (got.value(v) != want.value(i)) ++wrong;
            }
        }
        EXPECT_EQ(wrong, 0u);
        return expected.vertex_input_index;
    }

    testing::TempFolder folder_;
};

TEST_F(CliAttributes, EveryAttributeReachesTheVerticesOfItsPointIncludingCopies) {
    const PointSet input = attributed(testing::sample_hourglass(30));
    const Outcome r = hrsr("reconstruct " + write("in.ply", input) + " --method rsr -o " +
                           path("out.ply") + " --report " + path("r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::uint32_t> index =
        expect_values_by_index(input, Method::Rsr, path("out.ply"));

    // The case covers vertex copies (a point on two vertices) and merged duplicates, whose
    // own values never appear: their first occurrence represents them.
    const nlohmann::json report = nlohmann::json::parse(slurp(path("r.json")));
    const std::size_t distinct = std::set<std::uint32_t>(index.begin(), index.end()).size();
    EXPECT_LT(distinct, index.size());
    // The report counts the copies of the mesh written, not those made on the way.
    EXPECT_EQ(report.at("mesh").at("vertex_copies_for_non_manifold_points").get<std::size_t>(),
              index.size() - distinct);
    EXPECT_EQ(report.at("points").at("merged_duplicates").get<std::size_t>(), kDuplicates);
    const std::size_t first_duplicate = input.size() - kDuplicates;
    for (const std::uint32_t i : index) EXPECT_LT(i, first_duplicate);
}

TEST_F(CliAttributes, HrsrCarriesTheAttributesToo) {
    const PointSet input = attributed_sample();
    const Outcome r = hrsr("reconstruct -q " + write("in.ply", input) + " -o " + path("out.ply"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_values_by_index(input, Method::Hrsr, path("out.ply"));
}

TEST_F(CliAttributes, WithoutAttributesTheOutputIsTheSameBytes) {
    PointSet input = attributed_sample();
    const std::string coloured = write("coloured.ply", input);
    input.attributes.clear();
    const std::string plain = write("plain.ply", input);
    ASSERT_EQ(hrsr("reconstruct -q " + plain + " -o " + path("plain_out.ply")).exit_code, 0);
    ASSERT_EQ(
        hrsr("reconstruct -q --no-attributes " + coloured + " -o " + path("dropped.ply")).exit_code,
        0);
    ASSERT_EQ(hrsr("reconstruct -q " + coloured + " -o " + path("coloured_out.ply")).exit_code, 0);
    EXPECT_EQ(slurp(path("dropped.ply")), slurp(path("plain_out.ply")));
    // With them, the same vertices and faces.
    const io::MeshFile with = io::read_mesh(path("coloured_out.ply"));
    const io::MeshFile without = io::read_mesh(path("plain_out.ply"));
    EXPECT_EQ(with.points.positions, without.points.positions);
    EXPECT_EQ(with.triangles, without.triangles);
    EXPECT_GT(with.triangles.size(), with.points.size());
}

TEST_F(CliAttributes, TilesReadTogetherGiveTheMeshOfTheWholeFile) {
    const PointSet input = attributed_sample();
    PointSet first, second;
    const std::size_t half = input.size() / 2;
    for (PointSet* part : {&first, &second}) {
        const std::size_t begin = part == &first ? 0 : half,
                          end = part == &first ? half : input.size();
        part->positions.assign(input.positions.begin() + long(begin),
                               input.positions.begin() + long(end));
        part->precision = input.precision;
        for (const PointAttribute& a : input.attributes) {
            std::vector<std::uint32_t> range;
            for (std::size_t i = begin; i < end; ++i) range.push_back(std::uint32_t(i));
            part->attributes.push_back(gather(a, range));
        }
    }
    ASSERT_EQ(hrsr("reconstruct -q " + write("whole.ply", input) + " -o " + path("whole_out.ply"))
                  .exit_code,
              0);
    const Outcome r =
        hrsr("reconstruct -q " + write("a.ply", first) + " " + write("b.ply", second) + " -o " +
             path("tiles_out.ply") + " --report " + path("r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(path("tiles_out.ply")), slurp(path("whole_out.ply")));
    const nlohmann::json report = nlohmann::json::parse(slurp(path("r.json")));
    EXPECT_EQ(report.at("input"), nlohmann::json({path("a.ply"), path("b.ply")}));
}

TEST_F(CliAttributes, TilesWithDifferentAttributesAreAnErrorAndNothingIsWritten) {
    PointSet input = attributed_sample();
    const std::string a = write("a.ply", input);
    input.attributes.pop_back();
    const std::string b = write("b.ply", input);
    const Outcome r = hrsr("reconstruct " + a + " " + b + " -o " + path("out.ply"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err.rfind("hrsr: " + b + ": ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("attributes"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("out.ply")));
    EXPECT_EQ(
        hrsr("reconstruct -q --no-attributes " + a + " " + b + " -o " + path("out.ply")).exit_code,
        0);
}

TEST_F(CliAttributes, ObjVertexColoursReachTheMesh) {
    const PointSet sample = io::read_point_set(HRSR_SAMPLE);
    std::ofstream obj(path("in.obj"));
    obj.precision(9);
    for (std::size_t i = 0; i < sample.size(); ++i)
        obj << "v " << sample.positions[i][0] << " " << sample.positions[i][1] << " "
            << sample.positions[i][2] << " " << (i % 256) / 255.0 << " " << (i / 256 % 256) / 255.0
            << " 1\n";
    obj.close();
    const PointSet input = io::read_point_set(path("in.obj"));
    ASSERT_EQ(input.attributes.size(), 3u);
    for (std::size_t i = 0; i < input.size(); ++i) {
        ASSERT_EQ(input.attributes[0].value(i), double(i % 256));
        ASSERT_EQ(input.attributes[1].value(i), double(i / 256 % 256));
    }
    const Outcome r = hrsr("reconstruct -q " + path("in.obj") + " -o " + path("out.ply"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_values_by_index(input, Method::Hrsr, path("out.ply"));
}

TEST_F(CliAttributes, ListPropertiesAreLeftOutWithAWarning) {
    const PointSet sample = io::read_point_set(HRSR_SAMPLE);
    std::ofstream ply(path("in.ply"));
    ply.precision(9);
    ply << "ply\nformat ascii 1.0\nelement vertex " << sample.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
           "property list uchar int tags\nend_header\n";
    for (std::size_t i = 0; i < sample.size(); ++i)
        ply << sample.positions[i][0] << " " << sample.positions[i][1] << " "
            << sample.positions[i][2] << " " << i % 256 << " 3 7 8 9\n";
    ply.close();
    const std::string in = path("in.ply");
    const Outcome r = hrsr("reconstruct -q " + in + " -o " + path("out.ply"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("hrsr: warning: " + in + ": vertex property 'tags' is a list"),
              std::string::npos)
        << r.err;
    const PointSet out = io::read_point_set(path("out.ply"));
    ASSERT_EQ(out.attributes.size(), 1u);
    EXPECT_EQ(out.attributes[0].name, "red");
}

} // namespace
} // namespace hrsr
