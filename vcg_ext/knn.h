// k-nearest-neighbour queries on one point set through vcglib's KdTree, with results ordered by
// (distance, index) so that every consumer is deterministic whatever the thread count.
#pragma once

#include "parallel.h"
#include "point_set.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace hrsr {

struct Neighbour {
    std::uint32_t index;
    double squared_distance;
};

/// A kd-tree over a fixed set of points. The tree copies the coordinates (rebuild it after
/// moving points), but distances are recomputed from `points`' storage, which must outlive the
/// index: the vector may be moved (a move keeps its storage), not resized or reassigned.
class KnnIndex {
public:
    explicit KnnIndex(const std::vector<Vec3>& points);
    /// The same tree, built with `exec`'s threads (knn_tree.h).
    KnnIndex(const std::vector<Vec3>& points, const Execution& exec);
    ~KnnIndex();
    KnnIndex(const KnnIndex&) = delete;
    KnnIndex& operator=(const KnnIndex&) = delete;

    std::size_t size() const { return size_; }

    /// The min(k, size − 1) nearest neighbours of data point `i`, never `i` itself, sorted by
    /// (squared distance, index). `out` is overwritten. Thread-safe.
    void neighbours_of(std::uint32_t i, int k, std::vector<Neighbour>& out) const;
    /// The min(k, size) nearest data points to an arbitrary position, sorted likewise.
    void nearest(const Vec3& p, int k, std::vector<Neighbour>& out) const;
    /// For each rank r: the squared distance from data point `i` to its r-th nearest other point
    /// (as neighbours_of(i, r) would give it), or infinity when there are fewer points or r < 1.
    /// Cheaper than neighbours_of: the neighbours are not sorted. Thread-safe.
    void squared_distances_at_ranks(std::uint32_t i, const std::vector<int>& ranks,
                                    std::vector<double>& out) const;
    /// Whether at least `count` data points q satisfy `accept(squared distance from p to q)`,
    /// the distance computed as the k-nearest queries compute theirs, so that a caller decides
    /// exactly as it would from their results. `accept` must hold only within `radius` of p
    /// (the search looks no further). Stops at the count-th: a few leaves visited however many
    /// points lie within `radius`. Thread-safe.
    bool at_least(const Vec3& p, double radius, std::size_t count,
                  const std::function<bool(double)>& accept) const;
    /// neighbours_of(i, k) when at least k others lie within `radius` of point i: every point
    /// within the radius gathered (no bounded queue to keep), the k nearest kept and sorted.
    /// False, and `out` unspecified, when fewer than k lie there or the next one is within a
    /// millionth of the k-th's distance: vcglib's query prunes its walk in single precision,
    /// so which of such near ties it keeps, only its walk decides. With `walk_order` the k are
    /// left in the order the walk met them, unsorted. Also false once more than `at_most`
    /// points are gathered (a radius far too wide: the walk stops there). Thread-safe.
    bool neighbours_within(std::uint32_t i, double radius, int k, std::vector<Neighbour>& out,
                           bool walk_order = false,
                           std::size_t at_most = std::numeric_limits<std::size_t>::max()) const;
    /// Every data point within `radius` of p, in no particular order. `out` is overwritten.
    void within(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const;

private:
    struct Tree;
    std::unique_ptr<Tree> tree_;
    const Vec3* points_; ///< the storage of the points the tree was built on
    std::size_t size_ = 0;
    double coordinate_scale_ = 0; ///< the largest |coordinate| of the points
};

/// What the k-nearest queries of a cloud's own points found, kept for the next round that asks
/// the same of the same points, or of them moved a little (the smoothing rounds and the PCA
/// between them, §4.4): per point a distance within which at least k others lie. A radius query
/// then finds the k nearest without vcglib's bounded queue: about three times cheaper at
/// k = 192 (docs/BENCHMARKS.md, session 35). The set is always the k-nearest query's (a tie at
/// the k-th distance goes to that query); its order is the walk's, for sums that must not
/// depend on which round found the points.
class NeighbourReach {
public:
    /// Before a round over `points` points asking k of each: the radii are kept when the last
    /// round asked the same (else forgotten).
    void begin_round(std::size_t points, int k);
    /// The round's k nearest others of point i of `index`'s points (KnnIndex::neighbours_of's
    /// set) in the order of the kd-tree's walk from the point: by the kept radius where there is
    /// one, else by the k-th distance of the last point this thread served in the round, widened
    /// (knn.cpp), else by the radius vcglib's query finds (neighbours_of's own order where the
    /// k-th is tied). The k-th distance is kept for the next round. Thread-safe for distinct i.
    void neighbours(const KnnIndex& index, std::uint32_t i, std::vector<Neighbour>& out);
    /// The points moved from `before`, point i by at most |shift[i]| (the next rounds read a
    /// kd-tree of the new positions): a radius grows by its own point's shift and the largest
    /// shift near it (triangle inequality: its k nearest stay within that), and is forgotten
    /// where that makes it more than kMaxGrowth times the k-th distance (a wide radius gathers
    /// more points than the k-nearest query visits).
    void moved(const std::vector<Vec3>& before, const std::vector<double>& shift,
               const Execution& exec);
    /// Points whose next query goes by radius.
    std::size_t radii_known() const {
        return std::size_t(
            std::count_if(radius_.begin(), radius_.end(), [](float r) { return r > 0; }));
    }

private:
    static constexpr double kMaxGrowth = 1.2;
    /// "Near": the cells of a grid of at most kMaxCellsPerAxis³ cells about a radius wide
    /// (16 MB of floats) that the ball of a radius overlaps.
    static constexpr double kMaxCellsPerAxis = 160;
    /// A ball spanning more cells than 1 + this a side keeps no radius (its query as it comes).
    static constexpr std::size_t kMaxCellsAcrossBall = 6;
    int k_ = 0;
    std::uint64_t pass_ = 0;    ///< this round's number among all rounds (knn.cpp's guesses)
    std::vector<float> radius_; ///< per point, rounded up; 0: unknown
};

/// An entry of a KnnTable whose point is no longer in the cloud (dropped after the query).
inline constexpr std::uint32_t kNoNeighbour = 0xffffffffU;

/// The k nearest neighbours of every point, fixed stride: row i is
/// index[i * k .. i * k + k), with k = min(requested, N − 1), sorted by (distance, index).
struct KnnTable {
    int k = 0;
    std::vector<std::uint32_t> index;

    std::size_t size() const { return k == 0 ? 0 : index.size() / std::size_t(k); }
    const std::uint32_t* row(std::size_t i) const { return index.data() + i * std::size_t(k); }
};

/// Reserves twice `entries` in a relation's buffer, so that symmetric_union() can build the union
/// inside it: address space, resident only where the union writes. Where address space is
/// charged in full (strict overcommit, ulimit -v) it reserves just `entries`, and the union then
/// builds its result in a second array.
void reserve_room_for_union(std::vector<std::uint32_t>& buffer, std::size_t entries);

/// Computes the table in parallel (per-point queries, results written by index), with room
/// for symmetric_union() to work in place (reserve_room_for_union).
KnnTable knn_table(const KnnIndex& index, int k, const Execution& exec);

} // namespace hrsr
