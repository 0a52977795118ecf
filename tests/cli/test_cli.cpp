// End-to-end tests of the hrsr command-line tool: exit codes, messages, outputs.
#include "cli_runner.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "samplers.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace hrsr {
namespace {

using testing::lines;
using testing::Outcome;
using testing::slurp;

class Cli : public ::testing::Test {
protected:
    // Runs hrsr with `args` (shell-quoted by the caller where needed), no stdin.
    Outcome hrsr(const std::string& args) { return testing::run(HRSR_EXE, args, folder_.root()); }
    std::string path(const std::string& name) const { return folder_.path(name); }
    void write(const std::string& name, const std::string& content) {
        folder_.write(name, content);
    }
    // Files in the test folder (to check that failures leave nothing behind).
    std::vector<std::string> files() const { return folder_.entries(); }

    testing::TempFolder folder_;
    const fs::path& dir_ = folder_.root();
};

TEST_F(Cli, HelpAndVersion) {
    Outcome r = hrsr("--help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("normals"), std::string::npos);
    r = hrsr("--version");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(r.out.rfind("hrsr ", 0), 0u);
    r = hrsr("normals --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* option : {"--k-normals", "--threads", "--report", "--output"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST_F(Cli, UsageErrorsExitWithTwoAndOneLine) {
    for (const std::string& args :
         {std::string(""), std::string("frobnicate"), std::string("normals"),
          "normals " + std::string(HRSR_SAMPLE),
          "normals " + std::string(HRSR_SAMPLE) + " -o x.ply --bogus",
          "normals " + std::string(HRSR_SAMPLE) + " -o x.ply --threads -3",
          "normals " + std::string(HRSR_SAMPLE) + " -o x.ply --distance sideways"}) {
        const Outcome r = hrsr(args);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_EQ(lines(r.err), 1) << args << ": " << r.err;
        EXPECT_EQ(r.err.rfind("hrsr: ", 0), 0u) << r.err;
    }
}

TEST_F(Cli, InvalidOptionValuesNameTheOption) {
    const Outcome r =
        hrsr("normals " + std::string(HRSR_SAMPLE) + " -o " + path("o.ply") + " --k 1");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("hrsr: --k must be between 3 and 1000 (got 1)"), std::string::npos)
        << r.err;
    EXPECT_EQ(files(), std::vector<std::string>{});
    // The core names options without a front end's spelling; the CLI words them as flags.
    const Outcome p = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " -o " + path("o.ply") +
                           " --collapse-ratio 2");
    EXPECT_EQ(p.exit_code, 2);
    EXPECT_NE(p.err.find("hrsr: --collapse-ratio must be in (0, 1]"), std::string::npos) << p.err;
    EXPECT_EQ(files(), std::vector<std::string>{});
}

TEST_F(Cli, NeverOverwritesTheInput) {
    fs::copy_file(HRSR_SAMPLE, path("in.ply"));
    const std::string before = slurp(path("in.ply"));
    for (const std::string& out : {path("in.ply"), dir_.string() + "/./in.ply"}) {
        const Outcome r = hrsr("normals " + path("in.ply") + " -o " + out);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_NE(r.err.find("refusing to overwrite"), std::string::npos) << r.err;
    }
    const Outcome r =
        hrsr("normals " + path("in.ply") + " -o " + path("o.ply") + " --report " + path("in.ply"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(slurp(path("in.ply")), before);
    EXPECT_EQ(files(), std::vector<std::string>{"in.ply"});
}

TEST_F(Cli, BadInputExitsWithOneNamingTheFileAndTheProblem) {
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 100\n"
                               "property float x\nproperty float y\nproperty float z\nend_header\n";
    write("truncated.ply", header + std::string(12 * 40, '\0'));
    write("lying.ply",
          "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
          "property float z\nend_header\n0 0 0\n1 0 0\n");
    write("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                     "end_header\n0 0\n");
    write("empty.ply",
          "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
          "property float z\nend_header\n");
    write("zero.xyz", "");
    write("garbage.ply", std::string("\x89PNG\r\n\x1a\n\0\0\0", 11));
    write("line.xyz", "0 0 0\n1 1 1\n2 2 2\n3 3 3\n4 4 4\n");
    const std::vector<std::pair<std::string, std::string>> cases{
        {"truncated.ply", "truncated"}, {"lying.ply", "truncated"}, {"noz.ply", "'z'"},
        {"empty.ply", "empty"},         {"zero.xyz", "empty"},      {"garbage.ply", "ply"},
        {"missing.ply", "cannot open"}, {"line.xyz", "line"}};
    for (const auto& [name, word] : cases) {
        const Outcome r = hrsr("normals " + path(name) + " -o " + path("out.ply") + " --report " +
                               path("r.json"));
        EXPECT_EQ(r.exit_code, 1) << name << ": " << r.err;
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(word), std::string::npos) << name << ": " << r.err;
        EXPECT_EQ(lines(r.err), 1) << r.err;
        EXPECT_FALSE(fs::exists(path("out.ply"))) << name;
        EXPECT_FALSE(fs::exists(path("r.json"))) << name;
    }
}

TEST_F(Cli, WritesKeptPointsAtInputCoordinatesWithUnitNormals) {
    // A sphere without normals, some NaNs, duplicates and a far cluster, written as XYZ text.
    PointSet s = testing::sample_sphere(3000, 1.0, Vec3(1e6, -2e6, 5e5));
    std::ostringstream xyz;
    xyz.precision(17);
    for (const Vec3& p : s.positions) xyz << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    xyz << "nan 0 0\n"
        << s.positions[10][0] << ' ' << s.positions[10][1] << ' ' << s.positions[10][2] << '\n';
    for (int i = 0; i < 5; ++i) xyz << 1e6 + i * 0.001 << " 3e6 0\n"; // far away, tiny
    write("in.xyz", xyz.str());
    const Outcome r = hrsr("normals " + path("in.xyz") + " -o " + path("out.ply") + " --report " +
                           path("r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("3000 written"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("warning"), std::string::npos);

    const PointSet in = io::read_point_set(path("in.xyz"));
    const PointSet out = io::read_point_set(path("out.ply"));
    ASSERT_EQ(out.size(), 3000u);
    ASSERT_EQ(out.normals.size(), 3000u);
    EXPECT_EQ(out.precision, CoordinatePrecision::Double);
    for (std::size_t i = 0; i < out.size(); ++i) {
        EXPECT_EQ(out.positions[i], in.positions[i]); // bit-exact, input order
        EXPECT_NEAR(out.normals[i].Norm(), 1.0, 1e-6);
    }
    const std::string report = slurp(path("r.json"));
    for (const char* key :
         {"\"non_finite\": 1", "\"merged_duplicates\": 1", "\"small_component\": 5",
          "\"origin\": \"estimated\"", "\"peak_memory_bytes\""})
        EXPECT_NE(report.find(key), std::string::npos) << key;
    EXPECT_EQ(files(), (std::vector<std::string>{"in.xyz", "out.ply", "r.json"}));
}

TEST_F(Cli, SameBytesForOneAndTwoThreads) {
    ASSERT_EQ(hrsr(std::string("normals ") + HRSR_SAMPLE + " -q --threads 1 -o " + path("a.ply"))
                  .exit_code,
              0);
    ASSERT_EQ(hrsr(std::string("normals ") + HRSR_SAMPLE + " -q --threads 2 -o " + path("b.ply"))
                  .exit_code,
              0);
    EXPECT_EQ(slurp(path("a.ply")), slurp(path("b.ply")));
    EXPECT_GT(slurp(path("a.ply")).size(), 10000u * 24);
}

// hrsr starts itself again once with glibc's huge pages asked for (apps/malloc_policy.h), unless
// GLIBC_TUNABLES names them: the arguments (a path with a space among them), the exit code, the
// messages and the mesh must be the same either way.
TEST_F(Cli, RestartForHugePagesChangesNothingButSpeed) {
    const std::string reconstruct = std::string("reconstruct ") + HRSR_SAMPLE + " -o ";
    const Outcome restarted = hrsr(reconstruct + "'" + path("a mesh.ply") + "'");
    const Outcome one_process =
        testing::run("GLIBC_TUNABLES=glibc.malloc.hugetlb=0 " + std::string(HRSR_EXE),
                     reconstruct + "'" + path("b mesh.ply") + "'", dir_);
    ASSERT_EQ(restarted.exit_code, 0) << restarted.err;
    ASSERT_EQ(one_process.exit_code, 0) << one_process.err;
    EXPECT_EQ(slurp(path("a mesh.ply")), slurp(path("b mesh.ply")));
    EXPECT_GT(slurp(path("a mesh.ply")).size(), 10000u * 24);
    EXPECT_EQ(lines(restarted.out), lines(one_process.out));
    const Outcome bad = hrsr("reconstruct '" + path("no such file.ply") + "' -o " + path("c.ply"));
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("no such file.ply"), std::string::npos) << bad.err;
}

} // namespace
} // namespace hrsr
