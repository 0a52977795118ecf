#include "reconstruction_observed.h"

#include "errors.h"
#include "hrsr/border_notches.h"
#include "hrsr/collapse.h"
#include "hrsr/input_reach.h"
#include "hrsr/unsampled_triangles.h"
#include "index_types.h"
#include "input_order.h"
#include "mesh/fans.h"
#include "mesh/flat_faces.h"
#include "mesh/fold_removal.h"
#include "mesh/fold_repair.h"
#include "mesh/outward.h"
#include "mesh/small_holes_fill.h"
#include "preprocess/components.h"
#include "preprocess/pca_normals.h"
#include "preprocess/preprocess.h"
#include "rsr/candidate_graph.h"
#include "rsr/handles.h"
#include "rsr/reconstruct_cloud.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace hrsr {

namespace {

class Timer {
public:
    explicit Timer(std::vector<std::pair<std::string, double>>& timings, std::string phase)
        : timings_(timings), phase_(std::move(phase)) {}
    ~Timer() {
        timings_.emplace_back(
            phase_,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    }

private:
    std::vector<std::pair<std::string, double>>& timings_;
    std::string phase_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// A mesh over a subset of a cloud's points (Point: the cloud's index space), manifold after
/// the fan split (§5.8).
template <class Point>
struct CompactMesh {
    IndexVector<VertexIndex, Point> vertex_point; ///< the cloud point (copies share it)
    std::vector<Triangle> triangles;              ///< over vertices
    std::vector<Point> unused;                    ///< cloud points in no triangle
};

// Used points become vertices in point order; non-manifold ones get one copy per extra fan.
// `triangles` are over the points on entry, over the vertices on return.
template <class Point>
CompactMesh<Point> compact(std::size_t points, std::vector<Triangle> triangles,
                           const Execution& exec) {
    CompactMesh<Point> m;
    const std::vector<std::uint32_t> source =
        compact_and_split_vertices(points, triangles, nullptr, exec);
    std::vector<std::uint8_t> used(points, 0);
    for (std::uint32_t p : source) used[p] = 1;
    for (std::uint32_t p = 0; p < points; ++p)
        if (!used[p]) m.unused.push_back(Point(p));
    for (std::uint32_t p : source) m.vertex_point.push_back(Point(p));
    m.triangles = std::move(triangles);
    return m;
}

// D-6: closed components enclosing a negative volume are turned inside out (which changes none
// of the measures in `stats`).
void orient_outward(const std::vector<Vec3>& positions, const MeshStats& stats,
                    const std::vector<std::uint32_t>& component, Reconstruction& mesh,
                    ReconstructionReport& report) {
    report.flipped_components += turn_closed_components_outwards(
        positions, stats, component, mesh.triangles, mesh.vertex_normals);
}

// The output: vertices at the cloud points they stand for, with their normals.
Reconstruction make_output(const PreparedCloud& cloud,
                           const IndexVector<VertexIndex, PointIndex>& vertex_point,
                           std::vector<Triangle> triangles) {
    Reconstruction mesh;
    mesh.triangles = std::move(triangles);
    mesh.vertex_input_index.reserve(vertex_point.size());
    mesh.vertex_normals.reserve(vertex_point.size());
    for (PointIndex p : vertex_point) {
        mesh.vertex_input_index.push_back(cloud.input_index[p].value());
        mesh.vertex_normals.push_back(cloud.normals[p.value()]);
    }
    return mesh;
}

// The mesh as written, measured into report.mesh once the fold repair is done (so that the
// measures and D-6 see the faces it cut and added), and its closed components turned outwards.
void measure_output(const PointSet& input, const Normalisation& normalisation, bool outward,
                    const Execution& exec, Reconstruction& mesh, ReconstructionReport& report) {
    Timer timer(report.timings, "measure");
    std::vector<std::uint32_t> component;
    report.mesh = measure_mesh(mesh.vertex_input_index.size(), mesh.triangles, &component, exec);
    if (!outward) return;
    // Volumes in the normalised coordinates (D-2), as sanitize() computes them: far from the
    // origin the input's own would cancel.
    std::vector<Vec3> positions;
    positions.reserve(mesh.vertex_input_index.size());
    for (std::uint32_t i : mesh.vertex_input_index)
        positions.push_back((input.positions[i] - normalisation.centre) * normalisation.scale);
    orient_outward(positions, report.mesh, component, mesh, report);
}

// The coordinates as the writers store them: the input's, at its precision. D-26 and D-32 test
// intersections there (exactly), so that what they leave is what a user's check finds.
std::vector<Vec3> written_positions(const PointSet& input, const Reconstruction& mesh,
                                    const Execution& exec) {
    std::vector<Vec3> written(mesh.vertex_input_index.size());
    parallel_for_blocks(exec, written.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t v = first; v < end; ++v) {
                                Vec3 p = input.positions[mesh.vertex_input_index[v]];
                                if (input.precision == CoordinatePrecision::Float)
                                    for (int k = 0; k < 3; ++k) p[k] = double(float(p[k]));
                                written[v] = p;
                            }
                        });
    return written;
}

// D-32's result as the output: vertices without a face go (their points are "dropped: fold"),
// copies of pinched vertices are appended. The vertices from `given` on were points in no
// triangle (D-37): those placed into a face leave report.not_in_triangle, the rest stay in it.
void take_fold_removal(const PointSet& input, FoldRemoval& removal, std::size_t given,
                       Reconstruction& mesh, ReconstructionReport& report) {
    report.fold_removal = removal.stats;
    const std::vector<std::uint32_t>& source = removal.vertex_source;
    bool same_vertices = given == mesh.vertex_input_index.size() && source.size() == given;
    for (std::size_t v = 0; same_vertices && v < source.size(); ++v) same_vertices = source[v] == v;
    if (same_vertices) return; // every vertex kept its number (D-32 and D-38 may change faces)
    std::vector<std::uint8_t> was_vertex(input.size(), 0), is_vertex(input.size(), 0);
    for (std::size_t v = 0; v < given; ++v) was_vertex[mesh.vertex_input_index[v]] = 1;
    Reconstruction out;
    out.triangles = std::move(mesh.triangles);
    for (std::uint32_t v : removal.vertex_source) {
        out.vertex_input_index.push_back(mesh.vertex_input_index[v]);
        out.vertex_normals.push_back(mesh.vertex_normals[v]);
        is_vertex[mesh.vertex_input_index[v]] = 1;
    }
    mesh = std::move(out);
    for (std::uint32_t i = 0; i < input.size(); ++i)
        if (was_vertex[i] && !is_vertex[i]) report.dropped_fold.push_back(i);
    std::vector<std::uint32_t>& unplaced = report.not_in_triangle;
    unplaced.erase(std::remove_if(unplaced.begin(), unplaced.end(),
                                  [&](std::uint32_t i) { return is_vertex[i] != 0; }),
                   unplaced.end());
}

// D-37: the points in no triangle join the mesh as vertices without a face, with their oriented
// normals, for D-32's last step to place into a face near them. Returns the vertices before.
std::size_t append_points_in_no_triangle(const PreparedCloud& cloud,
                                         const ReconstructionReport& report, Reconstruction& mesh) {
    const std::size_t given = mesh.vertex_input_index.size();
    if (report.not_in_triangle.empty()) return given;
    std::vector<std::uint32_t> point_of(report.preprocess.input_points, ~0u);
    for (PointIndex p : cloud.input_index.keys())
        point_of[cloud.input_index[p].value()] = p.value();
    for (std::uint32_t i : report.not_in_triangle) {
        mesh.vertex_input_index.push_back(i);
        mesh.vertex_normals.push_back(cloud.normals[point_of[i]]);
    }
    return given;
}

// The fold repair on the finished mesh, on the coordinates as written: one search for the
// intersecting pairs, D-26's flips, then D-32 cuts out what they left, so that the written mesh
// has no intersecting pair. `fold_repair_rounds` = 0 turns both off. The cloud is released
// before the search: the fold removal is the run's peak of memory (issue 20 item 5).
void repair_and_remove_folds(const PointSet& input, PreparedCloud cloud, const RsrOptions& options,
                             const Execution& exec, Reconstruction& mesh,
                             ReconstructionReport& report) {
    const int rounds = options.fold_repair_rounds;
    if (rounds <= 0 || mesh.triangles.size() < 2) return;
    // D-45, D-59 (both methods): the loops of a piece closed but for loops no longer than a
    // handle must be to stay (D-27's hop limit on the input cloud) are pinholes: of the coarse
    // sampling that the re-expansion widened beyond D-28's fans (HRsR), or of the noise where
    // D-38's fills cross (RsR).
    const std::size_t pinhole_edges = std::max(
        kMaxFilledLoop, rsr::handle_hop_limit(options.min_handle_loop, cloud.size(), cloud.size()));
    if (exec.progress) exec.progress->begin("fold repair");
    const std::size_t given = append_points_in_no_triangle(cloud, report, mesh);
    cloud = PreparedCloud();
    const std::vector<Vec3> written = written_positions(input, mesh, exec);
    std::optional<Timer> timer(std::in_place, report.timings, "fold search");
    FoldSearch search(written, mesh.triangles, exec);
    timer.emplace(report.timings, "fold repair");
    report.fold_repair = repair_folds(search, mesh.triangles, rounds);
    timer.emplace(report.timings, "fold removal");
    FoldRemoval removal = remove_folds(search, mesh.vertex_normals, mesh.triangles, pinhole_edges);
    take_fold_removal(input, removal, given, mesh, report);
}

// D-36: faces without area in the coordinates as written go (a flip or, on the border, the face).
void clear_flat_output_faces(const PointSet& input, Reconstruction& mesh, const Execution& exec,
                             ReconstructionReport& report) {
    Timer timer(report.timings, "flat faces");
    report.flat_faces =
        clear_flat_faces(written_positions(input, mesh, exec), mesh.triangles, exec);
}

// D-33 for RsR embeds a noisy cloud along its input normals' neighbourhood mean; the vertices
// keep the input's own normals (unit, as sanitize() makes them), as HRsR's do.
void restore_input_normals(const PointSet& input, const PreprocessReport& pre,
                           Reconstruction& mesh) {
    if (!pre.denoised || pre.normal_origin != NormalOrigin::Input) return;
    for (std::size_t v = 0; v < mesh.vertex_input_index.size(); ++v) {
        const Vec3& n = input.normals[mesh.vertex_input_index[v]];
        mesh.vertex_normals[v] = n / n.Norm();
    }
}

// D-54: the normals turned for the algorithm (and the fold repair) are written as the input gave
// them. `turned`: input indices, increasing.
void write_turned_normals_as_given(const std::vector<InputIndex>& turned, Reconstruction& mesh) {
    if (turned.empty()) return;
    for (std::size_t v = 0; v < mesh.vertex_input_index.size(); ++v)
        if (std::binary_search(turned.begin(), turned.end(),
                               InputIndex(mesh.vertex_input_index[v])))
            mesh.vertex_normals[v] = -mesh.vertex_normals[v];
}

// A phase boundary: progress, and the chance to cancel before the phase's work.
void begin_phase(const Execution& exec, const std::string& phase) {
    if (exec.progress) exec.progress->begin(phase);
}

// A mesh without a triangle is a failure to report, not a result to write.
void require_triangles(const Reconstruction& mesh, const ReconstructionReport& report) {
    if (!mesh.triangles.empty()) return;
    throw InvalidInput("no triangle could be built from the " + std::to_string(report.points_used) +
                       " usable points (too few, or too far apart for k = the neighbourhood size)");
}

// r_v: input points that are vertices, or exact duplicates of one (D-3). A duplicate of a point
// that is not a vertex shares that point's outcome (§13 item 10: every point has one).
void account(const PointSet& input, const Reconstruction& mesh, ReconstructionReport& report) {
    const PreprocessReport& pre = report.preprocess;
    enum : std::uint8_t { kOther, kVertex, kNoTriangle, kSmallCoarse, kFold };
    std::vector<std::uint8_t> outcome(input.size(), kOther);
    for (std::uint32_t i : mesh.vertex_input_index) outcome[i] = kVertex;
    // Counted on the output, not where copies are made: a later step (D-55's joining piece)
    // may take a copy back.
    report.vertex_copies = mesh.vertex_input_index.size() -
                           std::size_t(std::count(outcome.begin(), outcome.end(), kVertex));
    for (std::uint32_t i : report.not_in_triangle) outcome[i] = kNoTriangle;
    for (std::uint32_t i : report.dropped_small_coarse_component) outcome[i] = kSmallCoarse;
    for (std::uint32_t i : report.dropped_fold) outcome[i] = kFold;
    for (std::uint32_t i = 0; i < input.size(); ++i) {
        if (pre.fate[i] != PointFate::Duplicate) continue;
        switch (outcome[pre.duplicate_of[i]]) {
        case kVertex:
            outcome[i] = kVertex;
            break;
        case kNoTriangle:
            report.not_in_triangle.push_back(i);
            break;
        case kSmallCoarse:
            report.dropped_small_coarse_component.push_back(i);
            break;
        case kFold:
            report.dropped_fold.push_back(i);
            break;
        default:
            if (report.coarse_points > 0)
                ++report.merged_points; // its point merged into another vertex
        }
    }
    std::sort(report.not_in_triangle.begin(), report.not_in_triangle.end());
    std::sort(report.dropped_small_coarse_component.begin(),
              report.dropped_small_coarse_component.end());
    std::sort(report.dropped_fold.begin(), report.dropped_fold.end());
    report.referenced_input_points =
        std::size_t(std::count(outcome.begin(), outcome.end(), kVertex));
    report.vertex_reference_ratio =
        input.size() ? double(report.referenced_input_points) / double(input.size()) : 0;
}

void take_rsr_stats(const rsr::CloudMesh& m, ReconstructionReport& report) {
    report.candidates = m.candidates;
    report.tree_edges = m.tree_edges;
    report.face_split_edges = m.face_split_edges;
    report.handle_edges = m.handle_edges;
    report.handles = m.handles;
    report.handle_hop_limits = m.handle_hop_limits;
    report.ear_edges = m.ear_edges;
    rsr::add_timings(report.timings, m.timings);
}

// D-39: the longest loop that is a pinhole of a closed coarse piece: five edges (D-28), or, when
// more, the hop limit of RsR's handles on the coarse cloud (D-27; the smallest of its
// components'): a loop no longer than the loop a handle must close is a gap RsR took for a slit
// and left open, not a tunnel (the 5k triple torus with 0.1 % noise at p = 1/8 came out of RsR
// with its three handles and one 6-edge hole, at a hop limit of 7).
std::size_t coarse_pinhole_edges(const std::vector<std::size_t>& handle_hop_limits) {
    if (handle_hop_limits.empty()) return kMaxFilledLoop;
    return std::max(kMaxFilledLoop,
                    *std::min_element(handle_hop_limits.begin(), handle_hop_limits.end()));
}

// RsR's mesh of the coarse cloud, its non-manifold vertices split (§5.8), as the re-expansion
// takes it.
CoarseMesh coarse_mesh_of(const PreparedCloud& coarse, std::vector<Triangle> triangles,
                          const std::vector<Vec3>& geometry, int candidate_rank,
                          const Execution& exec, ReconstructionReport& report) {
    CompactMesh<CoarseIndex> m = compact<CoarseIndex>(coarse.size(), std::move(triangles), exec);
    CoarseMesh coarse_mesh;
    for (CoarseIndex p : m.vertex_point) {
        coarse_mesh.vertex_node.push_back(coarse.node[p]);
        coarse_mesh.positions.push_back(coarse.positions[p.value()]);
    }
    coarse_mesh.triangles = std::move(m.triangles);
    // D-39: a coarse piece closed but for short loops (coarse_pinhole_edges) is a closed surface
    // whose coarse sampling left pinholes, which the re-expansion would widen into slits D-28
    // cannot close. D-53: so is one closed but for loops up to twice as long whose fills lie over
    // input points. Pieces with a longer border (open scans) keep their loops: D-30 and D-28
    // decide about those on the fine mesh.
    const std::size_t pinhole = coarse_pinhole_edges(report.handle_hop_limits);
    report.coarse_small_holes_filled = fill_small_holes(
        coarse_mesh.triangles, coarse_mesh.positions, {}, pinhole,
        SmallHoleScope::PiecesClosedButForThem, exec, {2 * pinhole, &geometry, candidate_rank});
    return coarse_mesh;
}

// §6 on the algorithm's positions. `index`: a kd-tree on them, or null.
CollapsedCloud collapse_geometry(const std::vector<Vec3>& geometry,
                                 const std::vector<Vec3>& normals, CollapseOptions options,
                                 const Execution& exec, std::unique_ptr<KnnIndex> index) {
    // D-24, D-47: never below min(N, 500) points, so small clouds still leave RsR enough.
    const double floor =
        double(std::min(geometry.size(), constants::kMinCoarsePoints)) / double(geometry.size());
    options.collapse_ratio = std::max(options.collapse_ratio, floor);
    return collapse(geometry, normals, options, exec, std::move(index));
}

// §7: the collapsed points, smoothed (tangent mode) and split into components like RsR's input.
PreparedCloud hand_off(const PreparedCloud& cloud, const CollapsedCloud& collapsed,
                       const PreprocessOptions& options, const Execution& exec,
                       ReconstructionReport& report, std::vector<PointIndex>& dropped,
                       const std::vector<Vec3>& geometry) {
    PreparedCloud coarse;
    coarse.positions = collapsed.positions;
    coarse.normals = collapsed.normals;
    coarse.weights = collapsed.weights;
    coarse.node = collapsed.survivors;
    coarse.normalisation = cloud.normalisation;
    // D-44: smoothed over the share of the surface the input's smoothing would span, not over
    // n / 2000 coarse points (which grew × 3.8 from the 800k to the 3.2M dragon sample).
    PreprocessOptions coarse_options = options;
    coarse_options.k_smoothing =
        coarse_neighbour_count(cloud.size(), coarse.size(), options.k_smoothing);
    coarse.smoothed = smoothed_positions(coarse.positions, coarse.normals, coarse_options, exec,
                                         report.preprocess);
    // The kNN rows stay with the coarse cloud: RsR's candidate graph on it asks the same
    // queries of every piece (nearly all its rows lie in one piece).
    {
        const KnnIndex index(coarse.smoothed, exec);
        coarse.neighbours = knn_table(index, options.k, exec);
    }
    const CsrGraph graph = symmetric_union(coarse.neighbours, coarse.size(), exec);
    // D-35: the coarse cloud's pieces are the input's. At a coarse spacing wider than the gap
    // between two surfaces their kNN graph joins them (three interlocked rings 0.023 apart, at
    // p = 1/8 a coarse spacing of 0.06, came out as one piece of genus 2): an edge longer
    // than the kNN reach of the input points at both its ends is one that RsR's component graph
    // on the input could not have. D-31: a coarse handle edge must be one RsR could make on the
    // input points, within the reach at the candidates' rank.
    std::vector<std::vector<double>> reach =
        input_reach(geometry, coarse.node.values(),
                    {options.k, rsr::candidate_rank(options.k, cloud.size())}, exec);
    coarse.handle_reach = std::move(reach[1]);
    const ComponentSplit split = split_components(graph, coarse.positions, coarse.smoothed,
                                                  coarse.normals, options, exec, reach[0]);
    record_split(split, cloud.normalisation, report.preprocess);
    return keep_components(coarse, split, dropped);
}

// The coarse survivor at the root of each node's collapse tree.
IndexVector<PointIndex, PointIndex> tree_roots(std::size_t nodes,
                                               const std::vector<CollapseRecord>& records) {
    IndexVector<PointIndex, PointIndex> root;
    root.reserve(nodes);
    for (PointIndex node : KeyRange<PointIndex>(nodes)) root.push_back(node);
    for (std::size_t k = records.size(); k-- > 0;)
        root[PointIndex(records[k].latent)] = root[PointIndex(records[k].active)];
    return root;
}

// §8.7: each point that is not its own vertex is merged into another's (l_min, failed splits),
// dropped with a small coarse component, or left out of every triangle.
void record_fates(const PreparedCloud& cloud, const IndexVector<PointIndex, PointIndex>& alias,
                  const IndexVector<PointIndex, PointIndex>& root,
                  const std::vector<PointIndex>& dropped_nodes, ReconstructionReport& report) {
    IndexVector<PointIndex, std::uint8_t> dropped_root(cloud.size(), 0);
    for (PointIndex node : dropped_nodes) dropped_root[node] = 1;
    for (PointIndex node : cloud.input_index.keys()) {
        if (alias[node] == node) continue;
        if (alias[node] != ReexpandedMesh::kNoNode)
            ++report.merged_points;
        else if (dropped_root[root[node]])
            report.dropped_small_coarse_component.push_back(cloud.input_index[node].value());
        else
            report.not_in_triangle.push_back(cloud.input_index[node].value());
    }
    std::sort(report.not_in_triangle.begin(), report.not_in_triangle.end());
    std::sort(report.dropped_small_coarse_component.begin(),
              report.dropped_small_coarse_component.end());
}

// The re-expanded mesh's border: D-34's notches closed, then D-30's holes in the data opened,
// then D-28's small loops closed.
void finish_border(ReexpandedMesh& fine, const std::vector<Vec3>& geometry, int candidate_rank,
                   const Execution& exec, ReconstructionReport& report) {
    report.border_notches_closed =
        close_border_notches(fine.triangles, fine.border, geometry, fine.vertex_node,
                             constants::kBorderNotchDegrees * M_PI / 180.0);
    std::vector<BorderEdge>().swap(fine.border); // spent
    // D-30: holes in the data that RsR's ears closed on the coarse cloud (where the input's
    // holes are only a few coarse spacings across) open again.
    report.unsampled_triangles_removed = remove_unsampled_triangles(
        fine.triangles, geometry, fine.vertex_node, candidate_rank, exec);
    report.small_holes_filled = fill_small_holes(fine.triangles, geometry, fine.vertex_node,
                                                 kMaxFilledLoop, SmallHoleScope::Every, exec);
}

// A mesh of the cloud in spatial order and what measuring it needs.
struct Unmeasured {
    Reconstruction mesh;
    Normalisation normalisation;
};

// D-40: the input in spatial order (timed with pre-processing, whose timings open the run's).
struct InSpatialOrder {
    InSpatialOrder(const PointSet& input, const Execution& exec, ReconstructionReport& report) {
        begin_phase(exec, "spatial order");
        Timer timer(report.preprocess.timings, "spatial order");
        order = spatial_order(input.positions, exec);
        points = reordered(input, order, exec);
    }
    SpatialOrder order;
    PointSet points;
};

// The mesh in input indices and order, measured, its closed components turned outwards (D-6),
// every input point accounted for.
Reconstruction finished(const PointSet& input, const InSpatialOrder& ordered, bool outward,
                        const Execution& exec, Unmeasured out, ReconstructionReport& report) {
    // Measured in spatial order, where the vertices of a triangle lie close in memory; what it
    // counts and turns does not depend on the vertices' numbers.
    measure_output(ordered.points, out.normalisation, outward, exec, out.mesh, report);
    restore_input_order(ordered.order, out.mesh, report, exec);
    account(input, out.mesh, report);
    require_triangles(out.mesh, report);
    return std::move(out.mesh);
}

// RsR's mesh of `input` (in spatial order), before it is measured.
Unmeasured rsr_mesh_of(const PointSet& input, const RsrOptions& options, const Execution& exec,
                       ReconstructionReport& report, rsr::Observer* observer) {
    PreparedCloud cloud =
        preprocess(input, options.preprocess, exec, report.preprocess, InputOrder::Spatial);
    report.points_used = cloud.size();
    report.timings = report.preprocess.timings;
    rsr::CloudMesh rsr_mesh = rsr::reconstruct_cloud(cloud, options, exec, observer);
    take_rsr_stats(rsr_mesh, report);
    begin_phase(exec, "assembly");
    std::optional<Timer> assembly(std::in_place, report.timings, "assembly");
    // D-46: the faces by their smallest vertex (the points are in spatial order), so that the
    // whole-mesh passes below walk memory in that order.
    sort_by_smallest_vertex(rsr_mesh.triangles, without_progress(exec));
    report.small_holes_filled = fill_small_holes(rsr_mesh.triangles, cloud.positions, {},
                                                 kMaxFilledLoop, SmallHoleScope::Every, exec);
    CompactMesh<PointIndex> m =
        compact<PointIndex>(cloud.size(), std::move(rsr_mesh.triangles), exec);
    for (PointIndex p : m.unused) report.not_in_triangle.push_back(cloud.input_index[p].value());
    Reconstruction mesh = make_output(cloud, m.vertex_point, std::move(m.triangles));
    assembly.reset();
    const Normalisation normalisation = cloud.normalisation;
    const std::vector<InputIndex> turned = std::move(cloud.turned_normals); // cloud goes next
    repair_and_remove_folds(input, std::move(cloud), options, exec, mesh, report);
    clear_flat_output_faces(input, mesh, exec, report);
    write_turned_normals_as_given(turned, mesh);
    restore_input_normals(input, report.preprocess, mesh);
    return {std::move(mesh), normalisation};
}

// HRsR's mesh of `input` (in spatial order), before it is measured.
// Its normals are released once prepared: only the positions are read later (peak memory).
Unmeasured hrsr_mesh_of(PointSet& input, const ReconstructionOptions& options,
                        const Execution& exec, ReconstructionReport& report,
                        rsr::Observer* observer, ReexpansionObserver* reexpansion_observer) {
    const PreprocessOptions& pre = options.rsr.preprocess;
    std::unique_ptr<KnnIndex> index_of_positions;
    PreparedCloud cloud = prepare_points(input, pre, exec, report.preprocess, PrepareFor::Collapse,
                                         InputOrder::Spatial, {nullptr, &index_of_positions});
    std::vector<Vec3>().swap(input.normals);
    report.points_used = cloud.size();
    report.timings = report.preprocess.timings;
    // D-33: in a noisy cloud every decision of HRsR (collapse, re-expansion, D-30, D-31, D-28)
    // is taken on smoothed positions, as RsR's are (§4.4); the output keeps the input's.
    const std::vector<Vec3>& geometry =
        report.preprocess.denoised ? cloud.smoothed : cloud.positions;
    const std::vector<Vec3>& geometry_normals =
        cloud.smoothed_normals.empty() ? cloud.normals : cloud.smoothed_normals;
    // The pre-processing's kd-tree, when on the positions the collapse reads, serves its graph.
    if (&geometry != &cloud.positions) index_of_positions.reset();

    CollapsedCloud collapsed;
    {
        Timer timer(report.timings, "collapse");
        collapsed = collapse_geometry(geometry, geometry_normals, options.collapse, exec,
                                      std::move(index_of_positions));
    }
    report.coarse_points = collapsed.survivors.size();
    report.collapse_tile_times = collapsed.tile_times;
    std::vector<PointIndex> dropped_nodes;
    PreparedCloud coarse;
    {
        Timer timer(report.timings, "hand-off");
        coarse = hand_off(cloud, collapsed, pre, exec, report, dropped_nodes, geometry);
    }
    if (coarse.size() == 0)
        throw InvalidOption(OptionId::CollapseRatio,
                            "is too small for this cloud: no point is left after collapsing "
                            "(every collapsed component is smaller than " +
                                std::to_string(pre.min_component_size) + " points); raise it");
    rsr::CloudMesh rsr_mesh = rsr::reconstruct_cloud(coarse, options.rsr, exec, observer);
    take_rsr_stats(rsr_mesh, report);

    CoarseMesh coarse_mesh = coarse_mesh_of(coarse, std::move(rsr_mesh.triangles), geometry,
                                            rsr::candidate_rank(pre.k, cloud.size()), exec, report);
    coarse = PreparedCloud();
    report.l_min = options.l_min_percent > 0
                       ? options.l_min_percent / 100.0 * report.preprocess.bbox_diagonal
                       : options.reexpand.l_min;
    // Fates of the points that are not their own vertex (§8.7) need the collapse trees; the
    // records themselves go to the re-expansion, which frees them as soon as they are spent.
    IndexVector<PointIndex, PointIndex> root = tree_roots(cloud.size(), collapsed.records);
    ReexpandedMesh fine;
    {
        Timer timer(report.timings, "re-expansion");
        fine =
            replay_collapses({geometry, geometry_normals, coarse_mesh, std::move(collapsed.records),
                              options.reexpand, report.l_min * cloud.normalisation.scale},
                             exec, report.reexpansion, reexpansion_observer);
    }

    begin_phase(exec, "assembly");
    std::optional<Timer> assembly(std::in_place, report.timings, "assembly");
    collapsed = CollapsedCloud();
    record_fates(cloud, fine.alias, root, dropped_nodes, report);
    finish_border(fine, geometry, rsr::candidate_rank(pre.k, cloud.size()), exec, report);
    Reconstruction mesh = [&] {
        // The re-expanded mesh is manifold by construction; the fan split is a safety net.
        // Its vertices are compacted into the output's: both are VertexIndex, of two meshes.
        CompactMesh<VertexIndex> out =
            compact<VertexIndex>(fine.vertex_node.size(), std::move(fine.triangles), exec);
        IndexVector<VertexIndex, PointIndex> vertex_point;
        vertex_point.reserve(out.vertex_point.size());
        for (VertexIndex v : out.vertex_point) vertex_point.push_back(fine.vertex_node[v]);
        return make_output(cloud, vertex_point, std::move(out.triangles));
    }();
    // Released before the fold repair, whose search and removal are the run's peak of memory.
    fine = ReexpandedMesh();
    root = IndexVector<PointIndex, PointIndex>();
    assembly.reset();
    const Normalisation normalisation = cloud.normalisation;
    const std::vector<InputIndex> turned = std::move(cloud.turned_normals); // cloud goes next
    repair_and_remove_folds(input, std::move(cloud), options.rsr, exec, mesh, report);
    clear_flat_output_faces(input, mesh, exec, report);
    write_turned_normals_as_given(turned, mesh);
    return {std::move(mesh), normalisation};
}

} // namespace

Reconstruction reconstruct_rsr(const PointSet& input, const RsrOptions& options,
                               const Execution& exec, ReconstructionReport& report,
                               rsr::Observer* observer) {
    validate(options);
    const InSpatialOrder ordered(input, exec, report);
    Unmeasured out = rsr_mesh_of(ordered.points, options, exec, report, observer);
    return finished(input, ordered, options.orient_outward, exec, std::move(out), report);
}

Reconstruction reconstruct_hrsr(const PointSet& input, const ReconstructionOptions& options,
                                const Execution& exec, ReconstructionReport& report,
                                rsr::Observer* observer,
                                ReexpansionObserver* reexpansion_observer) {
    validate(options);
    InSpatialOrder ordered(input, exec, report);
    Unmeasured out =
        hrsr_mesh_of(ordered.points, options, exec, report, observer, reexpansion_observer);
    return finished(input, ordered, options.rsr.orient_outward, exec, std::move(out), report);
}

Reconstruction reconstruct(const PointSet& input, const ReconstructionOptions& options,
                           const Execution& exec, ReconstructionReport& report,
                           rsr::Observer* observer) {
    validate(options); // every option, also those the chosen method does not use
    if (options.method == Method::Rsr)
        return reconstruct_rsr(input, options.rsr, exec, report, observer);
    return reconstruct_hrsr(input, options, exec, report, observer);
}

Reconstruction reconstruct_rsr(const PointSet& input, const RsrOptions& options,
                               const Execution& exec, ReconstructionReport& report) {
    return reconstruct_rsr(input, options, exec, report, nullptr);
}

Reconstruction reconstruct_hrsr(const PointSet& input, const ReconstructionOptions& options,
                                const Execution& exec, ReconstructionReport& report) {
    return reconstruct_hrsr(input, options, exec, report, nullptr, nullptr);
}

Reconstruction reconstruct(const PointSet& input, const ReconstructionOptions& options,
                           const Execution& exec, ReconstructionReport& report) {
    return reconstruct(input, options, exec, report, nullptr);
}

} // namespace hrsr
