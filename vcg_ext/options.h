// Every option of the method with its default, in one place (ALGORITHM.md §9). The CLI, the
// MeshLab filter and the docs read defaults from here.
#pragma once

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
    /// Components smaller than min(N, min_component_size) points are dropped (§4.6).
    int min_component_size = 100;
};

/// Throws hrsr::InvalidOption naming the first option that is out of range.
void validate(const PreprocessOptions& options);

/// Constants of the method that are not options (§9.4); named so the code says what they are.
namespace constants {
/// Smoothing: neighbours (true, not counting the point) and their normal filter (§4.4).
inline constexpr int kSmoothingNeighbours = 192;
inline constexpr double kSmoothingNormalAngleDegrees = 30.0;
/// Normal filter angle used in Euclidean mode (§3.3).
inline constexpr double kEuclideanNormalAngleDegrees = 90.0;
/// Automatic PCA neighbourhood: clamp(N / kPcaPointsPerNeighbour, kPcaMin, kPcaMax) (D-5).
inline constexpr int kPcaPointsPerNeighbour = 2000;
inline constexpr int kPcaMinNeighbours = 16;
inline constexpr int kPcaMaxNeighbours = 192;
/// A covariance whose middle eigenvalue is below this fraction of the largest is (nearly)
/// collinear or a single point: its PCA normal is undefined (D-5 degenerate case).
inline constexpr double kPcaDegenerateRatio = 1e-10;
/// Input normals shorter than this are unusable (zero) normals (§4.1).
inline constexpr double kMinNormalLength = 1e-12;
} // namespace constants

} // namespace hrsr
