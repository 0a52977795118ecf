// PCD reader (the Point Cloud Library's format, v0.6/0.7): DATA ascii, binary and
// binary_compressed (LZF, through liblzf). x y z are the positions, normal_x/y/z the normals,
// packed rgb / rgba become uchar red green blue (alpha), every other single-valued field an
// attribute of its own type. Points with a NaN coordinate (the empty pixels of an organized
// cloud) are skipped: they were never measured.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

#ifdef HRSR_HAVE_LZF
extern "C" {
#include <liblzf/lzf.h>
}
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace hrsr::io {
namespace {

using detail::fail;
using detail::quote;

enum class Data { Ascii, Binary, Compressed };
enum class Role { Skip, X, Y, Z, NormalX, NormalY, NormalZ, PackedColour, Attribute };

struct Field {
    std::string name;
    char kind = 'F'; // I, U or F
    std::uint64_t size = 4;
    std::uint64_t count = 1;
    ScalarType type = ScalarType::Float32;
    Role role = Role::Attribute;
    std::size_t attribute = 0; // index in PointSet::attributes (Role::Attribute)
};

struct PcdHeader {
    std::vector<Field> fields;
    std::uint64_t width = 0, height = 1, points = 0;
    bool has_points = false;
    Data data = Data::Ascii;
    std::size_t lines = 0;

    std::uint64_t record_size() const {
        std::uint64_t size = 0;
        for (const Field& f : fields) size += f.size * f.count;
        return size;
    }
    std::uint64_t values_per_point() const {
        std::uint64_t n = 0;
        for (const Field& f : fields) n += f.count;
        return n;
    }
};

bool scalar_type(char kind, std::uint64_t size, ScalarType& type) {
    static const struct {
        char kind;
        std::uint64_t size;
        ScalarType type;
    } kTypes[] = {{'I', 1, ScalarType::Int8},    {'U', 1, ScalarType::UInt8},
                  {'I', 2, ScalarType::Int16},   {'U', 2, ScalarType::UInt16},
                  {'I', 4, ScalarType::Int32},   {'U', 4, ScalarType::UInt32},
                  {'F', 4, ScalarType::Float32}, {'F', 8, ScalarType::Float64}};
    for (const auto& t : kTypes)
        if (t.kind == kind && t.size == size) {
            type = t.type;
            return true;
        }
    return false;
}

/// The numbers after a header keyword, one per field.
std::vector<std::string_view> per_field(detail::Tokens tokens, const PcdHeader& h,
                                        std::string_view keyword, const std::string& name) {
    std::vector<std::string_view> words;
    std::string_view w;
    while (tokens.next(w)) words.push_back(w);
    if (words.size() != h.fields.size())
        fail(name, "header line " + std::to_string(h.lines) + ": " + std::string(keyword) +
                       " has " + std::to_string(words.size()) + " entries for " +
                       std::to_string(h.fields.size()) + " fields");
    return words;
}

std::uint64_t count_of(std::string_view word, const PcdHeader& h, const std::string& name) {
    std::uint64_t n = 0;
    if (!detail::parse_count(word, n))
        fail(name,
             "header line " + std::to_string(h.lines) + ": " + quote(word) + " is not a count");
    return n;
}

PcdHeader read_header(std::istream& in, const std::string& name) {
    PcdHeader h;
    std::string line;
    bool has_width = false, has_type = false, has_size = false;
    for (;;) {
        if (!std::getline(in, line)) {
            if (h.lines == 0) fail(name, in.bad() ? "read error" : "empty file (0 bytes)");
            fail(name, "the header ends before its DATA line");
        }
        ++h.lines;
        if (line.size() > 64 * 1024) fail(name, "header line too long: not a PCD file");
        detail::Tokens tokens(line);
        std::string_view key;
        if (!tokens.next(key) || key[0] == '#') continue;
        if (key == "VERSION" || key == "VIEWPOINT") continue;
        if (key == "FIELDS" || key == "COLUMNS") {
            std::string_view w;
            while (tokens.next(w)) h.fields.push_back({std::string(w)});
            if (h.fields.empty()) fail(name, "FIELDS names no field");
        } else if (key == "SIZE" || key == "TYPE" || key == "COUNT") {
            if (h.fields.empty()) fail(name, std::string(key) + " before FIELDS");
            const auto words = per_field(tokens, h, key, name);
            for (std::size_t i = 0; i < words.size(); ++i) {
                Field& f = h.fields[i];
                if (key == "SIZE") f.size = count_of(words[i], h, name);
                if (key == "COUNT") f.count = count_of(words[i], h, name);
                if (key == "TYPE") f.kind = words[i].size() == 1 ? words[i][0] : '?';
            }
            has_size = has_size || key == "SIZE";
            has_type = has_type || key == "TYPE";
        } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
            std::string_view w;
            if (!tokens.next(w)) fail(name, std::string(key) + " without a number");
            (key == "WIDTH"    ? h.width
             : key == "HEIGHT" ? h.height
                               : h.points) = count_of(w, h, name);
            has_width = has_width || key == "WIDTH";
            h.has_points = h.has_points || key == "POINTS";
        } else if (key == "DATA") {
            std::string_view w;
            tokens.next(w);
            if (w == "ascii") {
                h.data = Data::Ascii;
            } else if (w == "binary") {
                h.data = Data::Binary;
            } else if (w == "binary_compressed") {
                h.data = Data::Compressed;
            } else {
                fail(name,
                     "unknown DATA " + quote(w) + " (expected ascii, binary or binary_compressed)");
            }
            break;
        } else {
            fail(name, "header line " + std::to_string(h.lines) + ": unknown keyword " +
                           quote(key) + ": not a PCD file");
        }
    }
    if (h.fields.empty() || !has_size || !has_type || !has_width)
        fail(name, "the header lacks FIELDS, SIZE, TYPE or WIDTH");
    if (h.height != 0 && h.width > std::numeric_limits<std::uint64_t>::max() / h.height)
        fail(name, "WIDTH x HEIGHT is too large");
    if (!h.has_points) h.points = h.width * h.height;
    if (h.points != h.width * h.height)
        fail(name, "wrong point count: POINTS " + std::to_string(h.points) +
                       " but WIDTH x HEIGHT = " + std::to_string(h.width) + " x " +
                       std::to_string(h.height));
    return h;
}

/// Gives every field its role and type, and `points` its attributes.
void assign_roles(PcdHeader& h, PointSet& points, bool attributes, const std::string& name) {
    static const std::pair<const char*, Role> kRoles[] = {{"x", Role::X},
                                                          {"y", Role::Y},
                                                          {"z", Role::Z},
                                                          {"normal_x", Role::NormalX},
                                                          {"normal_y", Role::NormalY},
                                                          {"normal_z", Role::NormalZ},
                                                          {"rgb", Role::PackedColour},
                                                          {"rgba", Role::PackedColour}};
    for (Field& f : h.fields) {
        if (!scalar_type(f.kind, f.size, f.type))
            fail(name, "field " + quote(f.name) + " has an unknown type " +
                           quote(std::string(1, f.kind)) + " of size " + std::to_string(f.size) +
                           " (known: I and U of size 1, 2, 4; F of size 4, 8)");
        // Bounded so that record sizes cannot overflow (real clouds: histograms of a few hundred).
        if (f.count == 0 || f.count > (1u << 20))
            fail(name, "field " + quote(f.name) + " has COUNT " + std::to_string(f.count) +
                           " (1 to 1048576)");
        f.role = Role::Attribute;
        for (const auto& [n, role] : kRoles)
            if (f.name == n) f.role = role;
        if (f.name == "_") f.role = Role::Skip; // PCL's padding
        if (f.role != Role::Skip && f.count != 1) {
            points.warnings.push_back("field " + quote(f.name) + " has " + std::to_string(f.count) +
                                      " values per point; it is not carried to the output");
            f.role = Role::Skip;
        }
        if (f.role == Role::PackedColour && f.size != 4) f.role = Role::Attribute;
        if (!attributes && (f.role == Role::Attribute || f.role == Role::PackedColour))
            f.role = Role::Skip;
    }
    for (Role r : {Role::X, Role::Y, Role::Z})
        if (std::none_of(h.fields.begin(), h.fields.end(),
                         [r](const Field& f) { return f.role == r; }))
            fail(name, "no x, y and z fields");
    int normal_fields = 0;
    for (const Field& f : h.fields)
        normal_fields +=
            f.role == Role::NormalX || f.role == Role::NormalY || f.role == Role::NormalZ;
    if (normal_fields != 3)
        for (Field& f : h.fields)
            if (f.role == Role::NormalX || f.role == Role::NormalY || f.role == Role::NormalZ)
                f.role = Role::Skip;
    for (Field& f : h.fields) {
        if (f.role == Role::Attribute) {
            f.attribute = points.attributes.size();
            points.attributes.emplace_back(f.name, f.type);
        } else if (f.role == Role::PackedColour) {
            f.attribute = points.attributes.size();
            const bool alpha = f.name == "rgba";
            for (const char* c : {"red", "green", "blue", "alpha"})
                if (alpha || std::strcmp(c, "alpha") != 0)
                    points.attributes.emplace_back(c, ScalarType::UInt8);
        }
    }
    std::vector<std::string> names;
    for (const PointAttribute& a : points.attributes) {
        if (std::find(names.begin(), names.end(), a.name) != names.end())
            fail(name, "two fields give the per-point value " + quote(a.name));
        names.push_back(a.name);
    }
}

/// One point's first value of each field, as a double and (for packed colours) as 32 bits.
struct Value {
    double number = 0;
    std::uint32_t bits = 0;
};

Value decode(const unsigned char* p, const Field& f) {
    Value v;
    v.number = load_value(f.type, p);
    if (f.size == 4) std::memcpy(&v.bits, p, 4);
    return v;
}

/// Adds one point unless a coordinate is NaN (returns false then).
bool store(const PcdHeader& h, const std::vector<Value>& values, PointSet& points) {
    double xyz[3] = {}, normal[3] = {};
    for (std::size_t i = 0; i < h.fields.size(); ++i) {
        const Role r = h.fields[i].role;
        if (r >= Role::X && r <= Role::Z) xyz[int(r) - int(Role::X)] = values[i].number;
        if (r >= Role::NormalX && r <= Role::NormalZ)
            normal[int(r) - int(Role::NormalX)] = values[i].number;
    }
    if (std::isnan(xyz[0]) || std::isnan(xyz[1]) || std::isnan(xyz[2])) return false;
    points.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    for (std::size_t i = 0; i < h.fields.size(); ++i) {
        const Field& f = h.fields[i];
        if (f.role == Role::NormalX) points.normals.emplace_back(normal[0], normal[1], normal[2]);
        if (f.role == Role::Attribute) points.attributes[f.attribute].append(values[i].number);
        if (f.role == Role::PackedColour) {
            const std::uint32_t c = values[i].bits; // 0xAARRGGBB
            const int channels = f.name == "rgba" ? 4 : 3;
            const int shift[4] = {16, 8, 0, 24};
            for (int k = 0; k < channels; ++k)
                points.attributes[f.attribute + std::size_t(k)].append((c >> shift[k]) & 0xffu);
        }
    }
    return true;
}

void read_ascii(std::istream& in, PcdHeader& h, PointSet& points, const std::string& name,
                std::uint64_t& skipped) {
    detail::LineReader lines(in, name);
    std::string_view line;
    std::vector<Value> values(h.fields.size());
    std::uint64_t read = 0;
    while (lines.next(line)) {
        detail::Tokens tokens(line);
        std::string_view token;
        if (!tokens.next(token)) continue;
        const std::string where = "line " + std::to_string(h.lines + lines.number()) + ": ";
        if (read == h.points)
            fail(name, where + "wrong point count: more points than the header's " +
                           std::to_string(h.points));
        for (std::size_t i = 0; i < h.fields.size(); ++i) {
            const Field& f = h.fields[i];
            for (std::uint64_t k = 0; k < f.count; ++k) {
                if (k > 0 || i > 0) {
                    if (!tokens.next(token))
                        fail(name, where + "too few values (" +
                                       std::to_string(h.values_per_point()) + " expected)");
                }
                if (k > 0) continue;
                Value& v = values[i];
                const bool ok = f.kind == 'F' && f.size == 4
                                    ? [&] {
                                          float x = 0;
                                          const bool parsed = detail::parse_number(token, x);
                                          std::memcpy(&v.bits, &x, 4);
                                          v.number = x;
                                          return parsed;
                                      }()
                                    : detail::parse_number(token, v.number);
                if (!ok || (f.kind != 'F' && !fits(f.type, v.number)))
                    fail(name, where + quote(token) + " is not a value of field " + quote(f.name));
                if (f.kind != 'F')
                    v.bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(v.number));
            }
        }
        if (tokens.next(token))
            fail(name,
                 where + "too many values (" + std::to_string(h.values_per_point()) + " expected)");
        if (!store(h, values, points)) ++skipped;
        ++read;
    }
    if (read != h.points)
        fail(name, "wrong point count: the header says " + std::to_string(h.points) +
                       " points, the file has " + std::to_string(read));
}

/// Reads `n` bytes, which the header promises; fails naming `what` if the file is shorter.
std::vector<unsigned char> read_block(std::istream& in, std::uint64_t n, const std::string& what,
                                      const std::string& name) {
    const std::optional<std::uint64_t> left = detail::remaining_bytes(in);
    if (left && *left < n)
        fail(name, "truncated: " + what + " needs " + std::to_string(n) + " bytes, the file has " +
                       std::to_string(*left) + " left");
    // Where the stream cannot tell how much it holds, the block grows as its bytes arrive: a
    // header's claim allocates nothing the file does not hold.
    constexpr std::uint64_t kChunk = std::uint64_t(1) << 26;
    std::vector<unsigned char> bytes;
    while (bytes.size() < n) {
        const std::size_t at = bytes.size();
        const std::uint64_t want = left ? n : std::min<std::uint64_t>(n - at, kChunk);
        bytes.resize(at + static_cast<std::size_t>(want));
        in.read(reinterpret_cast<char*>(bytes.data() + at), static_cast<std::streamsize>(want));
        if (static_cast<std::uint64_t>(in.gcount()) != want)
            fail(name, "truncated: " + what + " ends after " +
                           std::to_string(at + std::size_t(in.gcount())) + " of " +
                           std::to_string(n) + " bytes");
    }
    return bytes;
}

std::uint32_t little_u32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}

/// The points, record after record (binary) or field after field (binary_compressed).
void read_binary(std::istream& in, PcdHeader& h, PointSet& points, const std::string& name,
                 std::uint64_t& skipped) {
    const std::uint64_t record = h.record_size();
    if (h.points > 0 && record > std::numeric_limits<std::uint64_t>::max() / h.points)
        fail(name, "wrong point count: POINTS x record size overflows");
    const std::uint64_t total = h.points * record;
    std::vector<unsigned char> data;
    if (h.data == Data::Binary) {
        data = read_block(in, total, std::to_string(h.points) + " points", name);
    } else {
#ifdef HRSR_HAVE_LZF
        const std::vector<unsigned char> sizes =
            read_block(in, 8, "the compressed block's sizes", name);
        const std::uint32_t packed = little_u32(sizes.data()),
                            unpacked = little_u32(sizes.data() + 4);
        if (unpacked != total)
            fail(name, "wrong point count: the header's " + std::to_string(h.points) +
                           " points of " + std::to_string(record) + " bytes are " +
                           std::to_string(total) + " bytes, the compressed block holds " +
                           std::to_string(unpacked));
        // LZF expands at most ~100x: a larger claim is corrupt (and must not allocate).
        // An empty block must not reach lzf_decompress: it reads one byte before it checks
        // the input's length.
        if ((unpacked > 0 && packed == 0) || unpacked > 128 * std::uint64_t(packed) + 1024)
            fail(name, "corrupt compressed block: " + std::to_string(packed) +
                           " bytes cannot hold " + std::to_string(unpacked));
        const std::vector<unsigned char> compressed =
            read_block(in, packed, "the compressed block", name);
        data.resize(unpacked);
        if (unpacked > 0 &&
            lzf_decompress(compressed.data(), packed, data.data(), unpacked) != unpacked)
            fail(name, "corrupt compressed block: LZF decompression failed");
#else
        fail(name, "DATA binary_compressed needs liblzf, which this hrsr was built without "
                   "(scripts/setup.sh installs liblzf-dev; rebuild)");
#endif
    }
    // Where field f of point i starts.
    std::vector<std::uint64_t> start(h.fields.size()), stride(h.fields.size());
    std::uint64_t offset = 0;
    for (std::size_t f = 0; f < h.fields.size(); ++f) {
        const std::uint64_t bytes = h.fields[f].size * h.fields[f].count;
        start[f] = h.data == Data::Binary ? offset : offset * h.points;
        stride[f] = h.data == Data::Binary ? record : bytes;
        offset += bytes;
    }
    std::vector<Value> values(h.fields.size());
    for (std::uint64_t i = 0; i < h.points; ++i) {
        for (std::size_t f = 0; f < h.fields.size(); ++f)
            values[f] = decode(data.data() + start[f] + i * stride[f], h.fields[f]);
        if (!store(h, values, points)) ++skipped;
    }
}

PointSet read_pcd_unguarded(std::istream& in, const std::string& name, bool attributes) {
    PcdHeader h = read_header(in, name);
    PointSet points;
    assign_roles(h, points, attributes, name);
    points.precision = std::all_of(h.fields.begin(), h.fields.end(),
                                   [](const Field& f) {
                                       return f.role < Role::X || f.role > Role::Z ||
                                              f.type == ScalarType::Float32;
                                   })
                           ? CoordinatePrecision::Float
                           : CoordinatePrecision::Double;
    std::uint64_t skipped = 0;
    if (h.data == Data::Ascii) {
        read_ascii(in, h, points, name, skipped);
    } else {
        read_binary(in, h, points, name, skipped);
    }
    if (skipped > 0)
        points.warnings.push_back(std::to_string(skipped) + " of " + std::to_string(h.points) +
                                  " points have NaN coordinates (not measured, e.g. empty pixels "
                                  "of an organized cloud) and were skipped");
    return points;
}

} // namespace

PointSet read_pcd(std::istream& in, const std::string& name, const ReadOptions& options) {
    return detail::guarded_read(name,
                                [&] { return read_pcd_unguarded(in, name, options.attributes); });
}

} // namespace hrsr::io
