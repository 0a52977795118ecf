#include "hrsr/reexpansion.h"

#include "hrsr/crossings.h"
#include "hrsr/local_flips.h"
#include "hrsr/split_choice.h"
#include "mesh/small_holes_fill.h"
#include "mesh/split_mesh.h"

#include <algorithm>
#include <cmath>

namespace hrsr {

using namespace reexpand;

namespace {

// Per node, the mesh vertices standing for it (D-16). Almost always one, so one word per node:
// the vertex itself, or (rarely: fan-split copies of a coarse vertex) a tagged index into lists
// kept aside. An aliased node shares its target's word.
class NodeVertices {
public:
    struct Span {
        const std::uint32_t* first;
        std::size_t size;
        const std::uint32_t* begin() const { return first; }
        const std::uint32_t* end() const { return first + size; }
    };

    NodeVertices(std::size_t nodes, const IndexVector<VertexIndex, PointIndex>& coarse_vertex_node)
        : word_(nodes, kNone) {
        for (std::uint32_t v = 0; v < coarse_vertex_node.size(); ++v) {
            std::uint32_t& w = word_[coarse_vertex_node[VertexIndex(v)].value()];
            if (w == kNone) {
                w = v;
                continue;
            }
            if (!(w & kListBit)) {
                lists_.push_back({w});
                w = kListBit | std::uint32_t(lists_.size() - 1);
            }
            lists_[w & ~kListBit].push_back(v);
        }
    }

    Span of(std::uint32_t node) const {
        const std::uint32_t& w = word_[node];
        if (w == kNone) return {nullptr, 0};
        if (!(w & kListBit)) return {&w, 1};
        const std::vector<std::uint32_t>& list = lists_[w & ~kListBit];
        return {list.data(), list.size()};
    }
    void set(std::uint32_t node, std::uint32_t vertex) { word_[node] = vertex; }
    void share(std::uint32_t from, std::uint32_t to) { word_[to] = word_[from]; }

private:
    static constexpr std::uint32_t kNone = ~0u, kListBit = 1u << 31;
    std::vector<std::uint32_t> word_;
    std::vector<std::vector<std::uint32_t>> lists_;
};

// D-34: RsR on the coarse cloud closes a straight border with long edges over slivers whose apex
// lies just inside (a vertex split never lengthens the border, so the input's border points
// between their ends would stay interior, and fold). Peel them first: a triangle on a border
// loop longer than D-28 closes whose angle opposite the border edge is kBorderSliverDegrees or
// more goes, if its apex is interior (so every vertex stays manifold and keeps a face); repeated,
// since the apex's new border edges may be slivers too. Returns the triangles peeled.
std::size_t peel_border_slivers(SplitMesh& mesh) {
    const double max_cos = std::cos(constants::kBorderSliverDegrees * M_PI / 180.0);
    std::size_t peeled = 0;
    for (bool changed = true; changed;) {
        changed = false;
        for (SFace* f : mesh.live_faces())
            for (int z = 0; z < 3; ++z) {
                if (f->FFp(z) != f) continue; // not a border edge
                const std::uint32_t u = mesh.vertex_of(f, z), w = mesh.vertex_of(f, (z + 1) % 3),
                                    x = mesh.vertex_of(f, (z + 2) % 3);
                const Vec3 eu = mesh.position(u) - mesh.position(x),
                           ew = mesh.position(w) - mesh.position(x);
                const double lengths = eu.Norm() * ew.Norm();
                if (lengths <= 0 || eu.dot(ew) > max_cos * lengths || mesh.star(x).boundary ||
                    mesh.border_loop_edges(u, kMaxFilledLoop) <= kMaxFilledLoop)
                    continue;
                mesh.remove_face(f);
                ++peeled;
                changed = true;
                break;
            }
    }
    return peeled;
}

class Replayer {
public:
    Replayer(const ReexpansionInput& input, ReexpansionObserver* observer)
        : points_(input.points), normals_(input.normals), options_(input.options),
          observer_(observer), mesh_(input.coarse.positions, input.coarse.triangles,
                                     input.coarse.positions.size() + input.records.size(),
                                     input.coarse.triangles.size() + 2 * input.records.size()),
          vertices_of_(input.points.size(), input.coarse.vertex_node),
          vertex_node_(input.coarse.vertex_node) {
        vertex_node_.reserve(input.coarse.vertex_node.size() + input.records.size());
        alias_ = IndexVector<PointIndex, PointIndex>(input.points.size(), ReexpandedMesh::kNoNode);
        for (PointIndex node : input.coarse.vertex_node) alias_[node] = node;
    }

    std::size_t peel_border_slivers() { return hrsr::peel_border_slivers(mesh_); }

    // Aliasing (D-16): b is represented by a's vertices from now on.
    void alias(const CollapseRecord& r) {
        vertices_of_.share(r.active, r.latent);
        alias_[PointIndex(r.latent)] = alias_[PointIndex(r.active)];
    }

    void replay(const CollapseRecord& r, ReexpansionStats& stats) {
        // Stays valid while r.latent's entry changes: that is another word or list.
        const NodeVertices::Span candidates = vertices_of_.of(r.active);
        if (candidates.size == 0) { // the node never reached the mesh: its subtree is dropped
            ++stats.skipped_no_vertex;
            return;
        }
        bool unresolved = false;
        const std::size_t removed_before = stats.triangles_removed;
        for (std::uint32_t c : candidates) {
            if (mesh_.isolated(c)) continue;
            const CrossingStats cs =
                resolve_crossings(mesh_, c, r.active_before, r.latent_before, normals_[r.active]);
            stats.crossing_flips += cs.flips;
            stats.triangles_removed += cs.triangles_removed;
            unresolved = unresolved || cs.unresolved > 0 || cs.round_limit;
            mesh_.move(c, r.active_before);
        }
        for (std::uint32_t c : candidates) { // the first copy (in id order) with a valid pair
            if (mesh_.isolated(c)) continue;
            Star& star = star_; // reused: no allocation per split
            mesh_.star(c, star);
            const SplitChoice choice =
                choose_split(mesh_, c, star, r.active_before, r.latent_before);
            if (!choice.found) continue;
            const std::uint32_t c2 =
                mesh_.split(c, star, choice.a, choice.b, r.latent_before, choice.omit);
            vertex_node_.push_back(PointIndex(r.latent));
            vertices_of_.set(r.latent, c2);
            alias_[PointIndex(r.latent)] = PointIndex(r.latent);
            ++stats.replayed;
            stats.border_splits += choice.omit != SplitMesh::BorderSplit::None;
            if (unresolved) ++stats.unresolved_crossings;
            stats.improvement_flips += improve_around(mesh_, c2, options_);
            if (observer_)
                observer_->split_done(mesh_, c, c2, r.active_before, r.latent_before,
                                      stats.triangles_removed - removed_before, unresolved);
            return;
        }
        ++stats.failed_no_pair;
        alias(r);
    }

    // Every vertex at its own node's input point (the last move of a node restores it anyway
    // when every record was replayed; after a stop this is the snap-to-input of §8.1).
    void snap_to_input() {
        for (VertexIndex v : vertex_node_.keys())
            mesh_.move(v.value(), points_[vertex_node_[v].value()]);
    }

    ReexpandedMesh take_result() {
        return {std::move(vertex_node_), mesh_.triangles(), mesh_.border_edges(),
                std::move(alias_)};
    }

private:
    const std::vector<Vec3>& points_;
    const std::vector<Vec3>& normals_;
    const ReexpandOptions& options_;
    ReexpansionObserver* observer_;
    SplitMesh mesh_;
    NodeVertices vertices_of_;
    IndexVector<VertexIndex, PointIndex> vertex_node_;
    IndexVector<PointIndex, PointIndex> alias_;
    Star star_;
};

} // namespace

ReexpandedMesh replay_collapses(ReexpansionInput input, const Execution& exec,
                                ReexpansionStats& stats, ReexpansionObserver* observer) {
    const ReexpandOptions& options = input.options;
    const double l_min = input.l_min;
    std::vector<CollapseRecord>& records = input.records;
    validate(options);
    stats.records = records.size();
    Replayer replayer(input, observer);
    stats.border_slivers_peeled = replayer.peel_border_slivers();
    if (exec.progress) exec.progress->begin("re-expansion");
    for (std::size_t k = records.size(); k-- > 0;) {
        const CollapseRecord& r = records[k];
        if (exec.progress && (k & 0x3ff) == 0) // often enough to cancel promptly
            exec.progress->update(double(records.size() - k) / double(records.size()));
        if (l_min > 0 && (r.active_before - r.latent_before).Norm() < l_min) {
            if (options.l_min_mode == LMinMode::Stop) {
                stats.stopped_at_l_min = true;
                // Everything not yet replayed stays merged into its surviving node.
                for (std::size_t rest = k + 1; rest-- > 0;) {
                    replayer.alias(records[rest]);
                    ++stats.merged_by_l_min;
                }
                break;
            }
            replayer.alias(r);
            ++stats.merged_by_l_min;
            continue;
        }
        replayer.replay(r, stats);
    }
    replayer.snap_to_input();
    std::vector<CollapseRecord>().swap(records); // spent: free them before the export
    return replayer.take_result();
}

} // namespace hrsr
