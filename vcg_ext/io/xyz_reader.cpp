// XYZ text reader: one point per line, "x y z" or "x y z nx ny nz"; '#' starts a comment line.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

namespace hrsr::io {
namespace {

using detail::fail;

PointSet read_xyz_unguarded(std::istream& in, const std::string& name) {
    PointSet points;
    points.precision = CoordinatePrecision::Double; // text may carry more than float precision
    detail::LineReader lines(in, name);
    std::size_t columns = 0;    // fixed by the first data line
    std::size_t first_line = 0; // that line, for error messages
    std::string_view line;
    while (lines.next(line)) {
        detail::Tokens tokens(line);
        std::string_view token;
        if (!tokens.next(token) || token[0] == '#') continue;
        double v[6] = {};
        std::size_t found = 0;
        do {
            double value = 0;
            if (!detail::parse_number(token, value)) {
                fail(name, "line " + std::to_string(lines.number()) + ": " + detail::quote(token) +
                               " is not a number");
            }
            if (found < 6) v[found] = value;
            ++found;
        } while (tokens.next(token));
        const std::string where = "line " + std::to_string(lines.number()) + ": ";
        if (found != 3 && found != 6) {
            fail(name, where + "expected 3 or 6 numbers, found " + std::to_string(found));
        }
        if (columns == 0) {
            columns = found;
            first_line = lines.number();
        } else if (found != columns) {
            fail(name, where + "found " + std::to_string(found) + " numbers, but line " +
                           std::to_string(first_line) + " has " + std::to_string(columns) +
                           " (every line must have the same columns)");
        }
        points.positions.emplace_back(v[0], v[1], v[2]);
        if (columns == 6) points.normals.emplace_back(v[3], v[4], v[5]);
    }
    return points;
}

} // namespace

PointSet read_xyz(std::istream& in, const std::string& name, const ReadOptions&) {
    return detail::guarded_read(name, [&] { return read_xyz_unguarded(in, name); });
}

} // namespace hrsr::io
