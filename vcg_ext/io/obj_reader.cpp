// OBJ point reader: only "v" and "vn" lines (and the colour of "v x y z r g b"); faces, texture
// coordinates, groups, materials and everything else are ignored.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

#include <algorithm>
#include <cmath>

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

/// Vertex colours, as written by MeshLab and others after the position: r g b in [0, 1] (or,
/// by some writers, 0-255). They become uchar red/green/blue, the PLY convention.
class ObjColours {
public:
    /// Reads r g b if the line has exactly three more numbers ("v x y z w" has one).
    void read(detail::Tokens tokens) {
        std::string_view token;
        double rgb[3] = {};
        int found = 0;
        while (tokens.next(token)) {
            if (found == 3 || !detail::parse_number(token, rgb[found]) ||
                !std::isfinite(rgb[found])) {
                found = -1;
                break;
            }
            ++found;
        }
        if (found != 3) {
            all_coloured_ = false;
            return;
        }
        for (const double c : rgb) {
            values_.push_back(c);
            max_ = std::max(max_, c);
            negative_ = negative_ || c < 0;
        }
    }

    /// The colour attributes if every vertex has a colour in range, else none (with a warning
    /// if only some vertices have one).
    void finish(std::size_t vertices, PointSet& points) const {
        if (values_.empty()) return;
        if (!all_coloured_ || values_.size() != 3 * vertices || negative_ || max_ > 255) {
            points.warnings.push_back(
                "vertex colours are left out: not every 'v' line has an r g b in [0, 1] or 0-255");
            return;
        }
        const double scale = max_ <= 1 ? 255.0 : 1.0;
        const char* const names[3] = {"red", "green", "blue"};
        for (int k = 0; k < 3; ++k) {
            PointAttribute a(names[k], ScalarType::UInt8);
            a.bytes.reserve(vertices);
            for (std::size_t i = 0; i < vertices; ++i)
                a.append(std::round(values_[3 * i + static_cast<std::size_t>(k)] * scale));
            points.attributes.push_back(std::move(a));
        }
    }

private:
    std::vector<double> values_;
    double max_ = 0;
    bool negative_ = false;
    bool all_coloured_ = true;
};

PointSet read_obj_unguarded(std::istream& in, const std::string& name, bool attributes) {
    PointSet points;
    ObjColours colours;
    points.precision = CoordinatePrecision::Double; // text may carry more than float precision
    detail::LineReader lines(in, name);
    std::string_view line;
    while (lines.next(line)) {
        detail::Tokens tokens(line);
        std::string_view keyword;
        if (!tokens.next(keyword)) continue;
        if (keyword == "v") {
            points.positions.push_back(parse_triple(tokens, keyword, name, lines.number()));
            if (attributes) colours.read(tokens);
        } else if (keyword == "vn") {
            // Kept as read, even if their count differs from the vertices: the caller checks.
            points.normals.push_back(parse_triple(tokens, keyword, name, lines.number()));
        }
    }
    if (attributes) colours.finish(points.positions.size(), points);
    return points;
}

} // namespace

PointSet read_obj(std::istream& in, const std::string& name, const ReadOptions& options) {
    return detail::guarded_read(name,
                                [&] { return read_obj_unguarded(in, name, options.attributes); });
}

} // namespace hrsr::io
