#include "mesh_summary.h"

namespace hrsr::app {

nlohmann::json genus_of_closed_components(const MeshStats& m) {
    nlohmann::json genus = nlohmann::json::array();
    for (const ComponentTopology& c : m.components)
        if (c.closed()) genus.push_back(c.genus());
    return genus;
}

std::string genus_of_closed_components_text(const MeshStats& m) {
    std::string genus;
    for (const ComponentTopology& c : m.components)
        if (c.closed()) genus += (genus.empty() ? "" : ", ") + std::to_string(c.genus());
    return genus.empty() ? "none" : genus;
}

} // namespace hrsr::app
