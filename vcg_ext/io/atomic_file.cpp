#include "io/atomic_file.h"

#include "errors.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

#ifdef _WIN32
#include <process.h>
#define HRSR_GETPID _getpid
#else
#include <unistd.h>
#define HRSR_GETPID getpid
#endif

namespace hrsr::io {
namespace {

std::string reason() {
    return errno != 0 ? std::strerror(errno) : "unknown error";
}

} // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path_, error);
    if (!error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_directory(status)) {
        errno = 0;
        out_.open(path_, std::ios::binary | std::ios::out | std::ios::trunc);
        if (!out_) throw IoError(path_ + ": cannot open for writing: " + reason());
        return;
    }
    // pid + counter: unique among processes and among threads of this process.
    static std::atomic<unsigned long> counter{0};
    temp_path_ = path_ + ".tmp-" + std::to_string(HRSR_GETPID()) + "-" +
                 std::to_string(counter.fetch_add(1));
    errno = 0;
    out_.open(temp_path_, std::ios::binary | std::ios::out | std::ios::trunc);
    if (!out_) {
        throw IoError(path_ + ": cannot create the temporary file '" + temp_path_ +
                      "': " + reason());
    }
}

AtomicFile::~AtomicFile() {
    if (committed_) return;
    if (out_.is_open()) out_.close();
    if (!temp_path_.empty()) std::remove(temp_path_.c_str());
}

void AtomicFile::commit() {
    if (committed_) return;
    errno = 0;
    out_.flush();
    if (!out_) throw IoError(path_ + ": write error: " + reason());
    out_.close();
    if (out_.fail()) throw IoError(path_ + ": error closing the file: " + reason());
    errno = 0;
    if (!temp_path_.empty() && std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
        throw IoError(path_ + ": cannot replace the file with '" + temp_path_ + "': " + reason());
    }
    committed_ = true;
}

} // namespace hrsr::io
