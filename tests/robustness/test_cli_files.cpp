// Issue 7, items 2 and 4, end to end through `hrsr reconstruct`: malformed and unusual files
// (an error naming the file and the problem, exit 1, no output; or the same mesh as the plain
// file), the input never modified, outputs complete or absent, and byte-identical outputs
// across runs and thread counts.
#include "cli_runner.h"
#include "samplers.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <sstream>

namespace fs = std::filesystem;

namespace hrsr {
namespace {

using testing::lines;
using testing::Outcome;
using testing::slurp;

/// How a PLY file is encoded; every layout stores the same float values.
struct Layout {
    enum Format { Ascii, BinaryLittle, BinaryBig } format = Ascii;
    bool crlf = false;        ///< ascii with "\r\n" line ends
    bool extra = false;       ///< extra vertex properties (before, between and after x y z)
    bool int_lists = false;   ///< a face element whose list counts are int, not uchar
    bool normals = true;      ///< nx ny nz
    long declared = -1;       ///< vertex count in the header (-1: the true count)
    std::size_t truncate = 0; ///< bytes cut off the end
    bool without_z = false;   ///< no z property (and no z values)
};

template <typename T>
void put(std::string& out, T value, bool big_endian) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (big_endian) std::reverse(bytes, bytes + sizeof(T));
    out.append(bytes, sizeof(T));
}

std::string ply(const PointSet& s, const Layout& l) {
    const std::string nl = l.crlf ? "\r\n" : "\n";
    const bool binary = l.format != Layout::Ascii, big = l.format == Layout::BinaryBig;
    std::string h =
        "ply" + nl + "format " +
        (l.format == Layout::Ascii ? "ascii"
                                   : (big ? "binary_big_endian" : "binary_little_endian")) +
        " 1.0" + nl + "comment robustness case" + nl + "element vertex " +
        std::to_string(l.declared >= 0 ? std::size_t(l.declared) : s.size()) + nl;
    if (l.extra) h += "property uchar red" + nl;
    h += "property float x" + nl + "property float y" + nl;
    if (l.extra) h += "property int label" + nl;
    if (!l.without_z) h += "property float z" + nl;
    if (l.normals)
        h += "property float nx" + nl + "property float ny" + nl + "property float nz" + nl;
    if (l.extra) h += "property double quality" + nl;
    if (l.int_lists) h += "element face 1" + nl + "property list int int vertex_indices" + nl;
    h += "end_header" + nl;
    std::string body;
    for (std::size_t i = 0; i < s.size(); ++i) {
        std::vector<float> v{float(s.positions[i][0]), float(s.positions[i][1])};
        if (!l.without_z) v.push_back(float(s.positions[i][2]));
        if (l.normals)
            for (int k = 0; k < 3; ++k) v.push_back(float(s.normals[i][k]));
        if (!binary) {
            std::ostringstream line;
            line.precision(9);
            if (l.extra) line << 7 << ' ';
            for (std::size_t k = 0; k < v.size(); ++k) {
                line << v[k] << ' ';
                if (k == 1 && l.extra) line << -3 << ' ';
            }
            if (l.extra) line << 0.25;
            body += line.str() + nl;
            continue;
        }
        if (l.extra) put<std::uint8_t>(body, 7, big);
        for (std::size_t k = 0; k < v.size(); ++k) {
            put(body, v[k], big);
            if (k == 1 && l.extra) put<std::int32_t>(body, -3, big);
        }
        if (l.extra) put(body, 0.25, big);
    }
    if (l.int_lists) {
        if (binary) {
            put<std::int32_t>(body, 3, big);
            for (std::int32_t k = 0; k < 3; ++k) put(body, k, big);
        } else {
            body += "3 0 1 2" + nl;
        }
    }
    std::string file = h + body;
    file.resize(file.size() - std::min(l.truncate, body.size()));
    return file;
}

class CliFiles : public ::testing::Test {
protected:
    Outcome hrsr(const std::string& args) { return testing::run(HRSR_EXE, args, folder_.root()); }
    std::string path(const std::string& name) const { return folder_.path(name); }

    /// Runs reconstruct on `name` (written with `bytes`) into out.ply and report.json; checks that
    /// the input is unchanged and that nothing but the input and (on success) both outputs exist.
    Outcome reconstruct(const std::string& name, const std::string& bytes,
                        const std::string& options = "") {
        fs::remove_all(folder_.root());
        fs::create_directories(folder_.root());
        folder_.write(name, bytes);
        const Outcome r = hrsr("reconstruct " + path(name) + " -q -o " + path("out.ply") +
                               " --report " + path("report.json") + " " + options);
        EXPECT_EQ(slurp(path(name)), bytes) << name << ": the input was modified";
        std::vector<std::string> expected{name};
        if (r.exit_code == 0) expected = {name, "out.ply", "report.json"};
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(folder_.entries(), expected) << name << ": " << r.err;
        return r;
    }

    void expect_failure(const std::string& name, const std::string& bytes,
                        const std::string& word) {
        const Outcome r = reconstruct(name, bytes);
        EXPECT_EQ(r.exit_code, 1) << name << ": " << r.err;
        EXPECT_EQ(r.err.rfind("hrsr: ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(word), std::string::npos) << name << ": " << r.err;
        EXPECT_EQ(lines(r.err), 1) << r.err;
    }

    /// The mesh written for `name`, which must succeed.
    std::string mesh_of(const std::string& name, const std::string& bytes,
                        const std::string& options = "") {
        const Outcome r = reconstruct(name, bytes, options);
        EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
        return slurp(path("out.ply"));
    }

    testing::TempFolder folder_;
    const PointSet sphere_ = testing::sample_sphere(1500);
};

// Big-endian, CRLF, extra properties and int list counts read as the plain file does.
TEST_F(CliFiles, EveryEncodingOfTheSameCloudGivesTheSameMesh) {
    const std::string reference = mesh_of("plain.ply", ply(sphere_, {}));
    EXPECT_GT(reference.size(), 1500u * 24);
    Layout l;
    l.crlf = true;
    EXPECT_EQ(mesh_of("crlf.ply", ply(sphere_, l)), reference);
    for (Layout::Format f : {Layout::Ascii, Layout::BinaryLittle, Layout::BinaryBig}) {
        l = {};
        l.format = f;
        EXPECT_EQ(mesh_of("format.ply", ply(sphere_, l)), reference) << f;
        l.extra = true; // their values reach the output (test_cli_attributes); not here
        EXPECT_EQ(mesh_of("extra.ply", ply(sphere_, l), "--no-attributes"), reference) << f;
        l.extra = false;
        l.int_lists = true;
        EXPECT_EQ(mesh_of("lists.ply", ply(sphere_, l)), reference) << f;
    }
}

TEST_F(CliFiles, MalformedFilesAreErrorsNamingTheProblem) {
    for (Layout::Format f : {Layout::Ascii, Layout::BinaryLittle, Layout::BinaryBig}) {
        Layout l;
        l.format = f;
        l.declared = long(sphere_.size()) + 10;
        expect_failure("count.ply", ply(sphere_, l), "truncated");
        l.declared = -1;
        // Binary: cut mid-value. Ascii: a number cut short is still a number, so cut values off.
        l.truncate = f == Layout::Ascii ? 40 : 5;
        expect_failure("truncated.ply", ply(sphere_, l), "truncated");
        l.truncate = 0;
        l.without_z = true;
        expect_failure("noz.ply", ply(sphere_, l), "'z'");
    }
    expect_failure("zero.ply", "", "empty");
    expect_failure("zero.xyz", "", "empty");
    expect_failure("zero.obj", "", "empty");
    std::string garbage;
    std::uint64_t x = 88172645463325252ull;
    for (int i = 0; i < 4096; ++i) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        garbage.push_back(char(x & 0xff));
    }
    expect_failure("garbage.ply", garbage, "ply");
    expect_failure("garbage.xyz", garbage, "line 1");
    expect_failure("garbage.obj", "v " + garbage, "line 1");
    expect_failure("header.ply",
                   "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + garbage, "header");
}

/// The cloud as PCD (float x y z, normals) in `data` ascii or binary.
std::string pcd(const PointSet& s, const std::string& data) {
    std::ostringstream out;
    out.precision(9);
    out << "VERSION 0.7\nFIELDS x y z normal_x normal_y normal_z\nSIZE 4 4 4 4 4 4\n"
           "TYPE F F F F F F\nCOUNT 1 1 1 1 1 1\nWIDTH "
        << s.size() << "\nHEIGHT 1\nPOINTS " << s.size() << "\nDATA " << data << "\n";
    for (std::size_t i = 0; i < s.size(); ++i) {
        float v[6];
        for (int k = 0; k < 3; ++k) {
            v[k] = float(s.positions[i][k]);
            v[3 + k] = float(s.normals[i][k]);
        }
        if (data == "binary") {
            out.write(reinterpret_cast<const char*>(v), sizeof v);
        } else {
            for (int k = 0; k < 6; ++k) out << v[k] << (k < 5 ? " " : "\n");
        }
    }
    return out.str();
}

/// The file `name` of the fuzz seeds (small valid files of each format).
std::string seed(const std::string& name) {
    return slurp(fs::path(HRSR_FUZZ_DATA) / name);
}

// PCD ascii and binary are the float PLY's mesh; PTS is the double XYZ's.
TEST_F(CliFiles, ScanFormatsGiveTheMeshOfThePlainFile) {
    const std::string reference = mesh_of("plain.ply", ply(sphere_, {}));
    EXPECT_EQ(mesh_of("binary.pcd", pcd(sphere_, "binary")), reference);
    EXPECT_EQ(mesh_of("ascii.pcd", pcd(sphere_, "ascii")), reference);
    std::ostringstream xyz, pts;
    xyz.precision(17);
    pts.precision(17);
    pts << sphere_.size() << "\n";
    for (const Vec3& p : sphere_.positions) {
        xyz << p[0] << " " << p[1] << " " << p[2] << "\n";
        pts << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    EXPECT_EQ(mesh_of("cloud.pts", pts.str()), mesh_of("cloud.xyz", xyz.str()));
}

TEST_F(CliFiles, MalformedScanFilesAreErrorsNamingTheProblem) {
    const std::string binary = pcd(sphere_, "binary");
    expect_failure("truncated.pcd", binary.substr(0, binary.size() - 7), "truncated");
    std::string type = binary;
    type.replace(type.find("TYPE F"), 6, "TYPE Q");
    expect_failure("type.pcd", type, "unknown type 'Q'");
    std::string count = binary;
    count.replace(count.find("POINTS "), 7, "POINTS 1");
    expect_failure("count.pcd", count, "wrong point count");
    const std::string compressed = seed("read_pcd/compressed.pcd");
    expect_failure("compressed.pcd", compressed.substr(0, compressed.size() - 9), "truncated");
    const std::string las = seed("read_las/format3.las");
    expect_failure("truncated.las", las.substr(0, las.size() - 3), "wrong point count");
    const std::string laz = seed("read_las/format3.laz");
    expect_failure("truncated.laz", laz.substr(0, laz.size() - 40), "truncated or corrupt");
    expect_failure("garbage.laz", "LASF" + std::string(300, 'x'), "unsupported LAS version");
    expect_failure("short.pts", "5\n0 0 0\n", "wrong point count");
}

// Usable files whose content is not: the core's errors, naming the file.
TEST_F(CliFiles, UnusableContentIsAnErrorNamingTheFile) {
    expect_failure("nan.xyz", "nan 0 0\n0 inf 0\n", "finite");
    expect_failure("same.xyz", std::string(100, ' ') + "\n1 2 3\n1 2 3\n1 2 3\n", "distinct");
    expect_failure("line.xyz", "0 0 0 0 0 1\n1 1 1 0 0 1\n2 2 2 0 0 1\n3 3 3 0 0 1\n",
                   "no triangle");
}

// An OBJ with fewer normals than vertices: the normals are estimated, with a warning.
TEST_F(CliFiles, NormalCountDifferentFromVertexCountIsAWarning) {
    std::ostringstream obj;
    obj.precision(17);
    for (const Vec3& p : sphere_.positions)
        obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    obj << "vn 0 0 1\nvn 0 1 0\n";
    const Outcome r = reconstruct("few_normals.obj", obj.str());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("2 normals for 1500 points"), std::string::npos) << r.err;
}

// A failed run leaves an existing output as it was; a successful one replaces it completely.
TEST_F(CliFiles, OutputsAreCompleteOrUntouched) {
    folder_.write("line.xyz", "0 0 0\n1 1 1\n2 2 2\n3 3 3\n");
    folder_.write("out.ply", "previous");
    Outcome r = hrsr("reconstruct " + path("line.xyz") + " -q -o " + path("out.ply"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(slurp(path("out.ply")), "previous");
    folder_.write("in.ply", ply(sphere_, {}));
    r = hrsr("reconstruct " + path("in.ply") + " -q -o " + path("out.ply"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string mesh = slurp(path("out.ply"));
    EXPECT_EQ(mesh.rfind("ply\n", 0), 0u);
    EXPECT_GT(mesh.size(), 1500u * 24);
    EXPECT_EQ(folder_.entries(), (std::vector<std::string>{"in.ply", "line.xyz", "out.ply"}));
}

// Item 4: three runs with every core, and runs with one and two threads, write the same bytes
// (HRsR, the default; RsR is checked in tests/cli).
TEST_F(CliFiles, SameBytesForRepeatedRunsAndAnyThreadCount) {
    std::vector<std::string> meshes;
    for (const char* threads : {"0", "0", "0", "1", "2"}) {
        const Outcome r = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " -q -o " +
                               path("m.ply") + " --threads " + threads);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        meshes.push_back(slurp(path("m.ply")));
    }
    EXPECT_GT(meshes[0].size(), 10000u * 24);
    for (std::size_t i = 1; i < meshes.size(); ++i) EXPECT_TRUE(meshes[i] == meshes[0]) << i;
}

} // namespace
} // namespace hrsr
