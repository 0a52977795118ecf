// Running MeshLab 2020.09's meshlabserver headless (xvfb-run) from a private prefix that loads
// our plugin (make_prefix.sh), and writing complete .mlx scripts for it.
#pragma once

#include "cli_runner.h"
#include "options.h"

#include <map>
#include <sstream>
#include <string>

namespace hrsr::testing {

/// A private MeshLab prefix in `folder` (made by make_prefix.sh with `plugin`, "-" for none);
/// meshlabserver runs with `folder` as its current folder (Screened Poisson writes temporary
/// files there).
class MeshLabServer {
public:
    MeshLabServer(const std::string& folder, const std::string& plugin) : folder_(folder) {
        const std::string cmd = "sh " + std::string(HRSR_PLUGIN_TESTS) + "/make_prefix.sh " +
                                plugin + " " + prefix() + " > /dev/null";
        created_ = std::system(cmd.c_str()) == 0;
    }
    bool created() const { return created_; }
    std::string prefix() const { return folder_ + "/prefix"; }
    /// meshlabserver `args` (no stdin); the log goes to log.txt when `args` has `-l log.txt`.
    Outcome run(const std::string& args) const {
        return testing::run("cd " + folder_ + " && xvfb-run -a " + prefix() + "/bin/meshlabserver",
                            args, folder_);
    }

private:
    std::string folder_;
    bool created_ = false;
};

/// The <filter> element of "Surface Reconstruction: HRsR" with every parameter (meshlabserver
/// 2020.09 asserts when one is missing), the core's defaults unless `values` names it.
inline std::string hrsr_filter(const std::map<std::string, std::string>& values = {}) {
    const ReconstructionOptions d;
    auto value = [&](const std::string& name, const auto& fallback) {
        const auto it = values.find(name);
        std::ostringstream s;
        if (it != values.end())
            s << it->second;
        else
            s << fallback;
        return "\"" + s.str() + "\"";
    };
    const char* two = " enum_cardinality=\"2\" enum_val0=\"a\" enum_val1=\"b\"";
    std::ostringstream f;
    f << " <filter name=\"Surface Reconstruction: HRsR\">\n"
      << "  <Param type=\"RichInt\" name=\"k\" value=" << value("k", d.rsr.preprocess.k) << "/>\n"
      << "  <Param type=\"RichDynamicFloat\" name=\"collapse_ratio\" value="
      << value("collapse_ratio", d.collapse.collapse_ratio) << " min=\"0.01\" max=\"1\"/>\n"
      << "  <Param type=\"RichAbsPerc\" name=\"l_min\" value=" << value("l_min", d.reexpand.l_min)
      << " min=\"0\" max=\"1000\"/>\n"
      << "  <Param type=\"RichInt\" name=\"handles\" value=" << value("handles", d.rsr.handles)
      << "/>\n"
      << "  <Param type=\"RichEnum\" name=\"method\" value=" << value("method", 0) << two << "/>\n"
      << "  <Param type=\"RichInt\" name=\"collapse_k\" value="
      << value("collapse_k", d.collapse.collapse_k) << "/>\n"
      << "  <Param type=\"RichFloat\" name=\"theta\" value="
      << value("theta", d.rsr.preprocess.theta_degrees) << "/>\n"
      << "  <Param type=\"RichFloat\" name=\"r\" value=" << value("r", d.rsr.preprocess.r) << "/>\n"
      << "  <Param type=\"RichInt\" name=\"n\" value=" << value("n", int(d.rsr.min_handle_loop))
      << "/>\n"
      << "  <Param type=\"RichEnum\" name=\"distance\" value=" << value("distance", 0) << two
      << "/>\n"
      << "  <Param type=\"RichEnum\" name=\"normals\" value=" << value("normals", 0) << two
      << "/>\n"
      << "  <Param type=\"RichBool\" name=\"select_dropped\" value="
      << value("select_dropped", "false") << "/>\n"
      << " </filter>\n";
    return f.str();
}

/// An .mlx script of the given <filter> elements.
inline std::string mlx(const std::string& filters) {
    return "<!DOCTYPE FilterScript>\n<FilterScript>\n" + filters + "</FilterScript>\n";
}

} // namespace hrsr::testing
