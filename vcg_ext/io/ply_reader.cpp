// PLY reader: ascii and binary (both endiannesses), any element layout. Reads the vertex
// element's x/y/z (and nx/ny/nz when all three exist), every other scalar vertex property as a
// point attribute and, for meshes, the face element's vertex_indices (or vertex_index) list;
// everything else is skipped.
#include "io/mesh_reader.h"
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

namespace hrsr::io {
namespace {

using detail::fail;
using detail::quote;

enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };
/// The PLY scalar types are the attribute types (point_attributes.h).
using Type = ScalarType;

bool is_integer(Type type) {
    return type != Type::Float32 && type != Type::Float64;
}

bool parse_type(std::string_view word, Type& type) {
    static const std::pair<std::string_view, Type> kNames[] = {
        {"char", Type::Int8},       {"int8", Type::Int8},       {"uchar", Type::UInt8},
        {"uint8", Type::UInt8},     {"short", Type::Int16},     {"int16", Type::Int16},
        {"ushort", Type::UInt16},   {"uint16", Type::UInt16},   {"int", Type::Int32},
        {"int32", Type::Int32},     {"uint", Type::UInt32},     {"uint32", Type::UInt32},
        {"float", Type::Float32},   {"float32", Type::Float32}, {"double", Type::Float64},
        {"float64", Type::Float64},
    };
    for (const auto& [n, t] : kNames) {
        if (n == word) {
            type = t;
            return true;
        }
    }
    return false;
}

struct Property {
    std::string name;
    Type type = Type::Float32; // the item type for lists
    bool is_list = false;
    Type count_type = Type::UInt8;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;

    bool has_lists() const {
        return std::any_of(properties.begin(), properties.end(),
                           [](const Property& p) { return p.is_list; });
    }
    /// Bytes of one binary item, counting lists as their count only.
    std::size_t min_item_size() const {
        std::size_t size = 0;
        for (const Property& p : properties) size += size_of(p.is_list ? p.count_type : p.type);
        return size;
    }
};

struct Header {
    Format format = Format::Ascii;
    std::vector<Element> elements;
    std::size_t line_count = 0;
};

// ---------------------------------------------------------------------------------------------
// Buffered input

/// The file's bytes through a large buffer: one istream call per block, not per value, and
/// records handed out as contiguous memory.
class ByteSource {
public:
    explicit ByteSource(std::istream& in) : in_(in), buffer_(kBlockSize) {}

    /// Makes `n` contiguous bytes available at data(); false if the stream ends first.
    bool ensure(std::size_t n) { return end_ - pos_ >= n || refill(n); }
    const unsigned char* data() const { return buffer_.data() + pos_; }
    std::size_t available() const { return end_ - pos_; }
    void consume(std::size_t n) { pos_ += n; }
    bool read_failed() const { return in_.bad(); }

    /// Skips up to `n` bytes; returns how many there were.
    std::uint64_t skip(std::uint64_t n) {
        std::uint64_t skipped = 0;
        while (skipped < n && (pos_ < end_ || refill(1))) {
            const auto step = static_cast<std::size_t>(
                std::min<std::uint64_t>(n - skipped, static_cast<std::uint64_t>(end_ - pos_)));
            pos_ += step;
            skipped += step;
        }
        return skipped;
    }

    /// The number of bytes left, when the stream can tell (seekable, or read to its end).
    std::optional<std::uint64_t> remaining() {
        if (at_end_) return available();
        const std::streampos here = in_.tellg();
        if (here == std::streampos(-1)) return std::nullopt;
        in_.seekg(0, std::ios::end);
        const std::streampos end = in_.fail() ? std::streampos(-1) : in_.tellg();
        in_.clear();
        in_.seekg(here);
        if (end == std::streampos(-1) || end < here) return std::nullopt;
        return available() + static_cast<std::uint64_t>(end - here);
    }

private:
    static constexpr std::size_t kBlockSize = std::size_t(1) << 20;

    bool refill(std::size_t n) {
        if (pos_ > 0) {
            std::memmove(buffer_.data(), buffer_.data() + pos_, end_ - pos_);
            end_ -= pos_;
            pos_ = 0;
        }
        if (buffer_.size() < n) buffer_.resize(std::max(n, 2 * buffer_.size()));
        while (end_ < n && !at_end_) {
            in_.read(reinterpret_cast<char*>(buffer_.data() + end_),
                     static_cast<std::streamsize>(buffer_.size() - end_));
            end_ += static_cast<std::size_t>(in_.gcount());
            if (!in_) at_end_ = true;
        }
        return end_ >= n;
    }

    std::istream& in_;
    std::vector<unsigned char> buffer_;
    std::size_t pos_ = 0;
    std::size_t end_ = 0;
    bool at_end_ = false;
};

// ---------------------------------------------------------------------------------------------
// Header

enum class LineStatus { Ok, End, TooLong };

/// One header line without "\n" or "\r\n".
LineStatus read_line(ByteSource& src, std::string& line) {
    constexpr std::size_t kMaxLine = 64 * 1024;
    std::size_t scanned = 0;
    for (;;) {
        const auto* begin = src.data();
        const void* newline = std::memchr(begin + scanned, '\n', src.available() - scanned);
        if (newline != nullptr) {
            const auto length =
                static_cast<std::size_t>(static_cast<const unsigned char*>(newline) - begin);
            line.assign(reinterpret_cast<const char*>(begin), length);
            src.consume(length + 1);
            break;
        }
        scanned = src.available();
        if (scanned > kMaxLine) return LineStatus::TooLong;
        if (!src.ensure(scanned + 1)) {
            if (scanned == 0) return LineStatus::End;
            line.assign(reinterpret_cast<const char*>(src.data()), scanned);
            src.consume(scanned);
            break;
        }
    }
    while (!line.empty() && detail::is_space(line.back())) line.pop_back();
    return LineStatus::Ok;
}

class HeaderParser {
public:
    explicit HeaderParser(const std::string& name) : name_(name) {}

    Header parse(ByteSource& src);

private:
    /// Returns true at end_header.
    bool parse_line(std::string_view line);
    void parse_format(detail::Tokens& tokens);
    void parse_element(detail::Tokens& tokens);
    void parse_property(detail::Tokens& tokens);
    Type expect_type(detail::Tokens& tokens, const char* what);
    [[noreturn]] void error(const std::string& what) const {
        fail(name_, "header line " + std::to_string(header_.line_count) + ": " + what);
    }

    const std::string& name_;
    Header header_;
    bool has_format_ = false;
};

Header HeaderParser::parse(ByteSource& src) {
    if (!src.ensure(1)) fail(name_, src.read_failed() ? "read error" : "empty file (0 bytes)");
    std::string line;
    if (!src.ensure(3) || std::memcmp(src.data(), "ply", 3) != 0 ||
        read_line(src, line) != LineStatus::Ok || line != "ply") {
        fail(name_, "not a PLY file (the first line is not 'ply')");
    }
    header_.line_count = 1;
    for (;;) {
        const LineStatus status = read_line(src, line);
        ++header_.line_count;
        if (status == LineStatus::TooLong) error("line too long; the header is malformed");
        if (status == LineStatus::End) {
            if (src.read_failed()) fail(name_, "read error in the header");
            fail(name_, "missing end_header: the file ends inside the header");
        }
        if (parse_line(line)) break;
    }
    if (!has_format_) fail(name_, "the header has no 'format' line");
    return std::move(header_);
}

bool HeaderParser::parse_line(std::string_view line) {
    detail::Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) return false; // blank line
    if (keyword == "end_header") return true;
    if (keyword == "comment" || keyword == "obj_info") return false;
    if (keyword == "format") {
        parse_format(tokens);
    } else if (keyword == "element") {
        parse_element(tokens);
    } else if (keyword == "property") {
        parse_property(tokens);
    } else {
        error("unrecognised header line starting with " + quote(keyword));
    }
    return false;
}

void HeaderParser::parse_format(detail::Tokens& tokens) {
    std::string_view format;
    std::string_view version;
    if (!tokens.next(format)) error("'format' without a format");
    if (format == "ascii") {
        header_.format = Format::Ascii;
    } else if (format == "binary_little_endian") {
        header_.format = Format::BinaryLittleEndian;
    } else if (format == "binary_big_endian") {
        header_.format = Format::BinaryBigEndian;
    } else {
        error("unknown format " + quote(format) +
              " (expected ascii, binary_little_endian or binary_big_endian)");
    }
    double number = 0;
    if (tokens.next(version) && !(detail::parse_number(version, number) && number == 1.0)) {
        error("unsupported format version " + quote(version) + " (expected 1.0)");
    }
    has_format_ = true;
}

void HeaderParser::parse_element(detail::Tokens& tokens) {
    std::string_view element_name;
    std::string_view count;
    if (!tokens.next(element_name) || !tokens.next(count)) {
        error("'element' needs a name and a count");
    }
    Element element;
    element.name = std::string(element_name);
    if (!detail::parse_count(count, element.count)) {
        error("invalid count " + quote(count) + " for element " + quote(element_name));
    }
    header_.elements.push_back(std::move(element));
}

Type HeaderParser::expect_type(detail::Tokens& tokens, const char* what) {
    std::string_view word;
    if (!tokens.next(word)) error(std::string("'property' without ") + what);
    Type type{};
    if (!parse_type(word, type)) error("unknown property type " + quote(word));
    return type;
}

void HeaderParser::parse_property(detail::Tokens& tokens) {
    if (header_.elements.empty()) error("'property' before any 'element'");
    Property property;
    std::string_view word;
    detail::Tokens lookahead = tokens;
    if (lookahead.next(word) && word == "list") {
        tokens = lookahead;
        property.is_list = true;
        property.count_type = expect_type(tokens, "a list count type");
        if (!is_integer(property.count_type)) error("the count type of a list must be an integer");
    }
    property.type = expect_type(tokens, "a type");
    if (!tokens.next(word)) error("'property' without a name");
    property.name = std::string(word);
    header_.elements.back().properties.push_back(std::move(property));
}

// ---------------------------------------------------------------------------------------------
// Vertex layout

constexpr int kAbsent = -1;
constexpr std::size_t kNoList = std::numeric_limits<std::size_t>::max();

/// Where x y z nx ny nz and the attributes are among the vertex properties. Values are read
/// into an array: x..nz at 0..5, attribute j at kFirstAttribute + j.
constexpr int kFirstAttribute = 6;

struct VertexLayout {
    std::array<int, 6> index{kAbsent, kAbsent, kAbsent, kAbsent, kAbsent, kAbsent};
    int wanted = 3; // 6 with normals
    CoordinatePrecision precision = CoordinatePrecision::Double;
    std::vector<std::size_t> attribute_property; ///< the property of each attribute

    std::size_t value_count() const { return kFirstAttribute + attribute_property.size(); }

    /// For each property, where its value goes (or kAbsent).
    std::vector<int> targets(std::size_t property_count) const {
        std::vector<int> t(property_count, kAbsent);
        for (int k = 0; k < wanted; ++k) t[static_cast<std::size_t>(index[k])] = k;
        for (std::size_t j = 0; j < attribute_property.size(); ++j)
            t[attribute_property[j]] = kFirstAttribute + static_cast<int>(j);
        return t;
    }
};

bool is_geometry(const std::string& property) {
    for (const char* g : {"x", "y", "z", "nx", "ny", "nz"})
        if (property == g) return true;
    return false;
}

/// Every scalar vertex property except x..nz becomes an attribute (its first occurrence, if a
/// name repeats); lists cannot be a per-vertex value of the mesh and are left out with a warning.
void choose_attributes(const Element& vertex, VertexLayout& layout, PointSet& points) {
    std::vector<std::string> seen;
    for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
        const Property& p = vertex.properties[i];
        if (is_geometry(p.name)) continue;
        if (p.is_list) {
            points.warnings.push_back("vertex property " + quote(p.name) +
                                      " is a list; it is not carried to the output");
            continue;
        }
        if (std::find(seen.begin(), seen.end(), p.name) != seen.end()) {
            points.warnings.push_back("vertex property " + quote(p.name) +
                                      " appears twice; only the first is carried to the output");
            continue;
        }
        seen.push_back(p.name);
        layout.attribute_property.push_back(i);
        points.attributes.emplace_back(p.name, p.type);
    }
}

VertexLayout vertex_layout(const Element& vertex, const std::string& name) {
    static const char* const kNames[6] = {"x", "y", "z", "nx", "ny", "nz"};
    VertexLayout layout;
    for (int k = 0; k < 6; ++k) {
        for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
            if (vertex.properties[i].name != kNames[k]) continue;
            if (vertex.properties[i].is_list) {
                fail(name,
                     std::string("vertex property '") + kNames[k] + "' is a list, not a number");
            }
            layout.index[k] = static_cast<int>(i);
            break;
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (layout.index[k] == kAbsent) {
            fail(name, std::string("vertex element has no '") + kNames[k] + "' property");
        }
    }
    const bool normals =
        layout.index[3] != kAbsent && layout.index[4] != kAbsent && layout.index[5] != kAbsent;
    layout.wanted = normals ? 6 : 3;
    const auto is_float = [&](int k) {
        return vertex.properties[static_cast<std::size_t>(layout.index[k])].type == Type::Float32;
    };
    layout.precision = is_float(0) && is_float(1) && is_float(2) ? CoordinatePrecision::Float
                                                                 : CoordinatePrecision::Double;
    return layout;
}

/// Reserves room for the vertices, but never more than the rest of the file can hold: a header
/// may claim 10^15 vertices.
void reserve_vertices(PointSet& points, std::uint64_t count, std::size_t min_item_bytes,
                      std::optional<std::uint64_t> remaining, bool normals) {
    constexpr std::uint64_t kUnknownSizeReserve = 1 << 16;
    std::uint64_t n = count;
    if (remaining) {
        n = std::min(n, *remaining / std::max<std::size_t>(min_item_bytes, 1));
    } else {
        n = std::min(n, kUnknownSizeReserve);
    }
    points.positions.reserve(static_cast<std::size_t>(n));
    if (normals) points.normals.reserve(static_cast<std::size_t>(n));
    for (PointAttribute& a : points.attributes)
        a.bytes.reserve(static_cast<std::size_t>(n) * size_of(a.type));
}

std::string item_label(const Element& element, std::uint64_t item) {
    const std::string quoted = quote(element.name); // names come from the file: sanitise
    return quoted.substr(1, quoted.size() - 2) + " " + std::to_string(item + 1) + " of " +
           std::to_string(element.count);
}

/// Appends one vertex. Attribute values from ascii text may not fit their declared type.
void store(PointSet& points, const double* v, const VertexLayout& layout, const Element& vertex,
           std::uint64_t item, const std::string& name) {
    points.positions.emplace_back(v[0], v[1], v[2]);
    if (layout.wanted == 6) points.normals.emplace_back(v[3], v[4], v[5]);
    for (std::size_t j = 0; j < points.attributes.size(); ++j) {
        PointAttribute& a = points.attributes[j];
        const double value = v[kFirstAttribute + j];
        if (!fits(a.type, value))
            fail(name, item_label(vertex, item) + ", property " + quote(a.name) + ": " +
                           std::to_string(value) + " is not a " + ply_type_name(a.type) + " value");
        a.append(value);
    }
}

// ---------------------------------------------------------------------------------------------
// Binary data

bool host_is_big_endian() {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 0;
}

template <class U>
U load_bits(const unsigned char* p, bool swap) {
    U u;
    std::memcpy(&u, p, sizeof u);
    if (swap) {
        U r = 0;
        for (std::size_t i = 0; i < sizeof u; ++i) {
            r = static_cast<U>((r << 8) | ((u >> (8 * i)) & 0xffu));
        }
        u = r;
    }
    return u;
}

double load_scalar(const unsigned char* p, Type type, bool swap) {
    switch (type) {
    case Type::Int8:
        return static_cast<std::int8_t>(p[0]);
    case Type::UInt8:
        return p[0];
    case Type::Int16:
        return static_cast<std::int16_t>(load_bits<std::uint16_t>(p, swap));
    case Type::UInt16:
        return load_bits<std::uint16_t>(p, swap);
    case Type::Int32:
        return static_cast<std::int32_t>(load_bits<std::uint32_t>(p, swap));
    case Type::UInt32:
        return load_bits<std::uint32_t>(p, swap);
    case Type::Float32: {
        const std::uint32_t bits = load_bits<std::uint32_t>(p, swap);
        float f;
        std::memcpy(&f, &bits, sizeof f);
        return f;
    }
    case Type::Float64: {
        const std::uint64_t bits = load_bits<std::uint64_t>(p, swap);
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
    }
    }
    return 0;
}

class BinaryReader {
public:
    BinaryReader(ByteSource& src, Format format, const std::string& name)
        : src_(src), swap_((format == Format::BinaryBigEndian) != host_is_big_endian()),
          name_(name) {}

    void skip_element(const Element& element);
    void read_vertices(const Element& vertex, const VertexLayout& layout, PointSet& points);
    /// Reads one item property by property (needed when it has lists); values[targets[i]]
    /// receives property i when targets[i] != kAbsent, and `list` the items of the list
    /// property `list_property` (if any). Throws a "truncated" error if the data ends first.
    void read_item(const Element& element, std::uint64_t item, const std::vector<int>& targets,
                   double* values, std::size_t list_property, std::vector<double>* list) {
        if (!try_read_item(element, item, targets, values, list_property, list))
            truncated(element, item);
    }

private:
    bool try_read_item(const Element& element, std::uint64_t item, const std::vector<int>& targets,
                       double* values, std::size_t list_property = kNoList,
                       std::vector<double>* list = nullptr);
    void read_fixed_vertices(const Element& vertex, const VertexLayout& layout, PointSet& points);
    [[noreturn]] void truncated(const Element& element, std::uint64_t item) const {
        if (src_.read_failed()) fail(name_, "read error in " + item_label(element, item));
        fail(name_, "truncated binary data: " + item_label(element, item) + " is incomplete");
    }

    ByteSource& src_;
    bool swap_;
    const std::string& name_;
};

void BinaryReader::skip_element(const Element& element) {
    if (element.properties.empty() || element.count == 0) return;
    if (element.has_lists()) {
        const std::vector<int> none(element.properties.size(), kAbsent);
        for (std::uint64_t i = 0; i < element.count; ++i) {
            if (!try_read_item(element, i, none, nullptr)) truncated(element, i);
        }
        return;
    }
    const std::uint64_t size = element.min_item_size();
    // A lying count may overflow count * size; such data cannot exist anyway.
    const std::uint64_t items =
        std::min(element.count, std::numeric_limits<std::uint64_t>::max() / size);
    const std::uint64_t skipped = src_.skip(items * size);
    if (skipped < items * size || items < element.count) truncated(element, skipped / size);
}

bool BinaryReader::try_read_item(const Element& element, std::uint64_t item,
                                 const std::vector<int>& targets, double* values,
                                 std::size_t list_property, std::vector<double>* list) {
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
        const Property& property = element.properties[i];
        if (!property.is_list) {
            const std::size_t size = size_of(property.type);
            if (!src_.ensure(size)) return false;
            if (targets[i] != kAbsent) {
                values[targets[i]] = load_scalar(src_.data(), property.type, swap_);
            }
            src_.consume(size);
            continue;
        }
        const std::size_t count_size = size_of(property.count_type);
        if (!src_.ensure(count_size)) return false;
        const double count = load_scalar(src_.data(), property.count_type, swap_);
        if (count < 0) {
            fail(name_, "negative list length " + std::to_string(static_cast<long long>(count)) +
                            " in " + item_label(element, item) + ", property '" + property.name +
                            "'");
        }
        src_.consume(count_size);
        if (i == list_property && list != nullptr) {
            const std::size_t size = size_of(property.type);
            list->clear();
            for (std::uint64_t j = 0, n = static_cast<std::uint64_t>(count); j < n; ++j) {
                if (!src_.ensure(size)) return false;
                list->push_back(load_scalar(src_.data(), property.type, swap_));
                src_.consume(size);
            }
            continue;
        }
        const auto bytes = static_cast<std::uint64_t>(count) * size_of(property.type);
        if (src_.skip(bytes) != bytes) return false;
    }
    return true;
}

void BinaryReader::read_vertices(const Element& vertex, const VertexLayout& layout,
                                 PointSet& points) {
    reserve_vertices(points, vertex.count, vertex.min_item_size(), src_.remaining(),
                     layout.wanted == 6);
    if (!vertex.has_lists()) {
        read_fixed_vertices(vertex, layout, points);
        return;
    }
    const std::vector<int> targets = layout.targets(vertex.properties.size());
    std::vector<double> values(layout.value_count());
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
        if (!try_read_item(vertex, i, targets, values.data())) truncated(vertex, i);
        store(points, values.data(), layout, vertex, i, name_);
    }
}

/// The common case: every vertex has the same size, so decode at fixed offsets.
void BinaryReader::read_fixed_vertices(const Element& vertex, const VertexLayout& layout,
                                       PointSet& points) {
    // (target, offset in the record, type) of every value read
    struct Field {
        std::size_t target;
        std::size_t offset;
        Type type;
    };
    std::vector<Field> fields;
    const std::vector<int> targets = layout.targets(vertex.properties.size());
    std::size_t offset = 0;
    for (std::size_t i = 0; i < vertex.properties.size(); ++i) {
        if (targets[i] != kAbsent)
            fields.push_back(
                {static_cast<std::size_t>(targets[i]), offset, vertex.properties[i].type});
        offset += size_of(vertex.properties[i].type);
    }
    const std::size_t size = vertex.min_item_size();
    std::vector<double> values(layout.value_count());
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
        if (!src_.ensure(size)) truncated(vertex, i);
        const unsigned char* record = src_.data();
        for (const Field& f : fields)
            values[f.target] = load_scalar(record + f.offset, f.type, swap_);
        store(points, values.data(), layout, vertex, i, name_);
        src_.consume(size);
    }
}

// ---------------------------------------------------------------------------------------------
// Ascii data

/// The data section as a stream of whitespace-separated tokens: the PLY spec does not tie items
/// to lines. Counts lines for error messages.
class AsciiReader {
public:
    AsciiReader(ByteSource& src, std::size_t header_lines, const std::string& name)
        : src_(src), line_(header_lines + 1), name_(name) {}

    void skip_element(const Element& element);
    void read_vertices(const Element& vertex, const VertexLayout& layout, PointSet& points);
    /// As BinaryReader::read_item.
    void read_item(const Element& element, std::uint64_t item, const std::vector<int>& targets,
                   double* values, std::size_t list_property = kNoList,
                   std::vector<double>* list = nullptr);

private:
    /// The next token, or a "truncated" error naming the item.
    std::string_view token(const Element& element, std::uint64_t item);
    bool next_token(std::string_view& token);
    double number(std::string_view token, Type type, const Element& element, std::uint64_t item,
                  const Property& property) const;

    ByteSource& src_;
    std::size_t line_;
    const std::string& name_;
};

bool AsciiReader::next_token(std::string_view& token) {
    constexpr std::size_t kMaxToken = 4096;
    for (;;) { // skip whitespace
        if (src_.available() == 0 && !src_.ensure(1)) return false;
        const unsigned char* p = src_.data();
        const std::size_t n = src_.available();
        std::size_t i = 0;
        for (; i < n && detail::is_space(static_cast<char>(p[i])); ++i) {
            if (p[i] == '\n') ++line_;
        }
        src_.consume(i);
        if (i < n) break;
    }
    std::size_t length = 0;
    for (;;) {
        const unsigned char* p = src_.data();
        const std::size_t n = src_.available();
        while (length < n && !detail::is_space(static_cast<char>(p[length]))) ++length;
        if (length < n) break;
        if (length > kMaxToken) {
            fail(name_, "line " + std::to_string(line_) + ": value too long: " +
                            quote(std::string_view(reinterpret_cast<const char*>(p), length)));
        }
        if (!src_.ensure(length + 1)) break; // the last token of the file
    }
    token = std::string_view(reinterpret_cast<const char*>(src_.data()), length);
    src_.consume(length);
    return true;
}

std::string_view AsciiReader::token(const Element& element, std::uint64_t item) {
    std::string_view t;
    if (!next_token(t)) {
        if (src_.read_failed()) fail(name_, "read error in " + item_label(element, item));
        fail(name_, "truncated ascii data: the file ends in " + item_label(element, item) +
                        " (line " + std::to_string(line_) + ")");
    }
    return t;
}

double AsciiReader::number(std::string_view token, Type type, const Element& element,
                           std::uint64_t item, const Property& property) const {
    bool ok = false;
    double value = 0;
    if (type == Type::Float32) { // parse as float directly: no double rounding
        float f = 0;
        ok = detail::parse_number(token, f);
        value = f;
    } else {
        ok = detail::parse_number(token, value);
    }
    if (!ok) {
        fail(name_, "line " + std::to_string(line_) + ": " + quote(token) + " is not a number (" +
                        item_label(element, item) + ", property '" + property.name + "')");
    }
    return value;
}

void AsciiReader::read_item(const Element& element, std::uint64_t item,
                            const std::vector<int>& targets, double* values,
                            std::size_t list_property, std::vector<double>* list) {
    for (std::size_t i = 0; i < element.properties.size(); ++i) {
        const Property& property = element.properties[i];
        if (!property.is_list) {
            const double value =
                number(token(element, item), property.type, element, item, property);
            if (targets[i] != kAbsent) values[targets[i]] = value;
            continue;
        }
        const std::string_view count_token = token(element, item);
        std::uint64_t count = 0;
        if (!detail::parse_count(count_token, count)) {
            fail(name_, "line " + std::to_string(line_) + ": invalid list length " +
                            quote(count_token) + " (" + item_label(element, item) + ", property '" +
                            property.name + "')");
        }
        std::vector<double>* const values_out = i == list_property ? list : nullptr;
        if (values_out != nullptr) values_out->clear();
        for (std::uint64_t j = 0; j < count; ++j) {
            const double value =
                number(token(element, item), property.type, element, item, property);
            if (values_out != nullptr) values_out->push_back(value);
        }
    }
}

void AsciiReader::skip_element(const Element& element) {
    if (element.properties.empty()) return;
    const std::vector<int> none(element.properties.size(), kAbsent);
    for (std::uint64_t i = 0; i < element.count; ++i) read_item(element, i, none, nullptr);
}

void AsciiReader::read_vertices(const Element& vertex, const VertexLayout& layout,
                                PointSet& points) {
    // At least one character and one separator per value.
    reserve_vertices(points, vertex.count, 2 * vertex.properties.size(), src_.remaining(),
                     layout.wanted == 6);
    const std::vector<int> targets = layout.targets(vertex.properties.size());
    std::vector<double> values(layout.value_count());
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
        read_item(vertex, i, targets, values.data());
        store(points, values.data(), layout, vertex, i, name_);
    }
}

// ---------------------------------------------------------------------------------------------
// Faces

/// Where the corner list of a face is: "vertex_indices" (or "vertex_index"), a list.
std::size_t face_list_property(const Element& face, const std::string& name) {
    for (const char* wanted : {"vertex_indices", "vertex_index"})
        for (std::size_t i = 0; i < face.properties.size(); ++i)
            if (face.properties[i].name == wanted) {
                if (!face.properties[i].is_list)
                    fail(name, std::string("face property '") + wanted + "' is not a list");
                return i;
            }
    fail(name, "the face element has no 'vertex_indices' list");
}

/// Appends the polygon `corners` (checked: integers >= 0) as a fan of triangles.
void append_polygon(const std::vector<double>& corners, const Element& face, std::uint64_t item,
                    const std::string& name, MeshFile& mesh) {
    if (corners.size() < 3)
        fail(name, item_label(face, item) + " has " + std::to_string(corners.size()) +
                       " corners (a face needs at least 3)");
    std::vector<std::uint32_t> v(corners.size());
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const double c = corners[k];
        if (!(c >= 0 && c < 4294967295.0 && c == std::floor(c)))
            fail(name, item_label(face, item) + " has an invalid vertex index " +
                           std::to_string(static_cast<long long>(c)));
        v[k] = static_cast<std::uint32_t>(c);
    }
    if (v.size() > 3) ++mesh.polygons_triangulated;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) mesh.triangles.push_back({v[0], v[k], v[k + 1]});
}

template <class Reader>
void read_faces(Reader& reader, const Element& face, const std::string& name, MeshFile& mesh) {
    const std::size_t list = face_list_property(face, name);
    const std::vector<int> none(face.properties.size(), kAbsent);
    std::vector<double> corners;
    for (std::uint64_t i = 0; i < face.count; ++i) {
        reader.read_item(face, i, none, nullptr, list, &corners);
        append_polygon(corners, face, i, name, mesh);
    }
}

/// Reads the vertices and, if `faces` is given, the triangles (elements in file order).
template <class Reader>
void read_elements(Reader& reader, const Header& header, const std::string& name, PointSet& points,
                   MeshFile* faces, bool attributes) {
    const auto vertex = std::find_if(header.elements.begin(), header.elements.end(),
                                     [](const Element& e) { return e.name == "vertex"; });
    if (vertex == header.elements.end()) fail(name, "the header has no 'vertex' element");
    VertexLayout layout = vertex_layout(*vertex, name);
    if (attributes) choose_attributes(*vertex, layout, points);
    points.precision = layout.precision;
    bool face_read = false;
    for (auto e = header.elements.begin(); e != header.elements.end(); ++e) {
        if (e == vertex) {
            reader.read_vertices(*vertex, layout, points);
            if (faces == nullptr) return; // later elements (faces, ...) are not needed
        } else if (faces != nullptr && e->name == "face" && !face_read) {
            read_faces(reader, *e, name, *faces);
            face_read = true;
        } else {
            reader.skip_element(*e);
        }
    }
}

void read_ply_unguarded(std::istream& in, const std::string& name, PointSet& points,
                        MeshFile* faces, bool attributes) {
    ByteSource src(in);
    const Header header = HeaderParser(name).parse(src);
    if (header.format == Format::Ascii) {
        AsciiReader reader(src, header.line_count, name);
        read_elements(reader, header, name, points, faces, attributes);
    } else {
        BinaryReader reader(src, header.format, name);
        read_elements(reader, header, name, points, faces, attributes);
    }
}

} // namespace

PointSet read_ply(std::istream& in, const std::string& name, const ReadOptions& options) {
    return detail::guarded_read(name, [&] {
        PointSet points;
        read_ply_unguarded(in, name, points, nullptr, options.attributes);
        return points;
    });
}

MeshFile read_ply_mesh(std::istream& in, const std::string& name) {
    return detail::guarded_read(name, [&] {
        MeshFile mesh;
        read_ply_unguarded(in, name, mesh.points, &mesh, false);
        const std::size_t n = mesh.points.size();
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            for (std::uint32_t v : mesh.triangles[t])
                if (v >= n)
                    fail(name, "triangle " + std::to_string(t + 1) + " refers to vertex " +
                                   std::to_string(v) + ", but there are only " + std::to_string(n) +
                                   " vertices");
        return mesh;
    });
}

} // namespace hrsr::io
