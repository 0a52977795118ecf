#include "fuzz_targets.h"

#include "errors.h"
#include "io/mesh_reader.h"
#include "io/point_set_reader.h"
#include "mesh/check.h"
#include "reconstruction.h"

#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>

namespace hrsr::fuzz {

namespace {

using Reader = PointSet (*)(std::istream&, const std::string&, const io::ReadOptions&);

// A bug, not an answer: reported as an exception that is not an hrsr::Error.
void require(bool ok, const char* what) {
    if (!ok) throw std::logic_error(what);
}

void read_with(Reader read, const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    try {
        const PointSet s = read(in, "fuzz", io::ReadOptions{});
        require(s.normals.empty() || s.normals.size() == s.positions.size() ||
                    read == io::read_obj, // OBJ returns v and vn counts as read
                "a reader returned normals for only some points");
        for (const PointAttribute& a : s.attributes)
            require(a.size() == s.positions.size() && a.bytes.size() == a.size() * size_of(a.type),
                    "a reader returned an attribute for only some points");
    } catch (const IoError& e) {
        require(std::string(e.what()).rfind("fuzz", 0) == 0, "a read error does not name the file");
    }
}

double coordinate(const std::uint8_t* p) {
    std::int16_t v;
    std::memcpy(&v, p, sizeof v);
    return double(v) / 256.0;
}

} // namespace

void read_ply_bytes(const std::uint8_t* data, std::size_t size) {
    read_with(io::read_ply, data, size);
}
void read_xyz_bytes(const std::uint8_t* data, std::size_t size) {
    read_with(io::read_xyz, data, size);
}
void read_obj_bytes(const std::uint8_t* data, std::size_t size) {
    read_with(io::read_obj, data, size);
}
void read_pts_bytes(const std::uint8_t* data, std::size_t size) {
    read_with(io::read_pts, data, size);
}
void read_pcd_bytes(const std::uint8_t* data, std::size_t size) {
    read_with(io::read_pcd, data, size);
}
void read_las_bytes(const std::uint8_t* data, std::size_t size) {
    read_with(io::read_las, data, size);
}

void check_mesh_bytes(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    io::MeshFile mesh;
    try {
        mesh = io::read_ply_mesh(in, "fuzz");
    } catch (const IoError& e) {
        require(std::string(e.what()).rfind("fuzz", 0) == 0, "a read error does not name the file");
        return;
    }
    for (const Triangle& t : mesh.triangles)
        for (std::uint32_t v : t) require(v < mesh.points.size(), "a triangle refers to no vertex");
    constexpr std::size_t kMostTriangles = 2000; // the pair test grows with the area they cover
    if (mesh.triangles.size() > kMostTriangles) return;
    const MeshView view{mesh.points.positions, mesh.triangles, &mesh.points.normals};
    try {
        const MeshCheck c = check_mesh(view, nullptr, nullptr, CheckOptions{}, {1, nullptr});
        require(c.topology.faces == mesh.triangles.size(), "check lost a triangle");
        require(c.self_intersecting_pairs.has_value(), "the pair test did not run");
        require(c.faces_against_vertex_normals.has_value() == !mesh.points.normals.empty(),
                "faces against normals counted without normals, or not with them");
        require(c.faces_against_vertex_normals.value_or(0) <= c.topology.faces,
                "more faces against normals than faces");
    } catch (const InvalidInput&) { // non-finite coordinates
    }
}

void reconstruct_bytes(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    const std::uint8_t flags = data[0];
    const bool normals = flags & 1;
    ReconstructionOptions options;
    options.method = flags & 2 ? Method::Rsr : Method::Hrsr;
    options.rsr.preprocess.k = 3 + (flags >> 2) % 16;
    options.rsr.preprocess.min_component_size = 1;
    const std::size_t stride = normals ? 12 : 6;
    const std::size_t points = std::min<std::size_t>((size - 1) / stride, 256);
    PointSet cloud;
    for (std::size_t i = 0; i < points; ++i) {
        const std::uint8_t* p = data + 1 + i * stride;
        cloud.positions.emplace_back(coordinate(p), coordinate(p + 2), coordinate(p + 4));
        if (normals)
            cloud.normals.emplace_back(coordinate(p + 6), coordinate(p + 8), coordinate(p + 10));
    }
    ReconstructionReport report;
    try {
        const Reconstruction mesh = reconstruct(cloud, options, {1, nullptr}, report);
        require(!mesh.triangles.empty(), "an empty mesh was returned");
        require(report.mesh.non_manifold_edges == 0 && report.mesh.non_manifold_vertices == 0,
                "a non-manifold mesh was returned");
        for (const Triangle& t : mesh.triangles)
            for (std::uint32_t v : t)
                require(v < mesh.vertex_input_index.size(), "a triangle refers to no vertex");
        for (std::uint32_t i : mesh.vertex_input_index)
            require(i < cloud.size(), "a vertex refers to no input point");
    } catch (const InvalidInput&) {
    }
}

} // namespace hrsr::fuzz
