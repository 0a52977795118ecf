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
    /// of the object and folds curved regions).
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
    /// n: a handle edge only joins points more than n graph hops apart (§5.6).
    int max_handle_hops = 50;
    /// Handle groups: −1 = as many as found, 0 = none (genus 0), g = at most g (§5.9).
    int handles = -1;
    /// Flip closed output components whose signed volume is negative, so normals and face
    /// winding point outwards (D-6).
    bool orient_outward = true;
};

void validate(const RsrOptions& options);

/// Constants of the method that are not options (§9.4); named so the code says what they are.
namespace constants {
/// Smoothing: normal filter of the neighbours (§4.4).
inline constexpr double kSmoothingNormalAngleDegrees = 30.0;
/// Normal filter angle used in Euclidean mode (§3.3).
inline constexpr double kEuclideanNormalAngleDegrees = 90.0;
/// Automatic PCA and smoothing neighbourhoods: clamp(N / kPointsPerNeighbour, kMinNeighbours,
/// kMaxNeighbours) (D-5, D-20).
inline constexpr int kPointsPerNeighbour = 2000;
inline constexpr int kMinNeighbours = 16;
inline constexpr int kMaxNeighbours = 192;
/// A covariance whose middle eigenvalue is below this fraction of the largest is (nearly)
/// collinear or a single point: its PCA normal is undefined (D-5 degenerate case).
inline constexpr double kPcaDegenerateRatio = 1e-10;
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
} // namespace constants

} // namespace hrsr
