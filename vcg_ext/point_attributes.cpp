#include "point_attributes.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace hrsr {
namespace {

template <class T>
void append_as(std::vector<unsigned char>& bytes, double value) {
    const T v = static_cast<T>(value);
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &v, sizeof(T));
    bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

template <class T>
double load_as(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return static_cast<double>(v);
}

template <class T>
bool fits_integer(double value) {
    return value == std::floor(value) && value >= double(std::numeric_limits<T>::min()) &&
           value <= double(std::numeric_limits<T>::max());
}

} // namespace

std::size_t size_of(ScalarType type) {
    switch (type) {
    case ScalarType::Int8:
    case ScalarType::UInt8:
        return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
        return 2;
    case ScalarType::Int32:
    case ScalarType::UInt32:
    case ScalarType::Float32:
        return 4;
    case ScalarType::Float64:
        return 8;
    }
    return 1;
}

const char* ply_type_name(ScalarType type) {
    switch (type) {
    case ScalarType::Int8:
        return "char";
    case ScalarType::UInt8:
        return "uchar";
    case ScalarType::Int16:
        return "short";
    case ScalarType::UInt16:
        return "ushort";
    case ScalarType::Int32:
        return "int";
    case ScalarType::UInt32:
        return "uint";
    case ScalarType::Float32:
        return "float";
    case ScalarType::Float64:
        return "double";
    }
    return "?";
}

bool fits(ScalarType type, double value) {
    switch (type) {
    case ScalarType::Int8:
        return fits_integer<std::int8_t>(value);
    case ScalarType::UInt8:
        return fits_integer<std::uint8_t>(value);
    case ScalarType::Int16:
        return fits_integer<std::int16_t>(value);
    case ScalarType::UInt16:
        return fits_integer<std::uint16_t>(value);
    case ScalarType::Int32:
        return fits_integer<std::int32_t>(value);
    case ScalarType::UInt32:
        return fits_integer<std::uint32_t>(value);
    case ScalarType::Float32:
        return !std::isfinite(value) ||
               std::fabs(value) <= double(std::numeric_limits<float>::max());
    case ScalarType::Float64:
        return true;
    }
    return false;
}

void PointAttribute::append(double value) {
    switch (type) {
    case ScalarType::Int8:
        return append_as<std::int8_t>(bytes, value);
    case ScalarType::UInt8:
        return append_as<std::uint8_t>(bytes, value);
    case ScalarType::Int16:
        return append_as<std::int16_t>(bytes, value);
    case ScalarType::UInt16:
        return append_as<std::uint16_t>(bytes, value);
    case ScalarType::Int32:
        return append_as<std::int32_t>(bytes, value);
    case ScalarType::UInt32:
        return append_as<std::uint32_t>(bytes, value);
    case ScalarType::Float32:
        return append_as<float>(bytes, value);
    case ScalarType::Float64:
        return append_as<double>(bytes, value);
    }
}

double PointAttribute::value(std::size_t i) const {
    const unsigned char* p = data(i);
    switch (type) {
    case ScalarType::Int8:
        return load_as<std::int8_t>(p);
    case ScalarType::UInt8:
        return load_as<std::uint8_t>(p);
    case ScalarType::Int16:
        return load_as<std::int16_t>(p);
    case ScalarType::UInt16:
        return load_as<std::uint16_t>(p);
    case ScalarType::Int32:
        return load_as<std::int32_t>(p);
    case ScalarType::UInt32:
        return load_as<std::uint32_t>(p);
    case ScalarType::Float32:
        return load_as<float>(p);
    case ScalarType::Float64:
        return load_as<double>(p);
    }
    return 0;
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
