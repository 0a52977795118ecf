#include "preprocess/preprocess.h"

#include "errors.h"
#include "knn.h"
#include "preprocess/components.h"
#include "preprocess/noise_level.h"
#include "preprocess/orientation.h"
#include "preprocess/pca_normals.h"
#include "preprocess/smoothing.h"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace hrsr {

namespace {

// Starts a phase: progress, and a timing entry in the report when it ends.
class Phase {
public:
    Phase(const Execution& exec, PreprocessReport& report, std::string name)
        : report_(report), name_(std::move(name)), start_(std::chrono::steady_clock::now()) {
        if (exec.progress) exec.progress->begin(name_);
    }
    ~Phase() {
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
        report_.timings.emplace_back(name_, elapsed.count());
    }

private:
    PreprocessReport& report_;
    std::string name_;
    std::chrono::steady_clock::time_point start_;
};

std::vector<Vec3> estimate(const std::vector<Vec3>& positions, const KnnIndex& index,
                           const PreprocessOptions& options, const Execution& exec,
                           PreprocessReport& report, NeighbourReach& reach) {
    Phase phase(exec, report, "normal estimation");
    if (positions.size() < 3) {
        for (PointFate& f : report.fate)
            if (f == PointFate::Kept) f = PointFate::NoNormal;
        throw InvalidInput("only " + std::to_string(positions.size()) +
                           " distinct point(s): at least 3 are needed to estimate normals");
    }
    report.pca_neighbours = neighbour_count(positions.size(), options.k_normals);
    PcaNormals pca = estimate_normals(positions, index, report.pca_neighbours, exec, &reach);
    report.pca_degenerate = pca.degenerate;
    if (pca.normals.empty()) {
        for (PointFate& f : report.fate)
            if (f == PointFate::Kept) f = PointFate::NoNormal;
        throw InvalidInput("cannot estimate normals: all " + std::to_string(positions.size()) +
                           " distinct points lie on one line (PCA is undefined); give the cloud "
                           "normals or add points off the line");
    }
    return std::move(pca.normals);
}

// A kd-tree of the positions a round reads, and what the rounds before found (knn.h).
struct Neighbourhoods {
    const KnnIndex& index;
    NeighbourReach& reach;
};

// One round's positions. They are returned, not assigned: `near.index` may be built on
// `positions` (knn.h: their storage must outlive the tree), so the caller replaces them once the
// tree is gone.
std::vector<Vec3> smooth(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                         Neighbourhoods near, bool oriented, const PreprocessOptions& options,
                         const Execution& exec, PreprocessReport& report) {
    Phase phase(exec, report, "smoothing");
    report.smoothing_neighbours = neighbour_count(positions.size(), options.k_smoothing);
    SmoothingResult s = smooth_along_normals(
        positions, normals, near.index, report.smoothing_neighbours, oriented, exec, &near.reach);
    ++report.smoothing_rounds;
    report.smoothing_mean_shift = s.mean_shift; // normalised units = fraction of the diagonal
    report.smoothing_max_shift = s.max_shift;
    return std::move(s.positions);
}

// Input normals are used as given; half of them flipped gives two interleaved surfaces, one per
// orientation (the normal filter keeps them apart). Not silent: warn and name the remedy.
// D-54: a lone normal facing against its whole neighbourhood is a scanner's slip, turned here
// (and written as given); left, its point folds or stays out of the mesh.
void check_input_orientation(const KnnIndex& index, PreparedCloud& cloud, const Execution& exec,
                             PreprocessReport& report) {
    Phase phase(exec, report, "normal check");
    const OpposedNormals opposed = opposed_normals(index, cloud.normals, exec);
    report.opposed_input_normals = opposed.to_nearest;
    for (std::uint32_t p :
         turn_lone_flipped_normals(index, cloud.normals, opposed.to_a_near_one, exec))
        cloud.turned_normals.push_back(cloud.input_index[PointIndex(p)]);
    std::sort(cloud.turned_normals.begin(), cloud.turned_normals.end());
    report.turned_input_normals = cloud.turned_normals.size();
    if (double(report.opposed_input_normals) <=
        constants::kOpposedNormalsWarningFraction * double(cloud.size()))
        return;
    report.input_normals_look_inconsistent = true;
    report.warnings.push_back(
        std::to_string(report.opposed_input_normals) + " of " + std::to_string(cloud.size()) +
        " input normals point away from their nearest neighbour's: they look inconsistently "
        "oriented (re-estimate them), or two sheets are closer than the "
        "point spacing");
}

// A duplicate is wherever its representative went (kept, or dropped with it).
void propagate_fates_to_duplicates(PreprocessReport& report) {
    for (std::size_t i = 0; i < report.fate.size(); ++i)
        if (report.fate[i] == PointFate::Duplicate &&
            report.fate[report.duplicate_of[i]] != PointFate::Kept)
            report.fate[i] = report.fate[report.duplicate_of[i]];
}

// D-33: whether HRsR should collapse and re-expand on smoothed positions; the noise is
// measured on the input positions (`index` is built on them).
bool noisy(const PreparedCloud& cloud, const KnnIndex& index, const Execution& exec,
           PreprocessReport& report) {
    Phase phase(exec, report, "noise level");
    report.relative_noise = relative_noise(cloud.positions, cloud.normals, index, exec);
    report.denoised = report.relative_noise > constants::kNoisyCloud;
    return report.denoised;
}

// D-33: the input normals' mean over the smoothing neighbourhood, in two rounds as the
// positions get (`index` on the input positions).
std::vector<Vec3> neighbourhood_mean_normals(const PreparedCloud& cloud, const KnnIndex& index,
                                             const PreprocessOptions& options,
                                             const Execution& exec, NeighbourReach& reach) {
    const int neighbours = neighbour_count(cloud.size(), options.k_smoothing);
    std::vector<Vec3> mean = cloud.normals;
    for (int round = 0; round < 2; ++round)
        mean = averaged_normals(mean, index, neighbours, exec, &reach);
    return mean;
}

// D-33 for RsR with input normals: in a noisy cloud its points are smoothed and embedded along
// their normals' mean over the smoothing neighbourhood, as HRsR's are (1M triple torus with
// 0.3 % noise: 449 boundary edges in 15 pieces with the input normals, closed with the mean).
void average_normals_if_noisy(PreparedCloud& cloud, const KnnIndex& index,
                              const PreprocessOptions& options, const Execution& exec,
                              PreprocessReport& report, NeighbourReach& reach) {
    if (noisy(cloud, index, exec, report))
        cloud.normals = neighbourhood_mean_normals(cloud, index, options, exec, reach);
}

// §4.4's two rounds on the whole cloud, each through a kd-tree of the previous round's
// positions (`index` comes in on cloud.smoothed and leaves on the last round's), the normals
// re-estimated after each where they are estimated.
void smoothing_rounds(PreparedCloud& cloud, std::unique_ptr<KnnIndex>& index, NeighbourReach& reach,
                      bool estimated, const PreprocessOptions& options, const Execution& exec,
                      PreprocessReport& report) {
    for (int round = 0; round < 2; ++round) {
        std::vector<Vec3> next = smooth(cloud.smoothed, cloud.normals, {*index, reach}, !estimated,
                                        options, exec, report);
        index.reset(); // built on the positions being replaced
        cloud.smoothed = std::move(next);
        index = std::make_unique<KnnIndex>(cloud.smoothed, exec);
        if (estimated)
            cloud.normals = estimate(cloud.smoothed, *index, options, exec, report, reach);
    }
}

} // namespace

std::vector<Vec3> smoothed_positions(const std::vector<Vec3>& positions,
                                     const std::vector<Vec3>& normals,
                                     const PreprocessOptions& options, const Execution& exec,
                                     PreprocessReport& report, const KnnIndex* index_of_positions,
                                     NeighbourReach* reach_of_positions) {
    std::vector<Vec3> smoothed = positions;
    if (options.distance != DistanceMode::Tangent || positions.size() < 2) return smoothed;
    NeighbourReach own_reach;
    NeighbourReach& reach = reach_of_positions ? *reach_of_positions : own_reach;
    for (int round = 0; round < 2; ++round) {
        std::vector<Vec3> next;
        {
            std::optional<KnnIndex> own; // each round reads the previous one's positions
            const KnnIndex& index = round == 0 && index_of_positions ? *index_of_positions
                                                                     : own.emplace(smoothed, exec);
            next = smooth(smoothed, normals, {index, reach}, true, options, exec, report);
        }
        smoothed = std::move(next);
    }
    return smoothed;
}

CsrGraph neighbour_graph(const std::vector<Vec3>& positions, int k, const Execution& exec) {
    const KnnIndex index(positions, exec);
    return symmetric_union(knn_table(index, k, exec), positions.size(), exec);
}

PreparedCloud prepare_points(const PointSet& input, const PreprocessOptions& options,
                             const Execution& exec, PreprocessReport& report, PrepareFor purpose,
                             InputOrder order, PreparedExtras extras) {
    validate(options);
    if (extras.index_of_positions) extras.index_of_positions->reset();
    PreparedCloud cloud;
    {
        Phase phase(exec, report, "validation");
        SanitizedCloud clean = sanitize(input, options, report, exec, order);
        cloud.input_index = std::move(clean.input_index);
        cloud.positions = std::move(clean.positions);
        cloud.normals = std::move(clean.normals);
        cloud.normalisation = clean.normalisation;
    }
    const bool estimated = report.normal_origin == NormalOrigin::Estimated;
    const bool tangent = options.distance == DistanceMode::Tangent;
    // HRsR with input normals collapses the unsmoothed positions and smooths only the collapsed
    // cloud (§7): no smoothed copy of the full cloud; its kd-tree only serves the normal check.
    if (purpose == PrepareFor::Collapse && !estimated && !extras.graph) {
        auto kept = std::make_unique<KnnIndex>(cloud.positions, exec);
        const KnnIndex& index = *kept;
        check_input_orientation(index, cloud, exec, report);
        if (tangent && noisy(cloud, index, exec, report)) {
            // D-33: noise moved the points along the surface too, away from where their input
            // normals were measured. Smoothed along those, a noisy cloud folds (1M triple torus
            // with 0.3 % noise: 62k intersecting pairs); their mean over the smoothing
            // neighbourhood, in two rounds as the positions get, is the surface's where the
            // points lie (30 pairs).
            NeighbourReach reach;
            cloud.smoothed_normals = neighbourhood_mean_normals(cloud, index, options, exec, reach);
            cloud.smoothed = smoothed_positions(cloud.positions, cloud.smoothed_normals, options,
                                                exec, report, &index, &reach);
        }
        if (extras.index_of_positions) *extras.index_of_positions = std::move(kept);
        return cloud;
    }
    cloud.smoothed = cloud.positions;

    // Schedule of §4.4: each round reads the previous round's positions through a kd-tree
    // built on them; with estimated normals they are re-estimated after each round.
    auto index = std::make_unique<KnnIndex>(cloud.smoothed, exec);
    NeighbourReach reach; // the rounds below ask the same k of the same points, moved
    if (estimated)
        cloud.normals = estimate(cloud.smoothed, *index, options, exec, report, reach);
    else
        check_input_orientation(*index, cloud, exec, report);
    // The index is on the input positions until the first smoothing round (D-33).
    if (purpose == PrepareFor::Collapse && tangent) noisy(cloud, *index, exec, report);
    if (purpose == PrepareFor::Rsr && tangent && !estimated)
        average_normals_if_noisy(cloud, *index, options, exec, report, reach);
    // With input normals, HRsR needs no smoothing of the full cloud: it collapses the unsmoothed
    // positions and smooths the collapsed cloud (§7).
    if (tangent && (estimated || purpose == PrepareFor::Rsr))
        smoothing_rounds(cloud, index, reach, estimated, options, exec, report);
    if (report.pca_degenerate > 0)
        report.warnings.push_back(std::to_string(report.pca_degenerate) +
                                  " points had no defined PCA normal and took their nearest "
                                  "neighbour's");

    if (estimated || extras.graph) {
        CsrGraph g;
        std::vector<double> radius(cloud.size(), 0.0);
        {
            Phase phase(exec, report, "neighbour graph");
            KnnTable table = knn_table(*index, options.k, exec);
            index.reset(); // the last kd-tree: free it before the union's big arrays
            for (std::size_t i = 0; i < table.size(); ++i)
                radius[i] = (cloud.smoothed[table.row(i)[table.k - 1]] - cloud.smoothed[i]).Norm();
            g = symmetric_union(std::move(table), cloud.size(), exec);
        }
        if (estimated) {
            Phase phase(exec, report, "normal orientation");
            const OrientationResult o = orient_normals(g, cloud.smoothed, radius, cloud.normals);
            report.orientation_flips = o.flips;
            report.orientation_components = o.components;
        }
        if (extras.graph) *extras.graph = std::move(g);
    }
    if (purpose == PrepareFor::Collapse && report.denoised && estimated)
        // Smoothed again from the input positions along the final normals: the rounds above
        // moved points along the first, noisier estimates (D-33).
        cloud.smoothed = smoothed_positions(cloud.positions, cloud.normals, options, exec, report);
    if (purpose == PrepareFor::Collapse && !report.denoised)
        std::vector<Vec3>().swap(cloud.smoothed); // unused
    return cloud;
}

namespace {

// keep_components over the cloud's own origin map: input_index (the pre-processed cloud) or node
// (the coarse cloud).
template <class Key, class Origin>
PreparedCloud keep_components(const PreparedCloud& cloud, const ComponentSplit& split,
                              IndexVector<Key, Origin> PreparedCloud::*origin,
                              std::vector<Origin>& dropped) {
    PreparedCloud kept;
    kept.normalisation = cloud.normalisation;
    kept.turned_normals = cloud.turned_normals;
    kept.component_count = split.count;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Origin from = (cloud.*origin)[Key(std::uint32_t(i))];
        if (split.label[i] == ComponentSplit::kDropped) {
            dropped.push_back(from);
            continue;
        }
        (kept.*origin).push_back(from);
        kept.positions.push_back(cloud.positions[i]);
        kept.smoothed.push_back(cloud.smoothed[i]);
        kept.normals.push_back(cloud.normals[i]);
        if (!cloud.smoothed_normals.empty())
            kept.smoothed_normals.push_back(cloud.smoothed_normals[i]);
        if (!cloud.weights.empty()) kept.weights.push_back(cloud.weights[i]);
        if (!cloud.handle_reach.empty()) kept.handle_reach.push_back(cloud.handle_reach[i]);
        kept.component.push_back(split.label[i]);
    }
    if (cloud.neighbours.size() == cloud.size() && cloud.size() > 0) {
        std::vector<std::uint32_t> renumbered(cloud.size(), kNoNeighbour);
        for (std::uint32_t i = 0, next = 0; i < cloud.size(); ++i)
            if (split.label[i] != ComponentSplit::kDropped) renumbered[i] = next++;
        kept.neighbours.k = cloud.neighbours.k;
        kept.neighbours.index.reserve(kept.size() * std::size_t(cloud.neighbours.k));
        for (std::size_t i = 0; i < cloud.size(); ++i) {
            if (split.label[i] == ComponentSplit::kDropped) continue;
            const std::uint32_t* row = cloud.neighbours.row(i);
            for (int j = 0; j < cloud.neighbours.k; ++j)
                kept.neighbours.index.push_back(renumbered[row[j]]);
        }
    }
    return kept;
}

} // namespace

PreparedCloud keep_components(const PreparedCloud& cloud, const ComponentSplit& split,
                              std::vector<InputIndex>& dropped) {
    return keep_components(cloud, split, &PreparedCloud::input_index, dropped);
}

PreparedCloud keep_components(const PreparedCloud& cloud, const ComponentSplit& split,
                              std::vector<PointIndex>& dropped) {
    return keep_components(cloud, split, &PreparedCloud::node, dropped);
}

void record_split(const ComponentSplit& split, const Normalisation& normalisation,
                  PreprocessReport& report) {
    report.cut_length = split.cut_length / normalisation.scale;
    report.edges_cut = split.edges_cut;
    report.edges_beyond_input_reach = split.edges_beyond_reach;
    report.components_kept = split.count;
    report.components_dropped = split.dropped_components;
    report.component_sizes = split.sizes;
}

PreparedCloud preprocess(const PointSet& input, const PreprocessOptions& options,
                         const Execution& exec, PreprocessReport& report, InputOrder order) {
    CsrGraph graph;
    PreparedCloud cloud =
        prepare_points(input, options, exec, report, PrepareFor::Rsr, order, {&graph, nullptr});
    ComponentSplit split;
    {
        Phase phase(exec, report, "component split");
        split =
            split_components(graph, cloud.positions, cloud.smoothed, cloud.normals, options, exec);
    }
    graph = CsrGraph();
    record_split(split, cloud.normalisation, report);
    std::vector<InputIndex> dropped;
    PreparedCloud kept = keep_components(cloud, split, dropped);
    for (InputIndex i : dropped) report.fate[i.value()] = PointFate::SmallComponent;
    propagate_fates_to_duplicates(report);
    if (split.dropped_components > 0)
        report.warnings.push_back(
            std::to_string(report.count(PointFate::SmallComponent)) + " points in " +
            std::to_string(split.dropped_components) + " components smaller than " +
            std::to_string(options.min_component_size) + " points were dropped");
    if (kept.size() == 0)
        throw InvalidInput(
            "no point is left after pre-processing (every component is smaller than " +
            std::to_string(options.min_component_size) + " points)");
    return kept;
}

} // namespace hrsr
