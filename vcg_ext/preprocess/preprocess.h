// Pre-processing pipeline (ALGORITHM.md §4): validate and clean, normals, smoothing,
// orientation, component split.
#pragma once

#include "graph/neighbour_graph.h"
#include "index_types.h"
#include "knn.h"
#include "options.h"
#include "parallel.h"
#include "point_set.h"
#include "preprocess/components.h"
#include "preprocess/report.h"
#include "preprocess/sanitize.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace hrsr {

/// A cleaned cloud with oriented unit normals, its points in the order given (reconstruct()
/// gives them in spatial order, D-40: `input_index` then maps into its reordered copy).
struct PreparedCloud {
    /// Point -> index in the input point set; empty on HRsR's coarse cloud, which has `node`.
    IndexVector<PointIndex, InputIndex> input_index;
    /// HRsR's coarse cloud: coarse point -> the collapse node (pre-processed point) it is.
    IndexVector<CoarseIndex, PointIndex> node;
    std::vector<Vec3> positions; ///< normalised input positions (D-2)
    std::vector<Vec3> smoothed;  ///< normalised smoothed positions (= positions in Euclidean
                                 ///< mode); empty when prepared for the collapse
    std::vector<Vec3> normals;   ///< unit; consistently oriented per connected piece
    /// D-54: the input points whose normal `normals` holds turned (increasing); outputs write
    /// them as given.
    std::vector<InputIndex> turned_normals;
    /// D-33, HRsR on a noisy cloud with input normals: the normals its collapse and re-expansion
    /// use with `smoothed` (averaged_normals()); empty = `normals`. Outputs keep `normals`.
    std::vector<Vec3> smoothed_normals;
    /// Input points each point stands for (HRsR's coarse cloud: its collapse weight); empty =
    /// one each. RsR measures handle loops in spacings of the input through it (D-27).
    std::vector<std::uint32_t> weights;
    /// HRsR's coarse cloud: the longest handle edge at each point, the candidate reach of RsR on
    /// the input points there (D-31); empty = only the candidate graph limits handles.
    std::vector<double> handle_reach;
    /// HRsR's coarse cloud: each point's nearest others on `smoothed`, as knn_table() gives them
    /// for the options' k, in this cloud's indices (kNoNeighbour: dropped with a small
    /// component). RsR's candidate graph takes the rows that lie in one component instead of
    /// querying them again; empty = RsR queries every row.
    KnnTable neighbours;
    Normalisation normalisation;
    /// Set by preprocess(): component of each point (0 … component_count − 1, §4.6).
    std::vector<std::uint32_t> component;
    std::size_t component_count = 0;

    std::size_t size() const { return positions.size(); }
};

/// What the prepared cloud is for.
enum class PrepareFor {
    Rsr,     ///< RsR runs on it: smoothed positions are needed (tangent mode)
    Collapse ///< HRsR collapses it first (§2.2): smoothing only as part of normal estimation
};

/// What prepare_points hands back beside the cloud, where asked.
struct PreparedExtras {
    /// The symmetric kNN_k graph on the smoothed positions (built anyway when orienting).
    CsrGraph* graph = nullptr;
    /// The kd-tree built on the returned cloud's positions when one outlives the preparation
    /// (HRsR with input normals), else null: the caller's next queries of those positions need
    /// not build it again (keep the positions' storage in place while it lives).
    std::unique_ptr<KnnIndex>* index_of_positions = nullptr;
};

/// §4.1–4.5: sanitising, normals (input or PCA), smoothing (tangent mode), orientation (when
/// normals were estimated). Fills `report` and `extras`; throws InvalidOption, InvalidInput
/// (nothing usable left) or Cancelled.
PreparedCloud prepare_points(const PointSet& input, const PreprocessOptions& options,
                             const Execution& exec, PreprocessReport& report,
                             PrepareFor purpose = PrepareFor::Rsr,
                             InputOrder order = InputOrder::Any, PreparedExtras extras = {});

/// Tangent mode: two smoothing rounds with the normals fixed (§4.4, §7); Euclidean mode: a copy.
/// `index_of_positions`, if given, is a kd-tree on `positions` the first round uses, and
/// `reach_of_positions` what earlier rounds on them found (knn.h).
std::vector<Vec3> smoothed_positions(const std::vector<Vec3>& positions,
                                     const std::vector<Vec3>& normals,
                                     const PreprocessOptions& options, const Execution& exec,
                                     PreprocessReport& report,
                                     const KnnIndex* index_of_positions = nullptr,
                                     NeighbourReach* reach_of_positions = nullptr);

/// The symmetric union of the k-nearest-neighbour relation on `positions` (D-7).
CsrGraph neighbour_graph(const std::vector<Vec3>& positions, int k, const Execution& exec);

/// The whole stage: prepare_points, then the component split with the r cut (§4.6). Returns
/// only the points of kept components; every other input point has its fate in the report.
PreparedCloud preprocess(const PointSet& input, const PreprocessOptions& options,
                         const Execution& exec, PreprocessReport& report,
                         InputOrder order = InputOrder::Any);

/// The points of `cloud` in kept components, labelled with their component, in the same order;
/// `dropped` receives the input_index of every other point.
PreparedCloud keep_components(const PreparedCloud& cloud, const ComponentSplit& split,
                              std::vector<InputIndex>& dropped);
/// The same for HRsR's coarse cloud: `dropped` receives the node of every other point.
PreparedCloud keep_components(const PreparedCloud& cloud, const ComponentSplit& split,
                              std::vector<PointIndex>& dropped);

/// Copies the split's numbers into the report (the cut length in input units).
void record_split(const ComponentSplit& split, const Normalisation& normalisation,
                  PreprocessReport& report);

} // namespace hrsr
