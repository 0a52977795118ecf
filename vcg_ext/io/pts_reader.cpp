// Leica PTS reader: blocks of "point count" lines followed by that many "x y z [intensity
// [r g b]]" lines (some writers leave out the intensity: "x y z r g b"). Intensity becomes a
// `short intensity` attribute when every value is an integer in range (Leica's -2048..2047),
// else a float; colour becomes uchar red green blue.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

#include <algorithm>

namespace hrsr::io {
namespace {

using detail::fail;

struct Block {
    std::uint64_t declared = 0; // the count line's number
    std::uint64_t read = 0;
    std::size_t line = 0; // of the count line
};

void check_block(const Block& b, const std::string& name) {
    if (b.read != b.declared)
        fail(name, "wrong point count: line " + std::to_string(b.line) + " says " +
                       std::to_string(b.declared) + " points, " + std::to_string(b.read) +
                       " follow");
}

void add_attributes(const std::vector<double>& intensity, const std::vector<double>& rgb,
                    PointSet& points, const std::string& name) {
    if (!intensity.empty()) {
        const bool integral = std::all_of(intensity.begin(), intensity.end(),
                                          [](double v) { return fits(ScalarType::Int16, v); });
        PointAttribute a("intensity", integral ? ScalarType::Int16 : ScalarType::Float32);
        for (const double v : intensity) a.append(v);
        points.attributes.push_back(std::move(a));
    }
    if (!rgb.empty()) {
        const char* const names[3] = {"red", "green", "blue"};
        for (std::size_t k = 0; k < 3; ++k) {
            PointAttribute a(names[k], ScalarType::UInt8);
            for (std::size_t i = 0; i < points.size(); ++i) {
                const double v = rgb[3 * i + k];
                if (!fits(ScalarType::UInt8, v))
                    fail(name, "point " + std::to_string(i + 1) + ": colour " + std::to_string(v) +
                                   " is not an integer 0-255");
                a.append(v);
            }
            points.attributes.push_back(std::move(a));
        }
    }
}

PointSet read_pts_unguarded(std::istream& in, const std::string& name, bool attributes) {
    PointSet points;
    points.precision = CoordinatePrecision::Double; // text may carry more than float precision
    detail::LineReader lines(in, name);
    std::vector<double> intensity, rgb;
    std::size_t columns = 0; // 3, 4, 6 or 7, fixed by the first point line
    Block block;
    bool in_block = false;
    std::string_view line;
    while (lines.next(line)) {
        detail::Tokens tokens(line);
        std::string_view token, first;
        double v[8] = {};
        std::size_t found = 0;
        const std::string where = "line " + std::to_string(lines.number()) + ": ";
        while (tokens.next(token)) {
            if (found == 0) first = token;
            if (found == 8 || !detail::parse_number(token, v[found]))
                fail(name, where + detail::quote(token) + " is not a number, or too many values");
            ++found;
        }
        if (found == 0) continue;
        if (found == 1) { // a count line opens a block
            if (in_block) check_block(block, name);
            block = {};
            block.line = lines.number();
            if (!detail::parse_count(first, block.declared))
                fail(name, where + "expected a point count");
            in_block = true;
            continue;
        }
        if (!in_block) fail(name, where + "points before the first point count line");
        if (found != 3 && found != 4 && found != 6 && found != 7)
            fail(name, where + "expected x y z [intensity [r g b]], found " +
                           std::to_string(found) + " numbers");
        if (columns == 0) columns = found;
        if (found != columns)
            fail(name, where + "found " + std::to_string(found) + " numbers, the first point has " +
                           std::to_string(columns));
        if (block.read == block.declared)
            fail(name, where + "wrong point count: line " + std::to_string(block.line) + " says " +
                           std::to_string(block.declared) + " points, more follow");
        ++block.read;
        points.positions.emplace_back(v[0], v[1], v[2]);
        if (!attributes) continue;
        if (columns == 4 || columns == 7) intensity.push_back(v[3]);
        if (columns >= 6) rgb.insert(rgb.end(), v + columns - 3, v + columns);
    }
    if (!in_block) fail(name, "no point count line: not a PTS file");
    check_block(block, name);
    add_attributes(intensity, rgb, points, name);
    return points;
}

} // namespace

PointSet read_pts(std::istream& in, const std::string& name, const ReadOptions& options) {
    return detail::guarded_read(name,
                                [&] { return read_pts_unguarded(in, name, options.attributes); });
}

} // namespace hrsr::io
