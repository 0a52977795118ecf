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

nlohmann::json largest_component_json(const MeshStats& m) {
    const ComponentTopology* c = largest_component(m);
    if (!c) return nullptr;
    return {{"vertices", c->vertices},
            {"faces", c->faces},
            {"genus", c->genus()},
            {"boundary_loops", c->boundary_loops}};
}

std::string largest_component_text(const MeshStats& m) {
    const ComponentTopology* c = largest_component(m);
    if (!c) return "";
    return "largest: " + std::to_string(c->faces) + " triangles, genus " +
           std::to_string(c->genus()) + ", " + std::to_string(c->boundary_loops) +
           " boundary loops";
}

} // namespace hrsr::app
