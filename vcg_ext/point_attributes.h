// Per-point values a scan carries besides position and normal (colour, intensity, labels, ...),
// kept as the source stored them so that they reach the output vertices unchanged.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hrsr {

/// The scalar types of PLY, which also cover LAS, PCD and PTS fields.
enum class ScalarType : std::uint8_t {
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Float32,
    Float64
};

std::size_t size_of(ScalarType type);

/// The PLY type name ("uchar", "ushort", "float", ...).
const char* ply_type_name(ScalarType type);

/// True if `value` is exactly representable in `type` (integers: integral and in range).
bool fits(ScalarType type, double value);

/// The value stored at `host_order` (size_of(type) bytes in host byte order), exactly.
double load_value(ScalarType type, const unsigned char* host_order);

/// One named value per point, as bytes in host byte order (size_of(type) per point): a column
/// of uchar colours costs one byte per point, not a double.
struct PointAttribute {
    std::string name;
    ScalarType type = ScalarType::Float32;
    std::vector<unsigned char> bytes;

    PointAttribute() = default;
    PointAttribute(std::string attribute_name, ScalarType attribute_type)
        : name(std::move(attribute_name)), type(attribute_type) {}

    std::size_t size() const { return bytes.size() / size_of(type); }
    const unsigned char* data(std::size_t i) const { return bytes.data() + i * size_of(type); }
    /// Appends `value` converted to `type`; the caller checks fits() when it may not.
    void append(double value);
    /// The value of point i (exact: every type fits in a double).
    double value(std::size_t i) const;
};

/// The attribute for the points `index` (an output vertex -> input point map): entry k is the
/// value of point index[k]. Indices must be < source.size().
PointAttribute gather(const PointAttribute& source, const std::vector<std::uint32_t>& index);

/// The same for every attribute.
std::vector<PointAttribute> gather(const std::vector<PointAttribute>& source,
                                   const std::vector<std::uint32_t>& index);

} // namespace hrsr
