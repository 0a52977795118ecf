// An RsR observer that checks the invariants of ALGORITHM.md §13 after insertions.
#pragma once

#include "rsr/observer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace hrsr::testing {

class InvariantChecker : public rsr::Observer {
public:
    /// `full_check_every`: re-trace every face after every n-th insertion (1 = always).
    explicit InvariantChecker(std::size_t full_check_every = 1) : every_(full_check_every) {}

    void tree_built(const rsr::RotationSystem& rs, const rsr::Faces& faces) override {
        // A spanning tree: one face of 2(M − 1) darts per tree.
        EXPECT_EQ(long(rs.vertex_count()) - long(rs.edge_count()) + long(faces.count()),
                  2L * long(faces.count()));
        check_faces(rs, faces);
        euler_ = long(rs.vertex_count()) - long(rs.edge_count()) + long(faces.count());
    }

    void edge_inserted(rsr::Phase phase, std::uint32_t u, std::uint32_t v,
                       const rsr::RotationSystem& rs, const rsr::Faces& faces,
                       const std::vector<rsr::LocalTriangle>& triangles,
                       std::size_t new_triangles) override {
        ++insertions_;
        EXPECT_TRUE(rs.adjacent(u, v) && rs.adjacent(v, u));
        const long euler = long(rs.vertex_count()) - long(rs.edge_count()) + long(faces.count());
        if (phase == rsr::Phase::Handles) {
            // D-11: a handle edge merges two faces (χ − 2) or splits one (χ unchanged).
            EXPECT_TRUE(euler == euler_ || euler == euler_ - 2) << euler << " vs " << euler_;
            if (euler == euler_ - 2) ++merges_;
        } else {
            EXPECT_EQ(euler, euler_)
                << "phase " << int(phase) << " changed the Euler characteristic";
        }
        euler_ = euler;
        // Every new triangle is a face of the rotation, wound as the faces are traced.
        for (std::size_t t = triangles.size() - new_triangles; t < triangles.size(); ++t)
            EXPECT_TRUE(is_face(rs, faces, triangles[t])) << "triangle " << t << " is not a face";
        if (insertions_ % every_ == 0) check_faces(rs, faces);
    }

    std::size_t merges() const { return merges_; }
    long euler() const { return euler_; }

    /// Traces every face from scratch; their number must equal the structure's count, and all
    /// darts of one traced face must carry one label, distinct between faces.
    static void check_faces(const rsr::RotationSystem& rs, const rsr::Faces& faces) {
        std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
        std::set<std::uint32_t> labels;
        std::size_t traced = 0;
        for (std::uint32_t v = 0; v < rs.vertex_count(); ++v)
            for (std::uint32_t i = 0; i < rs.degree(v); ++i) {
                if (seen.count({v, rs.dart(v, i).to})) continue;
                ++traced;
                const std::uint32_t label = rs.dart(v, i).face;
                ASSERT_TRUE(labels.insert(label).second) << "two faces share label " << label;
                rsr::DartRef d{v, i};
                do {
                    ASSERT_EQ(rs.dart(d).face, label);
                    seen.insert({d.v, rs.dart(d).to});
                    d = rs.next_in_face(d);
                } while (!(d.v == v && d.i == i));
            }
        EXPECT_EQ(traced, faces.count());
    }

private:
    static bool is_face(const rsr::RotationSystem& rs, const rsr::Faces& faces,
                        const rsr::LocalTriangle& t) {
        const std::uint32_t i = rs.find(t[0], t[1]);
        if (i == rsr::kNotFound) return false;
        const std::vector<std::uint32_t> cycle = faces.vertices({t[0], i});
        return cycle == std::vector<std::uint32_t>{t[0], t[1], t[2]};
    }

    std::size_t every_;
    std::size_t insertions_ = 0;
    std::size_t merges_ = 0;
    long euler_ = 0;
};

} // namespace hrsr::testing
