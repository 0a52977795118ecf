// A reader run on bytes held in memory, as if they were a file called `name`: the reader tests
// write their small files as strings.
#pragma once

#include "io/point_set_reader.h"

#include <sstream>
#include <string>

namespace hrsr::testing {

using StreamReader = PointSet (*)(std::istream&, const std::string&, const io::ReadOptions&);

inline PointSet read_bytes(StreamReader reader, const std::string& bytes,
                           io::ReadOptions options = {}, const std::string& name = "cloud") {
    std::istringstream in(bytes, std::ios::binary);
    return reader(in, name, options);
}

} // namespace hrsr::testing
