#include "point_attributes.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

namespace hrsr {
namespace {

/// Calls f(T{}) with the C++ type T of `type`: one switch for every operation below.
template <class F>
auto with_type(ScalarType type, F&& f) {
    switch (type) {
    case ScalarType::Int8:
        return f(std::int8_t{});
    case ScalarType::UInt8:
        return f(std::uint8_t{});
    case ScalarType::Int16:
        return f(std::int16_t{});
    case ScalarType::UInt16:
        return f(std::uint16_t{});
    case ScalarType::Int32:
        return f(std::int32_t{});
    case ScalarType::UInt32:
        return f(std::uint32_t{});
    case ScalarType::Float32:
        return f(float{});
    case ScalarType::Float64:
        break;
    }
    return f(double{});
}

} // namespace

std::size_t size_of(ScalarType type) {
    return with_type(type, [](auto t) { return sizeof t; });
}

const char* ply_type_name(ScalarType type) {
    static const char* const kNames[] = {"char", "uchar", "short", "ushort",
                                         "int",  "uint",  "float", "double"};
    return kNames[static_cast<std::size_t>(type)];
}

bool fits(ScalarType type, double value) {
    return with_type(type, [value](auto t) {
        using T = decltype(t);
        if constexpr (std::is_floating_point_v<T>) {
            return !std::isfinite(value) ||
                   std::fabs(value) <= double(std::numeric_limits<T>::max());
        } else {
            return value == std::floor(value) && value >= double(std::numeric_limits<T>::min()) &&
                   value <= double(std::numeric_limits<T>::max());
        }
    });
}

double load_value(ScalarType type, const unsigned char* host_order) {
    return with_type(type, [host_order](auto t) {
        std::memcpy(&t, host_order, sizeof t);
        return static_cast<double>(t);
    });
}

void PointAttribute::append(double value) {
    with_type(type, [this, value](auto t) {
        t = static_cast<decltype(t)>(value);
        unsigned char raw[sizeof t];
        std::memcpy(raw, &t, sizeof t);
        bytes.insert(bytes.end(), raw, raw + sizeof t);
    });
}

double PointAttribute::value(std::size_t i) const {
    return load_value(type, data(i));
}

PointAttribute gather(const PointAttribute& source, const std::vector<std::uint32_t>& index) {
    PointAttribute out(source.name, source.type);
    const std::size_t size = size_of(source.type);
    out.bytes.resize(index.size() * size);
    for (std::size_t k = 0; k < index.size(); ++k)
        std::memcpy(out.bytes.data() + k * size, source.data(index[k]), size);
    return out;
}

std::vector<PointAttribute> gather(const std::vector<PointAttribute>& source,
                                   const std::vector<std::uint32_t>& index) {
    std::vector<PointAttribute> out;
    out.reserve(source.size());
    for (const PointAttribute& a : source) out.push_back(gather(a, index));
    return out;
}

} // namespace hrsr
