#include "mesh/face_quality.h"

#include "geometry.h"

#include <algorithm>
#include <cmath>

namespace hrsr {

bool is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double longest =
        std::max({(b - a).SquaredNorm(), (c - b).SquaredNorm(), (a - c).SquaredNorm()});
    return ((b - a) ^ (c - a)).Norm() <= 1e-12 * longest;
}

FaceQuality face_quality(const std::vector<Vec3>& p, const std::vector<Triangle>& triangles,
                         const std::vector<Triangle>& welded) {
    FaceQuality q;
    std::vector<double> angles;
    angles.reserve(triangles.size());
    for (const Triangle& t : triangles) {
        const bool repeated = t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
        if (repeated || is_degenerate(p[t[0]], p[t[1]], p[t[2]])) {
            ++q.degenerate_faces;
            q.repeated_vertex_faces += repeated;
            continue;
        }
        angles.push_back(smallest_angle(p[t[0]], p[t[1]], p[t[2]]) * 180.0 / M_PI);
    }
    std::vector<Triangle> sorted = welded;
    for (Triangle& t : sorted) std::sort(t.begin(), t.end());
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i) q.duplicate_faces += sorted[i] == sorted[i - 1];

    MinAngleStats& s = q.min_angle;
    s.faces = angles.size();
    if (angles.empty()) return q;
    double sum = 0;
    for (double a : angles) {
        sum += a;
        s.below_1_degree += a < 1.0;
        s.below_10_degrees += a < 10.0;
    }
    s.mean = sum / double(angles.size());
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    s.median = angles[angles.size() / 2];
    s.min = *std::min_element(angles.begin(), angles.end());
    return q;
}

} // namespace hrsr
