// Write a file completely or not at all: a temporary file next to the destination, renamed on
// success, removed on failure. A destination that exists and is not a regular file (/dev/null, a
// pipe, /dev/stdout) is written directly: renaming onto it would replace the device itself.
#pragma once

#include <fstream>
#include <string>

namespace hrsr::io {

class AtomicFile {
public:
    /// Opens a temporary file in the folder of `path` (binary mode), or `path` itself when it
    /// exists and is neither a regular file nor a folder. Throws hrsr::IoError.
    explicit AtomicFile(std::string path);
    /// Removes the temporary file unless commit() succeeded.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    std::ofstream& stream() { return out_; }
    /// Flushes, checks for write errors, and renames the temporary file onto the destination.
    /// Throws hrsr::IoError (naming the destination) on failure.
    void commit();

private:
    std::string path_;
    std::string temp_path_; ///< empty when writing to `path_` directly
    std::ofstream out_;
    bool committed_ = false;
};

} // namespace hrsr::io
