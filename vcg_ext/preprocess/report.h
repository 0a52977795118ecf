// What pre-processing did to the input: every dropped or merged point with its reason, every
// change to normals or positions, warnings and timings.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hrsr {

/// What became of one input point.
enum class PointFate : std::uint8_t {
    Kept,           ///< in the output
    NonFinite,      ///< a coordinate was NaN or infinite (§4.1)
    Duplicate,      ///< equal (or near, D-25) to a point before it, merged into it (D-3)
    NoNormal,       ///< no normal could be estimated for it (D-5: degenerate, nothing to copy)
    SmallComponent, ///< in a component smaller than the minimum size after the r cut (§4.6)
};
const char* to_string(PointFate fate);

enum class NormalOrigin {
    Input,     ///< the input's normals, normalised
    Estimated, ///< PCA (D-5) + MST orientation (§4.5)
};

struct PreprocessReport {
    std::size_t input_points = 0;
    std::vector<PointFate> fate;             ///< per input point
    std::vector<std::uint32_t> duplicate_of; ///< per input point: the kept point it was merged into
                                             ///< (itself if not a duplicate)

    NormalOrigin normal_origin = NormalOrigin::Input;
    std::string
        normals_fallback_reason; ///< why input normals were not used (empty: none given, or used)
    std::size_t normals_renormalised = 0; ///< input normals that were not of unit length
    int pca_neighbours = 0; ///< PCA neighbourhood used (true neighbours), 0 if no PCA ran
    std::size_t pca_degenerate =
        0; ///< points whose PCA normal was undefined and copied from the nearest valid one
    std::size_t opposed_input_normals =
        0; ///< input normals opposed to their nearest neighbour's (a warning above 10 %)
    /// That warning was given: each front end adds how to re-estimate normals in its own terms.
    bool input_normals_look_inconsistent = false;
    /// D-54: input normals facing against most of their neighbours', turned for the algorithm
    /// (the output keeps them as given).
    std::size_t turned_input_normals = 0;
    std::size_t orientation_flips = 0; ///< estimated normals flipped by the MST propagation
    std::size_t orientation_components =
        0; ///< connected pieces oriented independently (one sign each)

    int smoothing_rounds = 0;
    int smoothing_neighbours = 0; ///< neighbourhood used (true neighbours), 0 if no smoothing ran
    double smoothing_mean_shift =
        0; ///< mean |displacement| along the normal, fraction of the bbox diagonal
    double smoothing_max_shift = 0; ///< largest one
    /// Tangent mode: the cloud's noise in point spacings (D-33, relative_noise()), and whether
    /// it is over kNoisyCloud: HRsR's collapse and re-expansion then work on smoothed positions,
    /// and with input normals both methods smooth along their neighbourhood mean. Measured for
    /// HRsR always, for RsR only with input normals.
    double relative_noise = 0;
    bool denoised = false;

    double bbox_diagonal = 0;  ///< of the finite input points, in input units
    double cut_length = 0;     ///< R of §4.6, in input units
    std::size_t edges_cut = 0; ///< neighbour edges longer than R
    /// HRsR: coarse neighbour edges longer than the input's kNN reach at both ends, which kept
    /// two coarse pieces apart (D-35)
    std::size_t edges_beyond_input_reach = 0;
    std::size_t components_kept = 0;
    std::size_t components_dropped = 0;
    std::vector<std::size_t> component_sizes; ///< of the kept components, in label order

    std::vector<std::string> warnings;
    std::vector<std::pair<std::string, double>> timings; ///< (phase, seconds)

    std::size_t count(PointFate f) const;
};

} // namespace hrsr
