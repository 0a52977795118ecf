// Several files read as one cloud (LiDAR arrives in tiles): same layout required of each.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

namespace hrsr::io {
namespace {

std::string attribute_list(const PointSet& points) {
    if (points.attributes.empty()) return "none";
    std::string list;
    for (const PointAttribute& a : points.attributes)
        list += (list.empty() ? "" : " ") + std::string(ply_type_name(a.type)) + " " + a.name;
    return list;
}

bool same_layout(const PointSet& a, const PointSet& b) {
    if (a.attributes.size() != b.attributes.size()) return false;
    for (std::size_t j = 0; j < a.attributes.size(); ++j)
        if (a.attributes[j].name != b.attributes[j].name ||
            a.attributes[j].type != b.attributes[j].type)
            return false;
    return true;
}

/// Appends `next` (read from `path`) to `all` (read from `first`).
void append(PointSet& all, PointSet&& next, const std::string& first, const std::string& path) {
    if (next.has_normals() != all.has_normals())
        detail::fail(path, std::string(next.has_normals() ? "has" : "has no") +
                               " normals, unlike " + first +
                               " (files read together must have the same fields)");
    if (!same_layout(all, next))
        detail::fail(path, "its per-point attributes (" + attribute_list(next) +
                               ") differ from those of " + first + " (" + attribute_list(all) +
                               "); files read together must have the same ones (or be read "
                               "without attributes)");
    all.positions.insert(all.positions.end(), next.positions.begin(), next.positions.end());
    all.normals.insert(all.normals.end(), next.normals.begin(), next.normals.end());
    for (std::size_t j = 0; j < all.attributes.size(); ++j)
        all.attributes[j].bytes.insert(all.attributes[j].bytes.end(),
                                       next.attributes[j].bytes.begin(),
                                       next.attributes[j].bytes.end());
    if (next.precision == CoordinatePrecision::Double) all.precision = CoordinatePrecision::Double;
    for (std::string& w : next.warnings) all.warnings.push_back(path + ": " + w);
}

} // namespace

PointSet read_point_sets(const std::vector<std::string>& paths, const ReadOptions& options) {
    if (paths.empty()) throw IoError("no input file given");
    PointSet all = read_point_set(paths[0], options);
    for (std::string& w : all.warnings) w = paths[0] + ": " + w;
    for (std::size_t f = 1; f < paths.size(); ++f) {
        PointSet next = read_point_set(paths[f], options);
        if (next.normals.size() != next.positions.size() && next.has_normals())
            detail::fail(paths[f], std::to_string(next.normals.size()) + " normals for " +
                                       std::to_string(next.positions.size()) + " points");
        append(all, std::move(next), paths[0], paths[f]);
    }
    return all;
}

} // namespace hrsr::io
