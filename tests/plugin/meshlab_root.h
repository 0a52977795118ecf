// Running meshlab_host (filter_hrsr/host) with our plugin inside a MeshLab root made by
// scripts/root/ (HRSR_MESHLAB_ROOT: its folder on the host), through scripts/root/in_root.sh.
#pragma once

#include "cli_runner.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace hrsr::testing {

class MeshLabRoot {
public:
    /// A fresh work folder at /tmp/hrsr_test_<pid>_<n> inside the root, removed afterwards.
    MeshLabRoot() {
        const char* root = std::getenv("HRSR_MESHLAB_ROOT");
        root_ = root ? root : "";
        static int counter = 0;
        inside_ = "/tmp/hrsr_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++);
        if (!root_.empty()) std::filesystem::create_directories(path(""));
    }
    ~MeshLabRoot() {
        std::error_code ec;
        if (!root_.empty()) std::filesystem::remove_all(path(""), ec);
    }
    MeshLabRoot(const MeshLabRoot&) = delete;
    MeshLabRoot& operator=(const MeshLabRoot&) = delete;

    bool exists() const {
        return !root_.empty() && std::filesystem::exists(root_ + "/hrsr/build/filter_hrsr/host");
    }
    /// `file` of the work folder as the host sees it, and as the root sees it.
    std::string path(const std::string& file) const { return root_ + inside_ + "/" + file; }
    std::string inside(const std::string& file) const { return inside_ + "/" + file; }

    /// `command args` run inside the root (shell-quoted by the caller).
    Outcome run(const std::string& command, const std::string& args) const {
        return testing::run("bash " + std::string(HRSR_SOURCE_DIR) + "/scripts/root/in_root.sh " +
                                root_ + " " + command,
                            args, path(""));
    }
    /// meshlab_host with the plugin built in the root ("-": only the installed plugins) and the
    /// filter "Surface Reconstruction: HRsR" (or its PyMeshLab name); `args` as meshlab_host
    /// takes them.
    Outcome host(const std::string& args, const std::string& plugin = kPlugin,
                 const std::string& filter = "'Surface Reconstruction: HRsR'") const {
        return run("/hrsr/build/filter_hrsr/host/meshlab_host", plugin + " " + filter + " " + args);
    }
    static constexpr const char* kPlugin = "/hrsr/build/filter_hrsr/libfilter_hrsr.so";

private:
    std::string root_, inside_;
};

} // namespace hrsr::testing
