#include "preprocess/sanitize.h"

#include "errors.h"
#include "preprocess/near_duplicates.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <parallel/algorithm>
#include <string>

namespace hrsr {

namespace {

bool is_finite(const Vec3& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

// Returns why the input normals cannot be used, or "" when they can.
std::string unusable_normals_reason(const PointSet& input, const std::vector<PointFate>& fate) {
    if (input.normals.size() != input.positions.size())
        return "the input has " + std::to_string(input.normals.size()) + " normals for " +
               std::to_string(input.positions.size()) + " points";
    std::size_t non_finite = 0, zero = 0;
    for (std::size_t i = 0; i < input.normals.size(); ++i) {
        if (fate[i] != PointFate::Kept) continue;
        const Vec3& n = input.normals[i];
        if (!is_finite(n))
            ++non_finite;
        else if (n.Norm() < constants::kMinNormalLength)
            ++zero;
    }
    if (non_finite + zero == 0) return "";
    return std::to_string(non_finite) + " non-finite and " + std::to_string(zero) +
           " zero-length input normals";
}

// Exact duplicates (D-3) in a sequence where equal kept points follow each other in index order:
// each run's first point represents the rest.
template <class Sequence>
void merge_runs(const Sequence& sequence, const PointSet& input, PreprocessReport& report) {
    bool have_previous = false;
    std::uint32_t previous = 0;
    for (const std::uint32_t i : sequence) {
        if (report.fate[i] != PointFate::Kept) continue;
        if (have_previous && input.positions[previous] == input.positions[i]) {
            report.fate[i] = PointFate::Duplicate;
            report.duplicate_of[i] = report.duplicate_of[previous];
        }
        previous = i;
        have_previous = true;
    }
}

// Any order: the kept points sorted as records with their coordinates (twice as fast as indices
// compared through the positions, measured on the 3.2M dragon); (position, index) orders every
// pair of points, so the parallel sort gives the sequential order for any thread count.
void merge_duplicates(const PointSet& input, const Execution& exec, PreprocessReport& report) {
    struct Record {
        Vec3 p;
        std::uint32_t index;
    };
    std::vector<Record> order;
    for (std::uint32_t i = 0; i < input.size(); ++i)
        if (report.fate[i] == PointFate::Kept) order.push_back({input.positions[i], i});
    auto less = [](const Record& a, const Record& b) {
        if (a.p[0] != b.p[0]) return a.p[0] < b.p[0];
        if (a.p[1] != b.p[1]) return a.p[1] < b.p[1];
        if (a.p[2] != b.p[2]) return a.p[2] < b.p[2];
        return a.index < b.index;
    };
    __gnu_parallel::sort(order.begin(), order.end(), less,
                         __gnu_parallel::balanced_quicksort_tag(thread_count(exec)));
    std::vector<std::uint32_t> sorted(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = order[k].index;
    merge_runs(sorted, input, report);
}

// In spatial order (InputOrder::Spatial) the sort above would leave the kept points where they
// are, so the runs are found in one pass. That sort was 0.34 s of the 3.2M dragon sample's 0.76 s
// of validation (docs/BENCHMARKS.md, session 28).
void merge_adjacent_duplicates(const PointSet& input, PreprocessReport& report) {
    std::vector<std::uint32_t> all(input.size());
    std::iota(all.begin(), all.end(), 0u);
    merge_runs(all, input, report);
}

Normalisation bounding_box_normalisation(const std::vector<Vec3>& points, double& diagonal) {
    Vec3 lo = points.front(), hi = points.front();
    for (const Vec3& q : points)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], q[a]);
            hi[a] = std::max(hi[a], q[a]);
        }
    diagonal = (hi - lo).Norm();
    if (!std::isfinite(diagonal))
        throw InvalidInput("the point coordinates span more than the double-precision range");
    Normalisation t;
    t.centre = lo * 0.5 + hi * 0.5; // halves first: no overflow near the double range
    t.scale = diagonal > 0 ? 1.0 / diagonal : 1.0;
    return t;
}

// D-25: points closer than kNearDuplicateDistance (normalised units, i.e. a fraction of the
// diagonal) to a kept point before them (in the order given) are merged into it like exact
// duplicates. Their edges are about as short as the rotation-angle cut-off (D-1), so RsR saw them
// at angle 0 whatever their direction and tore the surface (measured: a 3k sphere with every point
// doubled at 1e-12 x the diagonal came out as 566 pieces; at 1e-11 with 13 boundary edges; from
// 1e-10 on, closed).
void merge_near_duplicates(SanitizedCloud& cloud, const Execution& exec, PreprocessReport& report) {
    const std::vector<std::uint32_t> representative =
        near_duplicate_representatives(cloud.positions, constants::kNearDuplicateDistance, exec);
    std::size_t merged = 0;
    for (std::size_t i = 0; i < representative.size(); ++i) merged += representative[i] != i;
    if (merged == 0) return; // the usual case: no copy of the cloud
    SanitizedCloud kept;
    kept.normalisation = cloud.normalisation;
    for (std::size_t i = 0; i < representative.size(); ++i) {
        const InputIndex input = cloud.input_index[PointIndex(std::uint32_t(i))];
        if (representative[i] != i) {
            report.fate[input.value()] = PointFate::Duplicate;
            report.duplicate_of[input.value()] =
                cloud.input_index[PointIndex(representative[i])].value();
            continue;
        }
        kept.input_index.push_back(input);
        kept.positions.push_back(cloud.positions[i]);
        if (!cloud.normals.empty()) kept.normals.push_back(cloud.normals[i]);
    }
    // Exact duplicates of a merged point follow it to its representative.
    for (std::uint32_t& d : report.duplicate_of) d = report.duplicate_of[d];
    char tolerance[32];
    std::snprintf(tolerance, sizeof tolerance, "%g", constants::kNearDuplicateDistance);
    report.warnings.push_back(std::to_string(merged) + " points closer than " + tolerance +
                              " x the bounding-box diagonal to another point were merged into it");
    cloud = std::move(kept);
}

} // namespace

SanitizedCloud sanitize(const PointSet& input, const PreprocessOptions& options,
                        PreprocessReport& report, const Execution& exec, InputOrder order) {
    const std::size_t n = input.size();
    const Execution quiet = without_progress(exec); // the phase reports no fraction of its own
    report.input_points = n;
    report.fate.assign(n, PointFate::Kept);
    report.duplicate_of.resize(n);
    std::iota(report.duplicate_of.begin(), report.duplicate_of.end(), 0u);

    std::size_t non_finite = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!is_finite(input.positions[i])) {
            report.fate[i] = PointFate::NonFinite;
            ++non_finite;
        }
    if (non_finite > 0)
        report.warnings.push_back(std::to_string(non_finite) +
                                  " points with non-finite coordinates were dropped");
    if (non_finite == n)
        throw InvalidInput(n == 0 ? "the point cloud is empty"
                                  : "none of the " + std::to_string(n) +
                                        " points has finite coordinates");

    bool use_normals = input.has_normals() && options.normals == NormalSource::Input;
    if (use_normals) {
        report.normals_fallback_reason = unusable_normals_reason(input, report.fate);
        if (!report.normals_fallback_reason.empty()) {
            use_normals = false;
            report.warnings.push_back(report.normals_fallback_reason +
                                      ": normals are estimated for the whole cloud instead");
        }
    }
    report.normal_origin = use_normals ? NormalOrigin::Input : NormalOrigin::Estimated;

    if (order == InputOrder::Spatial)
        merge_adjacent_duplicates(input, report);
    else
        merge_duplicates(input, quiet, report);
    const std::size_t duplicates = report.count(PointFate::Duplicate);
    if (duplicates > 0)
        report.warnings.push_back(
            std::to_string(duplicates) +
            " exact duplicate points were merged into their first occurrence");

    SanitizedCloud cloud;
    const std::size_t kept = report.count(PointFate::Kept);
    cloud.input_index.reserve(kept);
    cloud.positions.reserve(kept);
    if (use_normals) cloud.normals.reserve(kept);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (report.fate[i] != PointFate::Kept) continue;
        cloud.input_index.push_back(InputIndex(i));
        cloud.positions.push_back(input.positions[i]);
        if (!use_normals) continue;
        const Vec3& normal = input.normals[i];
        const double length = normal.Norm();
        if (std::abs(length - 1.0) > 1e-6) ++report.normals_renormalised;
        cloud.normals.push_back(normal / length);
    }
    cloud.normalisation = bounding_box_normalisation(cloud.positions, report.bbox_diagonal);
    const Normalisation& t = cloud.normalisation;
    parallel_for_blocks(quiet, cloud.positions.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i)
                                cloud.positions[i] = (cloud.positions[i] - t.centre) * t.scale;
                        });
    merge_near_duplicates(cloud, quiet, report);
    return cloud;
}

} // namespace hrsr
