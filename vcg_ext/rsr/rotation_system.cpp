#include "rsr/rotation_system.h"

#include <algorithm>

namespace hrsr::rsr {

namespace {
// Darts reserved for every vertex at once, in vertex order (a vertex of a triangle mesh has six
// neighbours on average): the rotations of nearby vertices (the points come in spatial order,
// D-40) then lie near each other in memory, where growing each one as edges come left them
// scattered; the face split reads them in length order, all over the cloud.
constexpr std::size_t kReservedDarts = 8;
} // namespace

RotationSystem::RotationSystem(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals)
    : positions_(positions), normals_(normals), rotation_(positions.size()) {
    frames_.reserve(normals.size());
    for (const Vec3& n : normals) frames_.push_back(tangent_frame(n));
    for (std::vector<Dart>& darts : rotation_) darts.reserve(kReservedDarts);
}

double RotationSystem::angle(std::uint32_t v, std::uint32_t w) const {
    return rotation_angle(frames_[v], positions_[w] - positions_[v]);
}

std::uint32_t RotationSystem::find(std::uint32_t v, std::uint32_t w) const {
    const auto& r = rotation_[v];
    for (std::uint32_t i = 0; i < r.size(); ++i)
        if (r[i].to == w) return i;
    return kNotFound;
}

// First position whose (angle, id) is greater than (angle, w): where w goes (D-4).
std::uint32_t RotationSystem::insertion_position(std::uint32_t v, double a, std::uint32_t w) const {
    const auto& r = rotation_[v];
    const auto it = std::upper_bound(
        r.begin(), r.end(), std::make_pair(a, w),
        [](const std::pair<double, std::uint32_t>& key, const Dart& d) {
            return key.first < d.angle || (key.first == d.angle && key.second < d.to);
        });
    return std::uint32_t(it - r.begin());
}

std::uint32_t RotationSystem::wedge(std::uint32_t v, std::uint32_t w) const {
    const std::uint32_t pos = insertion_position(v, angle(v, w), w);
    return pos == 0 ? degree(v) - 1 : pos - 1;
}

std::uint32_t RotationSystem::successor_as_if_inserted(std::uint32_t v, std::uint32_t w) const {
    const std::uint32_t pos = insertion_position(v, angle(v, w), w);
    return rotation_[v][pos == degree(v) ? 0 : pos].to;
}

DartRef RotationSystem::next_in_face(DartRef d) const {
    const std::uint32_t v = rotation_[d.v][d.i].to;
    return {v, prev(v, find(v, d.v))};
}

std::pair<DartRef, DartRef> RotationSystem::insert_darts(std::uint32_t v, std::uint32_t w) {
    const double av = angle(v, w), aw = angle(w, v);
    const std::uint32_t pv = insertion_position(v, av, w);
    rotation_[v].insert(rotation_[v].begin() + pv, Dart{w, kNoFace, 0, av});
    const std::uint32_t pw = insertion_position(w, aw, v);
    rotation_[w].insert(rotation_[w].begin() + pw, Dart{v, kNoFace, 0, aw});
    return {{v, pv}, {w, pw}};
}

void RotationSystem::erase_darts(std::pair<DartRef, DartRef> darts) {
    rotation_[darts.first.v].erase(rotation_[darts.first.v].begin() + darts.first.i);
    rotation_[darts.second.v].erase(rotation_[darts.second.v].begin() + darts.second.i);
}

} // namespace hrsr::rsr
