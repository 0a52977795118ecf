// The fuzz targets' bodies, shared by the libFuzzer executables (clang, scripts/test_sanitizers.sh)
// and by the ctest that replays tests/data/fuzz/ (any compiler). Each returns normally for any
// input: an hrsr::Error is an expected answer to bad input; anything else (another exception, a
// crash, a sanitizer report) is a bug.
#pragma once

#include <cstddef>
#include <cstdint>

namespace hrsr::fuzz {

/// read_ply / read_xyz / read_obj / read_pts / read_pcd / read_las on the bytes; checks what a
/// successful read returns.
void read_ply_bytes(const std::uint8_t* data, std::size_t size);
void read_xyz_bytes(const std::uint8_t* data, std::size_t size);
void read_obj_bytes(const std::uint8_t* data, std::size_t size);
void read_pts_bytes(const std::uint8_t* data, std::size_t size);
void read_pcd_bytes(const std::uint8_t* data, std::size_t size);
void read_las_bytes(const std::uint8_t* data, std::size_t size);

/// read_ply_mesh on the bytes, then, for a mesh of at most 2,000 triangles, every measure of
/// `hrsr check` on it (self-intersections and faces against vertex normals included); checks the
/// measures' own consistency.
void check_mesh_bytes(const std::uint8_t* data, std::size_t size);

/// Reconstruction of a small cloud made from the bytes: the first byte chooses the method, the
/// normals and k; then each 6 bytes are a point (three int16 / 256), each further 6 (if the
/// normals flag is set) a normal. At most 256 points.
void reconstruct_bytes(const std::uint8_t* data, std::size_t size);

} // namespace hrsr::fuzz
