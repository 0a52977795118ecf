// Helpers of the robustness suite: run the core on a cloud and classify what happened (a mesh,
// or which error with which message), and check the properties every mesh must have.
#pragma once

#include "errors.h"
#include "reconstruction_observed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <new>
#include <string>

namespace hrsr::testing {

/// What one reconstruction did: a mesh, or an error of a known kind.
struct Attempt {
    enum Kind { Mesh, BadInput, BadOption, Cancel, OtherError } kind = Mesh;
    std::string message;
    Reconstruction mesh;
    ReconstructionReport report;

    bool has_warning(const std::string& word) const {
        for (const std::string& w : report.preprocess.warnings)
            if (w.find(word) != std::string::npos) return true;
        return false;
    }
};

inline const char* to_string(Attempt::Kind k) {
    static const char* names[] = {"a mesh", "InvalidInput", "InvalidOption", "Cancelled",
                                  "another error"};
    return names[k];
}

inline Attempt attempt(const PointSet& cloud, Method method, ReconstructionOptions options = {},
                       const Execution& exec = {}, rsr::Observer* observer = nullptr) {
    options.method = method;
    Attempt a;
    try {
        a.mesh = reconstruct(cloud, options, exec, a.report, observer);
    } catch (const InvalidInput& e) {
        a = {Attempt::BadInput, e.what(), {}, {}};
    } catch (const InvalidOption& e) {
        a = {Attempt::BadOption, e.what(), {}, {}};
    } catch (const Cancelled& e) {
        a = {Attempt::Cancel, e.what(), {}, {}};
    } catch (const std::exception& e) {
        a = {Attempt::OtherError, e.what(), {}, {}};
    }
    return a;
}

inline const char* name(Method m) {
    return m == Method::Hrsr ? "hrsr" : "rsr";
}

inline constexpr Method kMethods[] = {Method::Hrsr, Method::Rsr};

/// The error kind and a word of its message.
inline void expect_error(const Attempt& a, Attempt::Kind kind, const std::string& word,
                         const std::string& context) {
    EXPECT_EQ(a.kind, kind) << context << ": got " << to_string(a.kind) << " " << a.message;
    EXPECT_NE(a.message.find(word), std::string::npos)
        << context << ": \"" << a.message << "\" does not say \"" << word << "\"";
}

/// What every mesh must be: non-empty, edge- and vertex-manifold, consistently oriented, no
/// degenerate triangle, vertices at finite input points with unit normals.
inline void expect_valid_mesh(const Attempt& a, const PointSet& input, const std::string& context) {
    ASSERT_EQ(a.kind, Attempt::Mesh) << context << ": " << a.message;
    const MeshStats& m = a.report.mesh;
    EXPECT_GT(m.faces, 0u) << context;
    EXPECT_EQ(m.non_manifold_edges, 0u) << context;
    EXPECT_EQ(m.non_manifold_vertices, 0u) << context;
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u) << context;
    EXPECT_EQ(m.degenerate_faces, 0u) << context;
    EXPECT_EQ(m.unreferenced_vertices, 0u) << context;
    ASSERT_EQ(a.mesh.vertex_normals.size(), a.mesh.vertex_input_index.size()) << context;
    for (std::size_t v = 0; v < a.mesh.vertex_input_index.size(); ++v) {
        const std::uint32_t i = a.mesh.vertex_input_index[v];
        ASSERT_LT(i, input.size()) << context;
        const Vec3& p = input.positions[i];
        ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) << context;
        ASSERT_NEAR(a.mesh.vertex_normals[v].Norm(), 1.0, 1e-9) << context;
    }
}

/// One closed component of the given genus with every distinct point a vertex.
inline void expect_closed(const Attempt& a, const PointSet& input, long genus, std::size_t vertices,
                          const std::string& context) {
    expect_valid_mesh(a, input, context);
    if (a.kind != Attempt::Mesh) return;
    const MeshStats& m = a.report.mesh;
    EXPECT_EQ(m.vertices, vertices) << context;
    EXPECT_EQ(m.boundary_edges, 0u) << context;
    ASSERT_EQ(m.components.size(), 1u) << context;
    EXPECT_EQ(m.components[0].genus(), genus) << context;
}

/// Same connectivity: the same input points in the same vertex order, the same triangles.
inline bool same_connectivity(const Reconstruction& a, const Reconstruction& b) {
    return a.vertex_input_index == b.vertex_input_index && a.triangles == b.triangles;
}

} // namespace hrsr::testing
