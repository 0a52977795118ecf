// Every option of the method with its default, in one place (ALGORITHM.md §9). The CLI, the
// MeshLab filter and the docs read defaults from here.
#pragma once

#include <cstddef>

namespace hrsr {

/// How edge lengths are measured (ALGORITHM.md §3.2).
enum class DistanceMode {
    Tangent,   ///< mean length of the edge projected on both tangent planes; positions smoothed
               ///< (§4.4)
    Euclidean, ///< plain |q − p|; no smoothing; normal filter at 90° (§3.3)
};

/// Where normals come from.
enum class NormalSource {
    Input,      ///< use the input's normals; estimate only when they are missing or unusable
    Reestimate, ///< always estimate (PCA + MST orientation), ignoring the input's normals
};

/// Pre-processing: cleaning, normals, smoothing, orientation, component split (§4).
struct PreprocessOptions {
    /// Neighbourhood size k (true neighbours, not counting the point): orientation graph and
    /// component split (§4.5, §4.6); RsR's candidate graph uses the same k.
    int k = 70;
    /// Component split: an edge longer than r × the mean neighbour distance is cut (§4.6).
    double r = 20.0;
    /// Normal filter θ in degrees: neighbours whose normals differ by more are not linked
    /// (tangent mode; Euclidean mode uses 90°, §3.3).
    double theta_degrees = 60.0;
    DistanceMode distance = DistanceMode::Tangent;
    NormalSource normals = NormalSource::Input;
    /// PCA neighbours (not counting the point); 0 = automatic, clamp(N / 2000, 16, 192) (D-5).
    int k_normals = 0;
    /// Smoothing neighbours (not counting the point); 0 = automatic, clamp(N / 2000, 16, 192)
    /// (D-20: GEL always uses 192, which on clouds of a few thousand points spans a large part
    /// of the object and folds curved regions). HRsR's coarse cloud of n points, automatically,
    /// spans the share of the surface the input's neighbourhood would: min(N / 2000, 192) · n / N
    /// points, same clamps (D-44).
    int k_smoothing = 0;
    /// Components smaller than min(N, min_component_size) points are dropped (§4.6).
    int min_component_size = 100;
};

/// Throws hrsr::InvalidOption naming the first option that is out of range.
void validate(const PreprocessOptions& options);

/// Rotation System Reconstruction (§5, §9.1). Neighbourhood size k, θ, r and the distance mode
/// are those of `preprocess`.
struct RsrOptions {
    PreprocessOptions preprocess;
    /// n: the shortest loop around a handle that is kept, in point spacings of the input (D-27).
    /// A handle edge only joins points more than n graph hops apart on the full cloud, n·sqrt(p)
    /// on HRsR's coarse cloud (p = its share of the points); §5.6 counted raw hops of whatever
    /// cloud RsR saw. Shorter loops are taken for slits and noise, not handles; HRsR closes them
    /// on coarse pieces that are closed but for them (D-39).
    double min_handle_loop = 20;
    /// Handle groups: −1 = as many as found, 0 = none (genus 0), g = at most g (§5.9).
    int handles = -1;
    /// Flip closed output components whose signed volume is negative, so normals and face
    /// winding point outwards (D-6).
    bool orient_outward = true;
    /// D-26: rounds of edge flips that undo folds (intersecting triangles) in the output, of RsR
    /// and of HRsR alike; 0 skips the search for them (about one `hrsr check` intersection test).
    int fold_repair_rounds = 8;
};

void validate(const RsrOptions& options);

/// HRsR collapse phase (§6, §9.2).
struct CollapseOptions {
    /// p: fraction of the points left after collapsing, in (0, 1]; 1 = no collapse (plain RsR).
    /// The default is the paper's fastest setting (12.5 %).
    double collapse_ratio = 0.125;
    /// Neighbours (true, not counting the point) of the collapse graph (D-14; GEL used 4).
    int collapse_k = 6;
};

void validate(const CollapseOptions& options);

/// What happens to collapses shorter than l_min during re-expansion (§8.1).
enum class LMinMode {
    Stop,   ///< stop re-expanding at the first record shorter than l_min (the paper)
    Filter, ///< skip every record shorter than l_min, keep replaying the rest
};

/// HRsR re-expansion phase (§8, §9.3).
struct ReexpandOptions {
    /// l_min in the units of the input; 0 = replay every collapse (full detail).
    double l_min = 0;
    LMinMode l_min_mode = LMinMode::Stop;
    /// Flip passes around each new vertex (§8.6; GEL's demo uses 0).
    int refinement_iterations = 1;
};

void validate(const ReexpandOptions& options);

enum class Method {
    Hrsr, ///< collapse → RsR → re-expansion (the default: RsR's quality, a fraction of its cost)
    Rsr,  ///< RsR on the full cloud
};

/// Everything `reconstruct` needs.
struct ReconstructionOptions {
    Method method = Method::Hrsr;
    RsrOptions rsr;
    CollapseOptions collapse;
    ReexpandOptions reexpand;
    /// l_min as a percentage of the bounding-box diagonal; used instead of reexpand.l_min when > 0.
    double l_min_percent = 0;
};

void validate(const ReconstructionOptions& options);

/// Constants of the method that are not options (§9.4); named so the code says what they are.
namespace constants {
/// Smoothing: normal filter of the neighbours (§4.4).
inline constexpr double kSmoothingNormalAngleDegrees = 30.0;
/// D-33: above this noise (relative_noise(): median distance from a fitted quadric over the
/// median sixth-neighbour distance) HRsR collapses and re-expands on smoothed positions. Measured:
/// clean samples, the owl and the lion 0–0.07, the merged bunny scans 0.1, the Kinect frame 0.12,
/// the LMS400 table 0.17, 100k spheres with noise of 0.1 / 0.3 / 0.5 % of the diagonal 0.13 /
/// 0.33 / 0.46; lower, the smoothing's shift of clean points costs more folds than it saves
/// (docs/BENCHMARKS.md, "Noise beyond the spacing").
inline constexpr double kNoisyCloud = 0.15;
/// Normal filter angle used in Euclidean mode (§3.3).
inline constexpr double kEuclideanNormalAngleDegrees = 90.0;
/// Automatic PCA and smoothing neighbourhoods: clamp(N / kPointsPerNeighbour, kMinNeighbours,
/// kMaxNeighbours) (D-5, D-20).
inline constexpr int kPointsPerNeighbour = 2000;
inline constexpr int kMinNeighbours = 16;
inline constexpr int kMaxNeighbours = 192;
/// D-29: on clouds of fewer than 16 · 40 = 640 points the automatic neighbourhood is at most
/// N / 40 (a patch of 2.5 % of the surface), never below 8.
inline constexpr int kSmallCloudPointsPerNeighbour = 40;
inline constexpr int kMinSmallCloudNeighbours = 8;
/// A covariance whose middle eigenvalue is below this fraction of the largest is (nearly)
/// collinear or a single point: its PCA normal is undefined (D-5 degenerate case).
inline constexpr double kPcaDegenerateRatio = 1e-10;
/// Points closer than this (normalised units: a fraction of the bounding-box diagonal) to an
/// earlier point are merged into it like exact duplicates (D-25). Ten times the rotation-angle
/// cut-off of D-1 (1e-12): closer pairs have no usable direction. Kept that small because a far
/// outlier inflates the diagonal (x 1e6 in tests/cli: still 5e-5 absolute on a unit sphere).
inline constexpr double kNearDuplicateDistance = 1e-11;
/// Warn when more than this fraction of the input normals oppose their nearest neighbour's.
inline constexpr double kOpposedNormalsWarningFraction = 0.1;
/// Input normals shorter than this are unusable (zero) normals (§4.1).
inline constexpr double kMinNormalLength = 1e-12;
/// RsR candidate graph: a candidate edge is at most as long as the ⌊2k/3⌋-th neighbour (§5.1).
inline constexpr int kPreMaxRankNumerator = 2, kPreMaxRankDenominator = 3;
/// Leaf-normal fix: an MST edge within this angle of the normal is "along the normal" (§5.2).
inline constexpr double kLeafFixAngleDegrees = 10.0;
/// Geometry check: ball radius factor and normal agreement with the half-sum normal (§5.5.2).
inline constexpr double kGeometryBallFactor = 1.5;
inline constexpr double kGeometryNormalDot = 0.5;
/// Face-split triangles with a larger interior angle are rejected (§5.5.2).
inline constexpr double kMaxTriangleAngleDegrees = 175.0;
/// Handle groups with this many candidates or fewer are ignored (§5.6).
inline constexpr std::size_t kMinHandleGroupSize = 5;
/// D-27: the hop limit of a handle never falls below this on a coarse cloud: the two sides of a
/// slit one or two triangles long are that close.
inline constexpr std::size_t kMinHandleHops = 4;
/// D-29: the loop a handle needs is at most this times sqrt(points the component stands for),
/// in input spacings: only components of fewer than (2n)² = 1,600 points at n = 20 are affected.
/// A torus tube of radius r around a circle of radius R is sqrt(r/R)·sqrt(N) spacings around.
inline constexpr double kSmallSurfaceLoopFraction = 0.5;
/// Re-expansion flips (§8.6): a flip is considered when an angle at the edge's endpoints is
/// below this.
inline constexpr double kRefinementAngleDegrees = 22.5;
/// Split energy E = E_D + w · E_A (§8.4): the weight w of the min-angle term, and the smallest
/// angle below which a triangle costs the flat penalty instead.
inline constexpr double kMinAngleWeight = 1.0;
inline constexpr double kMinAngleThresholdDegrees = 3.0;
inline constexpr double kMinAnglePenalty = 0.1;
/// Re-expansion (§8.3, §8.4): crossing search extension, round cap, dihedral guard on 1 − cos.
inline constexpr double kCrossingExtension = 1.11;
inline constexpr int kCrossingRounds = 100;
inline constexpr double kDihedralGuard = 1.75;
/// D-30, D-31: an edge of HRsR's mesh is overlong when it is longer than this many times RsR's
/// candidate reach (the ⌊2k/3⌋-th neighbour distance, §5.1) among the input points at either
/// end. Twice, because the re-expansion makes longer, thinner triangles than RsR where the
/// sampling is anisotropic (the rocker arm's flat faces reach 1.5 times the bound and were opened
/// at 1.5), while the ears over real holes are longer still (the shark's: up to 3.4 times).
inline constexpr double kOverlongFactor = 2.0;
/// HRsR never collapses below min(N, this) points (D-24, D-47): RsR needs points to triangulate
/// (12.5 % of a tiny cloud is a single point), and on 200–350 coarse points it opened holes the
/// data does not have (the half tunnel) and lost a handle (the sparse 5k triple torus).
inline constexpr std::size_t kMinCoarsePoints = 500;
/// D-42: the collapse works in tiles of about this many consecutive points of the spatial order
/// (D-40), in parallel; a cloud of at most this many points is one tile.
inline constexpr std::size_t kCollapseTilePoints = 65536;
/// D-34: a triangle on the coarse mesh's border whose angle opposite its border edge is at least
/// this is a sliver over nearly collinear border points, peeled before the re-expansion.
inline constexpr double kBorderSliverDegrees = 120.0;
/// D-34: a border vertex whose faces leave less than this of its surroundings open lies in a
/// notch of the border, closed by an ear after the re-expansion.
inline constexpr double kBorderNotchDegrees = 90.0;
/// D-34: ears never take a border loop below this many vertices, so a hole in the data never
/// shrinks to what D-28 closes (the shark lost one of its four holes).
inline constexpr std::size_t kMinNotchedLoop = 10;
} // namespace constants

} // namespace hrsr
