// LAS / LAZ reader (versions 1.0-1.4, point formats 0-10) through the LASzip library, which
// decodes both plain and compressed files. LASzip trusts its input: the header is checked here
// first, and the decoding runs in a child process so that a crash in it is an error, not ours.
// Coordinates are the scaled integers (X * scale + offset) as doubles: georeferenced values keep
// every stored digit.
#include "io/child_process_read.h"
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

#ifdef HRSR_HAVE_LASZIP
#include <laszip/laszip_api.h>
#endif

#include <algorithm>
#include <optional>

namespace hrsr::io {

#ifdef HRSR_HAVE_LASZIP
namespace {

using detail::fail;

/// The LASzip reader object, closed and destroyed on every path out.
class LaszipReader {
public:
    explicit LaszipReader(const std::string& name) : name_(name) {
        if (laszip_create(&handle_) != 0 || handle_ == nullptr)
            fail(name_, "cannot create a LASzip reader");
    }
    ~LaszipReader() {
        if (open_) laszip_close_reader(handle_);
        laszip_destroy(handle_);
    }
    LaszipReader(const LaszipReader&) = delete;
    LaszipReader& operator=(const LaszipReader&) = delete;

    /// Opens the stream; returns whether the points are compressed (LAZ).
    bool open(std::istream& in) {
        laszip_BOOL compressed = 0;
        if (laszip_open_reader_stream(handle_, in, &compressed) != 0)
            fail(name_, "not a readable LAS/LAZ file: " + error());
        open_ = true;
        return compressed != 0;
    }
    laszip_header* header() {
        laszip_header* h = nullptr;
        if (laszip_get_header_pointer(handle_, &h) != 0 || h == nullptr)
            fail(name_, "cannot read the LAS header: " + error());
        return h;
    }
    laszip_point* point() {
        laszip_point* p = nullptr;
        if (laszip_get_point_pointer(handle_, &p) != 0 || p == nullptr)
            fail(name_, "cannot read LAS points: " + error());
        return p;
    }
    /// False at a read error (truncated or corrupt data).
    bool read() { return laszip_read_point(handle_) == 0; }
    std::string error() {
        laszip_CHAR* message = nullptr;
        laszip_get_error(handle_, &message);
        return message != nullptr && *message != 0 ? std::string(message) : "unknown error";
    }

private:
    const std::string& name_;
    laszip_POINTER handle_ = nullptr;
    bool open_ = false;
};

bool has_gps_time(int format) {
    return format == 1 || format >= 3;
}
bool has_rgb(int format) {
    return format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
}
bool has_nir(int format) {
    return format == 8 || format == 10;
}

/// The per-point attributes of a point format, in a fixed order (so that tiles of the same
/// format have the same attributes).
std::vector<PointAttribute> attributes_of(int format) {
    std::vector<PointAttribute> a;
    a.emplace_back("intensity", ScalarType::UInt16);
    a.emplace_back("classification", ScalarType::UInt8);
    if (has_gps_time(format)) a.emplace_back("gps_time", ScalarType::Float64);
    if (has_rgb(format)) {
        for (const char* c : {"red", "green", "blue"}) a.emplace_back(c, ScalarType::UInt16);
    }
    if (has_nir(format)) a.emplace_back("nir", ScalarType::UInt16);
    return a;
}

void append_attributes(const laszip_point& p, int format, std::vector<PointAttribute>& out) {
    std::size_t k = 0;
    out[k++].append(p.intensity);
    // Formats 6-10 keep the full 8-bit class apart; the 5-bit field holds min(class, 31).
    out[k++].append(format >= 6 ? p.extended_classification : p.classification);
    if (has_gps_time(format)) out[k++].append(p.gps_time);
    if (has_rgb(format)) {
        for (int c = 0; c < 3; ++c) out[k++].append(p.rgb[c]);
    }
    if (has_nir(format)) out[k++].append(p.rgb[3]);
}

/// Little-endian reads at absolute offsets of the (seekable) stream; false past its end.
class LasBytes {
public:
    LasBytes(std::istream& in, std::uint64_t size) : in_(in), size_(size) {}
    std::uint64_t size() const { return size_; }
    template <class T>
    bool get(std::uint64_t offset, T& value) {
        if (offset > size_ || size_ - offset < sizeof(T)) return false;
        unsigned char b[sizeof(T)];
        in_.clear();
        in_.seekg(static_cast<std::streamoff>(offset));
        if (!in_.read(reinterpret_cast<char*>(b), sizeof b)) return false;
        std::uint64_t v = 0;
        for (std::size_t i = sizeof(T); i-- > 0;) v = v << 8 | b[i];
        value = static_cast<T>(v);
        return true;
    }

private:
    std::istream& in_;
    std::uint64_t size_;
};

/// The size of a point record of each format 0-10 (extra bytes may follow).
constexpr std::uint16_t kRecordLength[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

/// LASzip's own record (user "laszip encoded"): 34 bytes and 6 per item. LASzip reads it
/// field by field from the file and, on a short one, reads past it and crashes in its clean-up.
constexpr std::uint16_t kLaszipRecordId = 22204;

void check_laszip_record(LasBytes& bytes, std::uint64_t at, std::uint16_t length,
                         const std::string& name) {
    std::uint16_t items = 0;
    if (length < 34 || !bytes.get(at + 54 + 32, items) || length != 34 + 6 * std::uint32_t(items))
        fail(name, "corrupt LAZ header: the LASzip record has " + std::to_string(length) +
                       " bytes for " + std::to_string(items) + " items");
}

/// LASzip trusts the header's sizes and allocates by them (a header size below 227, 4 billion
/// VLRs, a LAZ chunk count of 4 billion): check them against the file first. Offsets are those
/// of the LAS 1.0-1.4 public header block.
void check_header_sizes(std::istream& in, std::uint64_t file_size, const std::string& name) {
    LasBytes bytes(in, file_size);
    char signature[4] = {};
    in.read(signature, 4);
    std::uint8_t major = 0, minor = 0, format = 0;
    std::uint16_t header_size = 0;
    std::uint32_t offset = 0, vlrs = 0;
    if (!in || std::string(signature, 4) != "LASF" || !bytes.get(24, major) ||
        !bytes.get(25, minor) || !bytes.get(94, header_size) || !bytes.get(96, offset) ||
        !bytes.get(100, vlrs) || !bytes.get(104, format) || file_size < 227)
        fail(name, "not a readable LAS/LAZ file: no complete LAS header");
    if (major != 1 || minor > 4)
        fail(name, "unsupported LAS version " + std::to_string(major) + "." +
                       std::to_string(minor) + " (1.0 to 1.4 are read)");
    const unsigned minimum = minor >= 4 ? 375 : minor == 3 ? 235 : 227;
    std::uint16_t record_length = 0;
    bytes.get(105, record_length);
    if ((format & 0x3f) > 10)
        fail(name, "unsupported LAS point format " + std::to_string(format & 0x3f) +
                       " (0 to 10 are read)");
    if (record_length < kRecordLength[format & 0x3f])
        fail(name, "corrupt LAS header: " + std::to_string(record_length) +
                       "-byte point records for point format " + std::to_string(format & 0x3f) +
                       ", which needs " + std::to_string(kRecordLength[format & 0x3f]));
    if (header_size < minimum || offset < header_size || offset > file_size)
        fail(name, "corrupt LAS header: header size " + std::to_string(header_size) +
                       ", point data at byte " + std::to_string(offset) + " of " +
                       std::to_string(file_size));
    std::uint64_t at = header_size;
    for (std::uint32_t i = 0; i < vlrs; ++i) {
        std::uint16_t length = 0, record_id = 0;
        if (at + 54 > offset || !bytes.get(at + 20, length) || at + 54 + length > offset)
            fail(name, "corrupt LAS header: variable-length record " + std::to_string(i + 1) +
                           " of " + std::to_string(vlrs) + " runs into the point data");
        bytes.get(at + 18, record_id);
        if (record_id == kLaszipRecordId) check_laszip_record(bytes, at, length, name);
        at += 54 + std::uint64_t(length);
    }
    if ((format & 0x80) == 0) return; // not compressed
    // A corrupt count must not make the decoder run for hours on a few bytes: real LAZ data
    // takes several bytes per point, 1000 points per byte is far beyond any.
    std::uint32_t legacy_count = 0;
    std::uint64_t count = 0;
    bytes.get(107, legacy_count);
    if (legacy_count == 0 && minor >= 4) bytes.get(247, count);
    count = legacy_count != 0 ? legacy_count : count;
    if (count / 1000 > file_size - offset)
        fail(name, "wrong point count: the header says " + std::to_string(count) +
                       " points, more than " + std::to_string(file_size - offset) +
                       " bytes of LAZ data can hold");
    // LAZ: the point data starts with the chunk table's position (-1: in the file's last 8 bytes).
    std::int64_t table = 0;
    if (!bytes.get(offset, table)) fail(name, "truncated LAZ file: no point data");
    if (table == -1 && !bytes.get(file_size - 8, table)) table = 0;
    std::uint32_t version = 1, chunks = 0;
    const std::uint64_t first_chunk = std::uint64_t(offset) + 8;
    if (table > 0 && std::uint64_t(table) >= first_chunk &&
        bytes.get(std::uint64_t(table), version) && version == 0 &&
        bytes.get(std::uint64_t(table) + 4, chunks) &&
        chunks > std::uint64_t(table) - first_chunk) // every chunk takes at least a byte
        fail(name, "corrupt LAZ chunk table: " + std::to_string(chunks) + " chunks in " +
                       std::to_string(std::uint64_t(table) - first_chunk) + " bytes");
}

/// Uncompressed points are fixed-size records between the header and the end of the file (or
/// the waveform data / extended VLRs): their number must be the header's. LAZ data is checked
/// by the decoder.
void check_point_count(const laszip_header& h, std::uint64_t count, std::uint64_t file_size,
                       const std::string& name) {
    std::uint64_t end = file_size;
    if (h.version_minor >= 4 && h.start_of_first_extended_variable_length_record > 0)
        end = std::min<std::uint64_t>(end, h.start_of_first_extended_variable_length_record);
    if (h.version_minor >= 3 && h.start_of_waveform_data_packet_record > 0)
        end = std::min<std::uint64_t>(end, h.start_of_waveform_data_packet_record);
    if (h.point_data_record_length == 0 || end < h.offset_to_point_data)
        fail(name, "corrupt header: point data offset " + std::to_string(h.offset_to_point_data) +
                       ", record length " + std::to_string(h.point_data_record_length));
    const std::uint64_t held = (end - h.offset_to_point_data) / h.point_data_record_length;
    if (held != count)
        fail(name, "wrong point count: the header says " + std::to_string(count) +
                       " points, the point data holds " + std::to_string(held));
}

/// The points through LASzip (in the child process: see read_las).
PointSet decode(std::istream& in, std::uint64_t file_size, const std::string& name,
                bool attributes) {
    LaszipReader reader(name);
    const bool compressed = reader.open(in);
    const laszip_header* h = reader.header();
    const int format = h->point_data_format & 0x3f; // bits 6-7 flag compression in LAZ
    if (format > 10)
        fail(name,
             "unsupported LAS point format " + std::to_string(format) + " (0 to 10 are read)");
    const std::uint64_t count = h->number_of_point_records != 0
                                    ? h->number_of_point_records
                                    : h->extended_number_of_point_records;
    if (!compressed) check_point_count(*h, count, file_size, name);
    PointSet points;
    points.precision = CoordinatePrecision::Double; // scale * int + offset is not a float
    if (attributes) points.attributes = attributes_of(format);
    const laszip_point* p = reader.point();
    for (std::uint64_t i = 0; i < count; ++i) {
        if (!reader.read())
            fail(name, "truncated or corrupt point data: point " + std::to_string(i + 1) + " of " +
                           std::to_string(count) +
                           " (the header's count) cannot be read: " + reader.error());
        points.positions.emplace_back(h->x_scale_factor * p->X + h->x_offset,
                                      h->y_scale_factor * p->Y + h->y_offset,
                                      h->z_scale_factor * p->Z + h->z_offset);
        if (attributes) append_attributes(*p, format, points.attributes);
    }
    return points;
}

} // namespace

PointSet read_las(std::istream& in, const std::string& name, const ReadOptions& options) {
    return detail::guarded_read(name, [&] {
        // The stream starts at the file's start: LAS offsets count from there.
        const std::optional<std::uint64_t> file_size = detail::remaining_bytes(in);
        if (!file_size) fail(name, "LAS/LAZ input must be seekable");
        check_header_sizes(in, *file_size, name);
        in.clear();
        in.seekg(0);
        // LASzip's decoder can crash on corrupt LAZ data (found by fuzz_read_las): it runs in
        // a child process, whose crash becomes an error naming the file.
        return detail::read_in_child_process(name, "the LASzip decoder", [&] {
            return detail::guarded_read(
                name, [&] { return decode(in, *file_size, name, options.attributes); });
        });
    });
}

#else

PointSet read_las(std::istream&, const std::string& name, const ReadOptions&) {
    detail::fail(name, "this hrsr was built without LASzip, so it cannot read LAS/LAZ files "
                       "(run scripts/setup.sh, which builds LASzip, and rebuild)");
}

#endif

} // namespace hrsr::io
