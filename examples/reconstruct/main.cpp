// The installed package in use: reads a point cloud, reconstructs it with the default options
// (HRsR) and writes the mesh, as `hrsr reconstruct INPUT -o OUTPUT` does.
#include <hrsr/errors.h>
#include <hrsr/io/mesh_writer.h>
#include <hrsr/io/point_set_reader.h>
#include <hrsr/reconstruction.h>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 3) return std::fprintf(stderr, "usage: %s INPUT OUTPUT.ply\n", argv[0]), 2;
    try {
        const hrsr::PointSet input = hrsr::io::read_point_set(argv[1]);
        hrsr::ReconstructionReport report;
        const hrsr::Reconstruction mesh = hrsr::reconstruct(input, {}, {}, report);
        std::vector<hrsr::Vec3> positions;
        for (std::uint32_t i : mesh.vertex_input_index) positions.push_back(input.positions[i]);
        hrsr::io::write_mesh(argv[2], positions, mesh.vertex_normals, mesh.triangles,
                             input.precision,
                             hrsr::gather(input.attributes, mesh.vertex_input_index));
        const hrsr::ComponentTopology* largest = hrsr::largest_component(report.mesh);
        std::printf("%zu vertices, %zu triangles, genus %ld\n", report.mesh.vertices,
                    report.mesh.faces, largest ? largest->genus() : 0L);
    } catch (const hrsr::Error& e) {
        return std::fprintf(stderr, "%s\n", e.what()), 1;
    }
}
