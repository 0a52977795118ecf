#include "io/child_process_read.h"

#include "errors.h"

#include <csignal>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace hrsr::io::detail {
namespace {

enum Outcome : std::uint8_t { Read = 0, Failed = 1 };

// The wire format: little helpers that append / consume plain values.
class Writer {
public:
    template <class T>
    void put(const T& v) {
        bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void put(const std::string& s) {
        put(std::uint64_t(s.size()));
        bytes_ += s;
    }
    void put_raw(const void* data, std::size_t size) {
        put(std::uint64_t(size));
        if (size > 0) bytes_.append(static_cast<const char*>(data), size);
    }
    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
};

class Reader {
public:
    explicit Reader(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        T v;
        take(&v, sizeof v);
        return v;
    }
    std::string get_string() {
        std::string s(static_cast<std::size_t>(get<std::uint64_t>()), '\0');
        take(s.data(), s.size());
        return s;
    }
    template <class T>
    void get_vector(std::vector<T>& v) {
        const auto size = static_cast<std::size_t>(get<std::uint64_t>());
        if (size % sizeof(T) != 0) throw std::runtime_error("bad vector size");
        v.resize(size / sizeof(T));
        take(v.data(), size);
    }

private:
    void take(void* out, std::size_t n) {
        if (bytes_.size() - at_ < n) throw std::runtime_error("truncated reply");
        if (n == 0) return; // an empty vector's data() may be null
        std::memcpy(out, bytes_.data() + at_, n);
        at_ += n;
    }
    const std::string& bytes_;
    std::size_t at_ = 0;
};

std::string serialise(const PointSet& p) {
    Writer w;
    w.put(Read);
    w.put(std::uint8_t(p.precision == CoordinatePrecision::Double));
    w.put_raw(p.positions.data(), p.positions.size() * sizeof(Vec3));
    w.put_raw(p.normals.data(), p.normals.size() * sizeof(Vec3));
    w.put(std::uint64_t(p.attributes.size()));
    for (const PointAttribute& a : p.attributes) {
        w.put(a.name);
        w.put(std::uint8_t(a.type));
        w.put_raw(a.bytes.data(), a.bytes.size());
    }
    w.put(std::uint64_t(p.warnings.size()));
    for (const std::string& s : p.warnings) w.put(s);
    return w.bytes();
}

PointSet deserialise(Reader& r) {
    PointSet p;
    p.precision = r.get<std::uint8_t>() ? CoordinatePrecision::Double : CoordinatePrecision::Float;
    r.get_vector(p.positions);
    r.get_vector(p.normals);
    p.attributes.resize(static_cast<std::size_t>(r.get<std::uint64_t>()));
    for (PointAttribute& a : p.attributes) {
        a.name = r.get_string();
        a.type = static_cast<ScalarType>(r.get<std::uint8_t>());
        r.get_vector(a.bytes);
    }
    p.warnings.resize(static_cast<std::size_t>(r.get<std::uint64_t>()));
    for (std::string& s : p.warnings) s = r.get_string();
    return p;
}

bool write_all(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

std::string read_all(int fd) {
    std::string bytes;
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes.append(buffer, static_cast<std::size_t>(n));
    }
    return bytes;
}

[[noreturn]] void run_child(int fd, const std::function<PointSet()>& read) {
    // The decoder's crash must end this process quietly, not reach a sanitizer's or fuzzer's
    // handler that would report it as the parent's.
    for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, SIG_DFL);
    std::string reply;
    try {
        reply = serialise(read());
    } catch (const std::exception& e) {
        Writer w;
        w.put(Failed);
        w.put(std::string(e.what()));
        reply = w.bytes();
    }
    _exit(write_all(fd, reply) ? 0 : 3);
}

} // namespace

PointSet read_in_child_process(const std::string& name, const std::string& what_crashed,
                               const std::function<PointSet()>& read) {
    int fds[2];
    if (::pipe(fds) != 0) throw IoError(name + ": cannot create a pipe: " + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        throw IoError(name + ": cannot start the reader process: " + std::strerror(errno));
    }
    if (pid == 0) {
        ::close(fds[0]);
        run_child(fds[1], read);
    }
    ::close(fds[1]);
    const std::string reply = read_all(fds[0]);
    ::close(fds[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status))
        throw IoError(name + ": " + what_crashed + " crashed on this file (signal " +
                      std::to_string(WTERMSIG(status)) + ": " + strsignal(WTERMSIG(status)) +
                      "): the file is corrupt");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.empty())
        throw IoError(name + ": the reader process failed (exit status " +
                      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
    try {
        Reader r(reply);
        if (r.get<std::uint8_t>() == Failed) throw IoError(r.get_string());
        return deserialise(r);
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {
        throw IoError(name + ": bad reply from the reader process: " + e.what());
    }
}

} // namespace hrsr::io::detail
