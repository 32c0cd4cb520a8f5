#include "eval/evaluator.h"

#include <vtkGenericCell.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "common/angles.h"
#include "common/error.h"
#include "common/quantile.h"
#include "common/thread_pool.h"
#include "geometry/internal/vtk_mesh.h"
#include "io/files/finite_points.h"

namespace sonarcarve {
namespace {

// The q-quantile of a copy of `values`; 0 for none.
double quantileOf(std::vector<float> values, double q) {
  return values.empty() ? 0.0 : quantile(values, q);
}

// Reference points farther than this from every reconstructed point count at this distance
// (in the Chamfer distance): an unbounded search from far outside the cloud visits every bin
// of the locator in between, minutes for a structure the reconstruction missed.
constexpr double kFarDistance_m = 1.0;

std::vector<float> distancesToPoints(const std::vector<Eigen::Vector3f>& queries,
                                     const std::vector<Eigen::Vector3f>& cloud, ThreadPool& pool) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(cloud.size()));
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), cloud[i].x(), cloud[i].y(), cloud[i].z());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(poly);
  locator->BuildLocator();
  std::vector<float> d(queries.size());
  pool.parallelFor(queries.size(), 1024, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      double x[3] = {queries[i].x(), queries[i].y(), queries[i].z()};
      double dist2 = 0.0;
      const vtkIdType id = locator->FindClosestPointWithinRadius(kFarDistance_m, x, dist2);
      d[i] = id < 0 ? static_cast<float>(kFarDistance_m)
                    : (cloud[static_cast<std::size_t>(id)] - queries[i]).norm();
    }
  });
  return d;
}

double mean(const std::vector<float>& v) {
  double s = 0.0;
  for (float x : v) {
    s += x;
  }
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

double fractionWithin(const std::vector<float>& v, double tau) {
  if (v.empty()) {
    return 0.0;
  }
  const auto n = std::count_if(v.begin(), v.end(), [&](float d) { return d <= tau; });
  return static_cast<double>(n) / static_cast<double>(v.size());
}

// A face is horizontal when its normal lies within 30 degrees of vertical.
bool isHorizontal(const Scene& mesh, std::size_t triangle) {
  const auto& t = mesh.triangles[triangle];
  const Eigen::Vector3f n =
      (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
  return n.squaredNorm() > 0.0f && std::abs(n.z()) >= std::cos(degToRad(30.0)) * n.norm();
}

}  // namespace

struct MeshDistance::Locator {
  vtkSmartPointer<vtkPolyData> poly;
  vtkSmartPointer<vtkStaticCellLocator> cells;
};

MeshDistance::MeshDistance(const Scene& mesh, ThreadPool& pool)
    : locator_(std::make_unique<Locator>()), pool_(pool) {
  locator_->poly = polyDataFromScene(mesh);
  locator_->cells = vtkSmartPointer<vtkStaticCellLocator>::New();
  locator_->cells->SetDataSet(locator_->poly);
  locator_->cells->BuildLocator();
}

MeshDistance::~MeshDistance() = default;

void MeshDistance::forEachClosest(
    const std::vector<Eigen::Vector3f>& points, double max_distance_m,
    const std::function<void(std::size_t, double, long long)>& visit) const {
  const bool bounded = std::isfinite(max_distance_m);
  pool_.parallelFor(points.size(), 1024, [&](std::size_t b, std::size_t e) {
    auto cell = vtkSmartPointer<vtkGenericCell>::New();
    for (std::size_t i = b; i < e; ++i) {
      double x[3] = {points[i].x(), points[i].y(), points[i].z()};
      double closest[3];
      vtkIdType cell_id = -1;
      int sub_id = 0;
      double dist2 = 0.0;
      if (!bounded) {
        locator_->cells->FindClosestPoint(x, closest, cell, cell_id, sub_id, dist2);
      } else if (locator_->cells->FindClosestPointWithinRadius(x, max_distance_m, closest, cell,
                                                               cell_id, sub_id, dist2) == 0) {
        dist2 = max_distance_m * max_distance_m;
        cell_id = -1;
      }
      visit(i, dist2, static_cast<long long>(cell_id));
    }
  });
}

std::vector<float> MeshDistance::distances(const std::vector<Eigen::Vector3f>& points,
                                           double max_distance_m) const {
  std::vector<float> d(points.size());
  forEachClosest(points, max_distance_m, [&](std::size_t i, double dist2, long long) {
    d[i] = static_cast<float>(std::sqrt(dist2));
  });
  return d;
}

std::vector<std::size_t> MeshDistance::nearestTriangles(
    const std::vector<Eigen::Vector3f>& points) const {
  std::vector<std::size_t> nearest(points.size());
  forEachClosest(
      points, std::numeric_limits<double>::infinity(),
      [&](std::size_t i, double, long long cell) { nearest[i] = static_cast<std::size_t>(cell); });
  return nearest;
}

namespace {

// Divisions of a triangle's sides at `spacing_m`: its longest side over the spacing, at least 1.
double divisions(const Scene& mesh, const std::array<std::uint32_t, 3>& t, double spacing_m) {
  const Eigen::Vector3f ab = mesh.vertices[t[1]] - mesh.vertices[t[0]];
  const Eigen::Vector3f ac = mesh.vertices[t[2]] - mesh.vertices[t[0]];
  const double longest = std::max({ab.norm(), ac.norm(), (ab - ac).norm()});
  return std::max(1.0, std::ceil(longest / spacing_m));
}

}  // namespace

double sampleCount(const Scene& mesh, double spacing_m) {
  double count = 0.0;
  for (const auto& t : mesh.triangles) {
    const double n = divisions(mesh, t, spacing_m);
    count += (n + 1.0) * (n + 2.0) / 2.0;
  }
  return count;
}

std::vector<Eigen::Vector3f> sampleSurface(const Scene& mesh, double spacing_m) {
  std::vector<Eigen::Vector3f> points;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3f a = mesh.vertices[t[0]];
    const Eigen::Vector3f ab = mesh.vertices[t[1]] - a;
    const Eigen::Vector3f ac = mesh.vertices[t[2]] - a;
    const int n = static_cast<int>(divisions(mesh, t, spacing_m));
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        points.push_back(a + (static_cast<float>(i) / n) * ab + (static_cast<float>(j) / n) * ac);
      }
    }
  }
  return points;
}

EvaluationResult evaluate(const std::vector<Eigen::Vector3f>& reconstruction, const Scene& mesh,
                          std::vector<Eigen::Vector3f> reference_points, ThreadPool& pool,
                          double tau_m) {
  if (mesh.triangles.empty()) {
    throw Error("evaluation", "reference", "the reference mesh has no triangles");
  }
  if (reconstruction.empty()) {
    throw Error("evaluation", "reconstruction", "the reconstruction has no points");
  }
  if (!(tau_m > 0.0) || !std::isfinite(tau_m)) {
    throw Error("evaluation", "tau", "expected a positive distance in metres");
  }
  // A NaN is within no distance and beyond none: it would make the figures depend on the order.
  for (std::size_t i = 0; i < reconstruction.size(); ++i) {
    requireFinitePoint(reconstruction[i], "evaluation",
                       "reconstruction point " + std::to_string(i));
  }
  for (std::size_t i = 0; i < reference_points.size(); ++i) {
    requireFinitePoint(reference_points[i], "evaluation", "visible point " + std::to_string(i));
  }
  EvaluationResult r;
  if (reference_points.empty()) {
    // Each triangle gives at least its 3 corners, whatever the spacing.
    const double fewest = 3.0 * static_cast<double>(mesh.triangles.size());
    r.reference_spacing_m = 0.01;
    while (sampleCount(mesh, r.reference_spacing_m) > std::max(kMaxReferenceSamples, fewest)) {
      r.reference_spacing_m *= 1.25;
    }
    reference_points = sampleSurface(mesh, r.reference_spacing_m);
  }
  r.tau_m = tau_m;
  r.reconstructed_points = reconstruction.size();
  r.reference_points = reference_points.size();
  const MeshDistance to_mesh(mesh, pool);
  r.point_errors_m = to_mesh.distances(reconstruction);
  r.accuracy_mean_m = mean(r.point_errors_m);
  r.accuracy_median_m = quantileOf(r.point_errors_m, 0.5);
  r.accuracy_p90_m = quantileOf(r.point_errors_m, 0.9);
  r.precision = fractionWithin(r.point_errors_m, tau_m);
  r.floating_points = static_cast<std::size_t>(std::count_if(
      r.point_errors_m.begin(), r.point_errors_m.end(), [](float d) { return d > 0.10f; }));
  const std::vector<float> to_reconstruction =
      distancesToPoints(reference_points, reconstruction, pool);
  r.completeness = fractionWithin(to_reconstruction, tau_m);
  const std::vector<std::size_t> faces = to_mesh.nearestTriangles(reference_points);
  std::size_t found_horizontal = 0, found_other = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const bool found = to_reconstruction[i] <= tau_m;
    if (isHorizontal(mesh, faces[i])) {
      ++r.reference_points_horizontal;
      found_horizontal += found ? 1 : 0;
    } else {
      ++r.reference_points_other;
      found_other += found ? 1 : 0;
    }
  }
  const auto ratio = [](std::size_t a, std::size_t b) {
    return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b);
  };
  r.completeness_horizontal = ratio(found_horizontal, r.reference_points_horizontal);
  r.completeness_other = ratio(found_other, r.reference_points_other);
  r.fscore = r.precision + r.completeness > 0.0
                 ? 2.0 * r.precision * r.completeness / (r.precision + r.completeness)
                 : 0.0;
  r.chamfer_m = r.accuracy_mean_m + mean(to_reconstruction);
  return r;
}

std::string EvaluationResult::toJson() const {
  return nlohmann::json{{"tau_m", tau_m},
                        {"reconstructed_points", reconstructed_points},
                        {"reference_points", reference_points},
                        {"accuracy_mean_m", accuracy_mean_m},
                        {"accuracy_median_m", accuracy_median_m},
                        {"accuracy_p90_m", accuracy_p90_m},
                        {"precision", precision},
                        {"completeness", completeness},
                        {"completeness_horizontal", completeness_horizontal},
                        {"completeness_other", completeness_other},
                        {"reference_points_horizontal", reference_points_horizontal},
                        {"reference_points_other", reference_points_other},
                        {"fscore", fscore},
                        {"chamfer_m", chamfer_m},
                        {"floating_points_over_10cm", floating_points},
                        {"reference_spacing_m", reference_spacing_m}}
      .dump(2);
}

}  // namespace sonarcarve
