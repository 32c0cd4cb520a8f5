// Evaluation of a reconstruction against a ground-truth mesh (all in world metres):
//   accuracy      distance from each reconstructed point to the mesh (mean, median, p90)
//   precision     fraction of reconstructed points within tau of the mesh
//   completeness  fraction of the reference surface points (the simulator's visible points,
//                 or the mesh sampled every 1 cm) within tau of the reconstruction; also
//                 split by the orientation of the mesh under each reference point: faces
//                 whose normal lies within 30 degrees of vertical (tops, decks, the seabed)
//                 and the rest
//   F-score       harmonic mean of precision and completeness at tau
//   Chamfer       mean accuracy + mean distance from reference points to the reconstruction
//                 (each counted at most 1 m)
// Per-point errors are kept for colouring. Distances use VTK's static locators.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include <limits>
#include <memory>

#include "common/thread_pool.h"
#include "geometry/scene.h"

namespace sonarcarve {

struct EvaluationResult {
  double tau_m = 0.05;
  std::size_t reconstructed_points = 0;
  std::size_t reference_points = 0;
  double accuracy_mean_m = 0.0;
  double accuracy_median_m = 0.0;
  double accuracy_p90_m = 0.0;
  double precision = 0.0;
  double completeness = 0.0;
  /// Completeness on reference points whose nearest face is within 30 degrees of horizontal
  /// (normal within 30 degrees of vertical), and on the others; with their counts.
  double completeness_horizontal = 0.0;
  double completeness_other = 0.0;
  std::size_t reference_points_horizontal = 0;
  std::size_t reference_points_other = 0;
  double fscore = 0.0;
  double chamfer_m = 0.0;
  std::size_t floating_points = 0;  ///< reconstructed points farther than 10 cm from the mesh
  /// Spacing of the points sampled on the mesh for completeness (0: reference points given).
  /// Completeness is measured to this resolution.
  double reference_spacing_m = 0.0;
  std::vector<float> point_errors_m;  ///< per reconstructed point

  std::string toJson() const;
};

/// Distances from points to a mesh, with the mesh's locator built once (for viewers that
/// colour a growing map by its error). distances() is thread safe; it runs on `pool`, which
/// must outlive this.
class MeshDistance {
 public:
  MeshDistance(const Scene& mesh, ThreadPool& pool);
  ~MeshDistance();
  MeshDistance(const MeshDistance&) = delete;
  MeshDistance& operator=(const MeshDistance&) = delete;
  /// Distances, metres; with a finite `max_distance_m` farther points get that value (much
  /// faster for points far from the mesh, enough for colouring).
  std::vector<float> distances(
      const std::vector<Eigen::Vector3f>& points,
      double max_distance_m = std::numeric_limits<double>::infinity()) const;
  /// Index into the mesh's triangles of the triangle nearest each point.
  std::vector<std::size_t> nearestTriangles(const std::vector<Eigen::Vector3f>& points) const;

 private:
  struct Locator;  // VTK stays out of core's public headers
  // Runs `visit(i, squared distance, cell)` for each point's closest point on the mesh.
  void forEachClosest(const std::vector<Eigen::Vector3f>& points, double max_distance_m,
                      const std::function<void(std::size_t, double, long long)>& visit) const;
  std::unique_ptr<Locator> locator_;
  ThreadPool& pool_;
};

/// At most this many points are sampled on a mesh (or 3 a triangle for a mesh of more than 1.3
/// million triangles): a larger mesh is sampled more coarsely and the spacing used is reported
/// (reference_spacing_m), so that evaluation time and memory stay bounded whatever the mesh's
/// size (a 1 km triangle at 1 cm would be 5e9 points).
inline constexpr double kMaxReferenceSamples = 4.0e6;

/// `reference_points` may be empty: the mesh is then sampled every 1 cm, or more coarsely to
/// stay under kMaxReferenceSamples. Distances are computed in parallel on `pool`.
EvaluationResult evaluate(const std::vector<Eigen::Vector3f>& reconstruction, const Scene& mesh,
                          std::vector<Eigen::Vector3f> reference_points, ThreadPool& pool,
                          double tau_m = 0.05);

/// Points spread over the mesh surface about every `spacing_m` (deterministic).
std::vector<Eigen::Vector3f> sampleSurface(const Scene& mesh, double spacing_m);
/// How many points sampleSurface(mesh, spacing_m) gives, without making them.
double sampleCount(const Scene& mesh, double spacing_m);

}  // namespace sonarcarve
