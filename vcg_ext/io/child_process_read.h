// Running a reader in a child process, for third-party decoders that may crash on corrupt input
// (LASzip): the crash ends the child, and the caller gets an IoError instead.
#pragma once

#include "point_set.h"

#include <functional>
#include <string>

namespace hrsr::io::detail {

/// Runs `read` in a forked child and returns its PointSet (sent back through a pipe). An IoError
/// thrown there is rethrown here; a child that dies (a signal, an abort) gives IoError
/// "`name`: `what_crashed` crashed on this file (...)". Call it only while no other thread
/// runs (fork copies the calling thread alone).
PointSet read_in_child_process(const std::string& name, const std::string& what_crashed,
                               const std::function<PointSet()>& read);

} // namespace hrsr::io::detail
