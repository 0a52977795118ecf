// Running the hrsr executable from tests (HRSR_EXE is its path, defined by the build).
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace hrsr::testing {

struct Outcome {
    int exit_code;
    std::string out;
    std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline int lines(const std::string& s) {
    return int(std::count(s.begin(), s.end(), '\n'));
}

/// Runs `executable args` (shell-quoted by the caller where needed) with no stdin; stdout and
/// stderr go through files in `scratch`, which are removed afterwards.
inline Outcome run(const std::string& executable, const std::string& args,
                   const std::filesystem::path& scratch) {
    const std::filesystem::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
    const std::string cmd =
        executable + " " + args + " < /dev/null > " + out.string() + " 2> " + err.string();
    const int status = std::system(cmd.c_str());
    Outcome r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

} // namespace hrsr::testing
