// Private helpers shared by the point-set readers: number parsing, tokenising, error messages.
// Not installed, not part of the public interface.
#pragma once

#include "errors.h"
#include "point_set.h"

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>

namespace hrsr::io::detail {

inline bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

[[noreturn]] inline void fail(const std::string& name, const std::string& what) {
    throw IoError(name + ": " + what);
}

/// A token as shown in an error message: quoted, shortened, non-printable bytes replaced
/// (the input may be binary garbage).
inline std::string quote(std::string_view token) {
    constexpr std::size_t kMaxShown = 32;
    std::string s = "'";
    for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        s += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
    }
    if (token.size() > kMaxShown) s += "...";
    return s + "'";
}

/// What strtod gives for a number outside the range of T: +-infinity or +-0. from_chars
/// reports the error but leaves the value unset.
template <class T>
T out_of_range_value(std::string_view token) {
    const bool negative = !token.empty() && token[0] == '-';
    bool tiny = true;
    const auto e = token.find_first_of("eE");
    if (e != std::string_view::npos) {
        tiny = e + 1 < token.size() && token[e + 1] == '-';
    } else {
        for (const char c : token.substr(0, token.find('.'))) {
            if (c >= '1' && c <= '9') tiny = false;
        }
    }
    const T magnitude = tiny ? T(0) : std::numeric_limits<T>::infinity();
    return negative ? -magnitude : magnitude;
}

/// Parses a whole token as a float or double, locale-independently. Accepts a leading '+'
/// and "nan" / "inf" (the caller decides what to do with non-finite values).
template <class T>
bool parse_number(std::string_view token, T& out) {
    const char* begin = token.data();
    const char* const end = begin + token.size();
    if (begin != end && *begin == '+') {
        ++begin;
        if (begin != end && *begin == '-') return false;
    }
    const auto [ptr, ec] = std::from_chars(begin, end, out);
    if (ptr != end || begin == end) return false;
    if (ec == std::errc::result_out_of_range) {
        double wide = 0;
        if constexpr (std::is_same_v<T, float>) {
            if (parse_number(token, wide)) out = static_cast<float>(wide);
        } else {
            out = out_of_range_value<T>(token);
        }
        return true;
    }
    return ec == std::errc();
}

/// Parses a whole token as a non-negative integer.
inline bool parse_count(std::string_view token, std::uint64_t& out) {
    const char* const end = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), end, out);
    return ec == std::errc() && ptr == end && !token.empty();
}

/// Splits a line into whitespace-separated tokens without allocating.
class Tokens {
public:
    explicit Tokens(std::string_view text) : rest_(text) {}

    bool next(std::string_view& token) {
        std::size_t i = 0;
        while (i < rest_.size() && is_space(rest_[i])) ++i;
        if (i == rest_.size()) {
            rest_ = {};
            return false;
        }
        std::size_t j = i;
        while (j < rest_.size() && !is_space(rest_[j])) ++j;
        token = rest_.substr(i, j - i);
        rest_.remove_prefix(j);
        return true;
    }

private:
    std::string_view rest_;
};

/// Reads a text stream line by line (LF or CRLF), counting lines for error messages.
class LineReader {
public:
    LineReader(std::istream& in, const std::string& name) : in_(in), name_(name) {}

    /// The next line without its end-of-line characters; false at the end of the stream.
    bool next(std::string_view& line) {
        if (!std::getline(in_, buffer_)) {
            if (in_.bad()) fail(name_, "read error after line " + std::to_string(number_));
            return false;
        }
        ++number_;
        if (!buffer_.empty() && buffer_.back() == '\r') buffer_.pop_back();
        line = buffer_;
        return true;
    }
    std::size_t number() const { return number_; }

private:
    std::istream& in_;
    const std::string& name_;
    std::string buffer_;
    std::size_t number_ = 0;
};

/// The bytes left in a stream from its read position, if it can tell (files and string streams
/// can). Lets readers check a header's sizes before allocating for them.
inline std::optional<std::uint64_t> remaining_bytes(std::istream& in) {
    // A header read up to the end of the data (its last line without a newline) leaves the
    // stream at its end: nothing is left, though tellg() cannot say where that is.
    if (in.eof()) return 0;
    const std::streampos here = in.tellg();
    in.seekg(0, std::ios::end);
    const std::streampos end = in.tellg();
    in.clear();
    in.seekg(here);
    if (here == std::streampos(-1) || end == std::streampos(-1) || end < here) return std::nullopt;
    return static_cast<std::uint64_t>(end - here);
}

/// Runs a reader and turns every exception into an IoError naming the file, so that callers
/// only ever see IoError (e.g. bad_alloc from a header that lies about its size).
template <class Read>
auto guarded_read(const std::string& name, Read&& read) -> decltype(read()) {
    try {
        return read();
    } catch (const IoError&) {
        throw;
    } catch (const std::bad_alloc&) {
        fail(name, "not enough memory to read the file");
    } catch (const std::exception& e) {
        fail(name, e.what());
    }
}

} // namespace hrsr::io::detail
