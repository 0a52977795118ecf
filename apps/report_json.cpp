#include "report_json.h"

#include "io/atomic_file.h"

namespace hrsr::app {

namespace {

const char* to_string(NormalOrigin origin) {
    return origin == NormalOrigin::Input ? "input" : "estimated";
}

nlohmann::json point_accounting(const PreprocessReport& r) {
    nlohmann::json dropped = nlohmann::json::object();
    nlohmann::json by_reason = nlohmann::json::object();
    for (PointFate f : {PointFate::NonFinite, PointFate::NoNormal, PointFate::SmallComponent}) {
        dropped[hrsr::to_string(f)] = r.count(f);
        by_reason[hrsr::to_string(f)] = nlohmann::json::array();
    }
    nlohmann::json merged = nlohmann::json::array();
    for (std::size_t i = 0; i < r.fate.size(); ++i) {
        if (r.fate[i] == PointFate::Kept) continue;
        if (r.fate[i] == PointFate::Duplicate)
            merged.push_back({i, r.duplicate_of[i]});
        else
            by_reason[hrsr::to_string(r.fate[i])].push_back(i);
    }
    return {{"input", r.input_points},
            {"kept", r.count(PointFate::Kept)},
            {"merged_duplicates", r.count(PointFate::Duplicate)},
            {"dropped", dropped},
            {"dropped_indices", by_reason},
            {"merged_into", merged}}; // [duplicate index, index of the kept point it merged into]
}

} // namespace

nlohmann::json to_json(const PreprocessReport& r) {
    nlohmann::json timings = nlohmann::json::array();
    for (const auto& [phase, seconds] : r.timings)
        timings.push_back({{"phase", phase}, {"seconds", seconds}});
    return {
        {"points", point_accounting(r)},
        {"normals",
         {{"origin", to_string(r.normal_origin)},
          {"fallback_reason", r.normals_fallback_reason},
          {"renormalised", r.normals_renormalised},
          {"opposed_to_nearest_neighbour", r.opposed_input_normals},
          {"turned_against_their_neighbours", r.turned_input_normals},
          {"pca_neighbours", r.pca_neighbours},
          {"pca_degenerate_copied", r.pca_degenerate},
          {"orientation_flips", r.orientation_flips},
          {"orientation_components", r.orientation_components}}},
        {"smoothing",
         {{"rounds", r.smoothing_rounds},
          {"neighbours", r.smoothing_neighbours},
          {"mean_shift_of_diagonal", r.smoothing_mean_shift},
          {"max_shift_of_diagonal", r.smoothing_max_shift},
          {"relative_noise", r.relative_noise},
          {"hrsr_on_smoothed_positions", r.denoised}}},
        {"components",
         {{"kept", r.components_kept},
          {"dropped", r.components_dropped},
          {"sizes", r.component_sizes},
          {"cut_length", r.cut_length},
          {"edges_cut", r.edges_cut},
          {"edges_beyond_input_reach", r.edges_beyond_input_reach}}},
        {"bbox_diagonal", r.bbox_diagonal},
        {"warnings", r.warnings},
        {"timings", timings},
    };
}

void write_json(const std::string& path, const nlohmann::json& document) {
    io::AtomicFile file(path);
    file.stream() << document.dump(2) << '\n';
    file.commit();
}

} // namespace hrsr::app
