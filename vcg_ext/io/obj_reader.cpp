// OBJ point reader: only "v" and "vn" lines; faces, texture coordinates, groups, materials and
// everything else are ignored.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

namespace hrsr::io {
namespace {

using detail::fail;

/// The first three numbers after the keyword ("v x y z [w | r g b]"; extra values ignored).
Vec3 parse_triple(detail::Tokens& tokens, std::string_view keyword, const std::string& name,
                  std::size_t line) {
    double v[3] = {};
    std::string_view token;
    for (int k = 0; k < 3; ++k) {
        if (!tokens.next(token)) {
            fail(name, "line " + std::to_string(line) + ": '" + std::string(keyword) +
                           "' needs 3 numbers, found " + std::to_string(k));
        }
        if (!detail::parse_number(token, v[k])) {
            fail(name,
                 "line " + std::to_string(line) + ": " + detail::quote(token) + " is not a number");
        }
    }
    return Vec3(v[0], v[1], v[2]);
}

PointSet read_obj_unguarded(std::istream& in, const std::string& name) {
    PointSet points;
    points.precision = CoordinatePrecision::Double; // text may carry more than float precision
    detail::LineReader lines(in, name);
    std::string_view line;
    while (lines.next(line)) {
        detail::Tokens tokens(line);
        std::string_view keyword;
        if (!tokens.next(keyword)) continue;
        if (keyword == "v") {
            points.positions.push_back(parse_triple(tokens, keyword, name, lines.number()));
        } else if (keyword == "vn") {
            // Kept as read, even if their count differs from the vertices: the caller checks.
            points.normals.push_back(parse_triple(tokens, keyword, name, lines.number()));
        }
    }
    return points;
}

} // namespace

PointSet read_obj(std::istream& in, const std::string& name) {
    return detail::guarded_read(name, [&] { return read_obj_unguarded(in, name); });
}

} // namespace hrsr::io
