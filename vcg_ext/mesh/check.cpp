#include "mesh/check.h"

#include "errors.h"
#include "knn.h"
#include "mesh/welding.h"

#include <vcg/space/box3.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace hrsr {

namespace {

void validate(const MeshView& m, const char* what) {
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(m.positions[v][k]))
                throw InvalidInput(std::string(what) + ": vertex " + std::to_string(v) +
                                   " has a non-finite coordinate");
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (std::uint32_t v : m.triangles[t])
            if (v >= m.positions.size())
                throw InvalidInput(std::string(what) + ": triangle " + std::to_string(t) +
                                   " refers to vertex " + std::to_string(v) + " of " +
                                   std::to_string(m.positions.size()));
}

bool has_normals(const MeshView& m) {
    return m.normals != nullptr && !m.normals->empty();
}

void validate_normals(const MeshView& m, const char* what) {
    if (has_normals(m) && m.normals->size() != m.positions.size())
        throw InvalidInput(std::string(what) + ": " + std::to_string(m.normals->size()) +
                           " normals for " + std::to_string(m.positions.size()) + " vertices");
}

// D-64's test on the mesh as given: the face's winding normal against the sum of its corners'
// normals (faces without area do not count; they are counted as degenerate).
std::size_t faces_against_vertex_normals(const MeshView& m, const Execution& exec) {
    const std::vector<Vec3>& n = *m.normals;
    std::vector<std::size_t> against(block_count(m.triangles.size(), kCheapBlock), 0);
    parallel_for_blocks(exec, m.triangles.size(), kCheapBlock,
                        [&](std::size_t block, std::size_t first, std::size_t end) {
                            for (std::size_t f = first; f < end; ++f) {
                                const Triangle& t = m.triangles[f];
                                const Vec3& a = m.positions[t[0]];
                                const Vec3 winding =
                                    (m.positions[t[1]] - a) ^ (m.positions[t[2]] - a);
                                const double along = winding.dot(n[t[0]] + n[t[1]] + n[t[2]]);
                                against[block] += winding.SquaredNorm() > 0 && along < 0;
                            }
                        });
    std::size_t total = 0;
    for (std::size_t a : against) total += a;
    return total;
}

double diagonal(const std::vector<Vec3>& points) {
    vcg::Box3d box;
    for (const Vec3& p : points)
        if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) box.Add(p);
    return box.IsNull() ? 0 : box.Diag();
}

VertexReference vertex_reference(const MeshView& mesh, const PointSet& input, double tolerance,
                                 const Execution& exec) {
    VertexReference r;
    r.input_points = input.size();
    r.tolerance = tolerance * diagonal(input.positions);
    std::vector<std::uint8_t> used(mesh.positions.size(), 0);
    for (const Triangle& t : mesh.triangles)
        for (std::uint32_t v : t) used[v] = 1;
    std::vector<Vec3> vertices;
    for (std::size_t v = 0; v < used.size(); ++v)
        if (used[v]) vertices.push_back(mesh.positions[v]);
    if (vertices.empty() || input.size() == 0) return r;
    const KnnIndex index(vertices, exec);
    std::vector<std::uint8_t> present(input.size(), 0);
    const double limit = r.tolerance * r.tolerance;
    parallel_for(exec, input.size(), [&](std::size_t i) {
        const Vec3& p = input.positions[i];
        if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) return;
        std::vector<Neighbour> nearest;
        index.nearest(p, 1, nearest);
        present[i] = !nearest.empty() && nearest[0].squared_distance <= limit;
    });
    for (std::uint8_t p : present) r.present += p;
    return r;
}

} // namespace

MeshCheck check_mesh(const MeshView& mesh, const PointSet* input, const MeshView* reference,
                     const CheckOptions& o, const Execution& exec) {
    validate(mesh, "mesh");
    validate_normals(mesh, "mesh");
    if (reference != nullptr) {
        validate(*reference, "reference");
        if (reference->triangles.empty()) throw InvalidInput("reference: no triangles");
        if (mesh.triangles.empty())
            throw InvalidInput("mesh: no triangles to compare with the reference");
    }
    MeshCheck c;
    c.file_vertices = mesh.positions.size();
    const std::vector<std::uint32_t> representative = same_position_representatives(mesh.positions);
    for (std::size_t v = 0; v < representative.size(); ++v)
        c.coincident_vertices += representative[v] != v;
    c.topology = measure_mesh(mesh.positions.size(), mesh.triangles);
    c.faces = face_quality(mesh.positions, mesh.triangles,
                           welded_triangles(mesh.triangles, representative));
    if (o.self_intersections) {
        const std::vector<TrianglePair> pairs =
            self_intersecting_pairs(mesh.positions, mesh.triangles, exec);
        c.self_intersecting_pairs = pairs.size();
        c.first_intersecting_pairs.assign(pairs.begin(),
                                          pairs.begin() + std::min<std::size_t>(pairs.size(), 100));
    }
    if (has_normals(mesh))
        c.faces_against_vertex_normals = faces_against_vertex_normals(mesh, exec);
    if (input != nullptr)
        c.vertex_reference = vertex_reference(mesh, *input, o.vertex_tolerance, exec);
    if (reference != nullptr) {
        ReferenceDistance r;
        r.diagonal = diagonal(reference->positions);
        r.distance =
            surface_distance({mesh.positions, mesh.triangles},
                             {reference->positions, reference->triangles}, o.distance, exec);
        c.reference = r;
    }
    return c;
}

} // namespace hrsr
