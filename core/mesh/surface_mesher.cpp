#include "mesh/surface_mesher.h"

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkContourFilter.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkPolyDataNormals.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkStaticPointLocator.h>
#include <vtkSurfaceReconstructionFilter.h>
#include <vtkTriangleFilter.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include "common/error.h"
#include "geometry/internal/vtk_mesh.h"
#include "mesh/internal/occupancy_contour.h"

namespace sonarcarve {
namespace {

vtkSmartPointer<vtkPolyData> pointCloud(const SurfacePoints& points) {
  auto vtk_points = vtkSmartPointer<vtkPoints>::New();
  vtk_points->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i].position_m;
    vtk_points->SetPoint(static_cast<vtkIdType>(i), p.x(), p.y(), p.z());
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(vtk_points);
  return poly;
}

vtkSmartPointer<vtkPolyData> implicitSurface(vtkPolyData* cloud, const MeshParams& params) {
  auto hoppe = vtkSmartPointer<vtkSurfaceReconstructionFilter>::New();
  hoppe->SetInputData(cloud);
  hoppe->SetSampleSpacing(params.voxel_size_m);
  hoppe->SetNeighborhoodSize(20);
  auto contour = vtkSmartPointer<vtkContourFilter>::New();
  contour->SetInputConnection(hoppe->GetOutputPort());
  contour->SetValue(0, 0.0);
  contour->Update();
  vtkSmartPointer<vtkPolyData> surface = contour->GetOutput();
  // Keep the triangles some point supports: the zero set also closes over empty places.
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  const double limit = params.max_distance_voxels * params.voxel_size_m;
  auto kept = vtkSmartPointer<vtkCellArray>::New();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c) {
    surface->GetCellPoints(c, ids);
    double centroid[3] = {0, 0, 0};
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      double p[3];
      surface->GetPoint(ids->GetId(k), p);
      for (int a = 0; a < 3; ++a)
        centroid[a] += p[a] / static_cast<double>(ids->GetNumberOfIds());
    }
    double dist2 = 0.0;
    if (locator->FindClosestPointWithinRadius(limit, centroid, dist2) >= 0) {
      kept->InsertNextCell(ids);
    }
  }
  auto trimmed = vtkSmartPointer<vtkPolyData>::New();
  trimmed->SetPoints(surface->GetPoints());
  trimmed->SetPolys(kept);
  auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
  clean->SetInputData(trimmed);
  clean->Update();
  return clean->GetOutput();
}

OccupancyContourParams occupancyParams(const MeshParams& params) {
  OccupancyContourParams contour;
  contour.voxel_size_m = params.voxel_size_m;
  contour.sigma_voxels = params.occupancy_sigma_voxels;
  contour.iso = params.occupancy_iso;
  return contour;
}

}  // namespace

void MeshParams::validate() const {
  if (!hasName(method)) {
    throw Error("parameters", "mesh.method", "expected implicit or occupancy");
  }
  if (!(voxel_size_m > 0.0) || !(max_distance_voxels > 0.0)) {
    throw Error("parameters", "mesh", "expected a positive voxel size and distance");
  }
  if (decimate < 0.0 || decimate > 0.95) {
    throw Error("parameters", "mesh.decimate", "expected a fraction in [0, 0.95]");
  }
}

Mesh meshSurface(const SurfacePoints& points, const MeshParams& params) {
  params.validate();
  if (points.size() < 10) {
    throw Error("meshing", "",
                "too few surface points to mesh (" + std::to_string(points.size()) + ")");
  }
  const auto cloud = pointCloud(points);
  vtkSmartPointer<vtkPolyData> surface = params.method == MeshMethod::Implicit
                                             ? implicitSurface(cloud, params)
                                             : occupancyContour(points, occupancyParams(params));
  // Each filter lets go of its output once the next one has read it: memory holds about two
  // copies of the surface, not one per filter.
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->SetInputData(surface);
  triangles->ReleaseDataFlagOn();
  // Fragments: keep the connected regions of at least min_fragment_triangles.
  auto regions = vtkSmartPointer<vtkPolyDataConnectivityFilter>::New();
  regions->SetInputConnection(triangles->GetOutputPort());
  regions->SetExtractionModeToAllRegions();
  regions->Update();
  vtkIdTypeArray* sizes = regions->GetRegionSizes();
  regions->SetExtractionModeToSpecifiedRegions();
  for (vtkIdType r = 0; r < regions->GetNumberOfExtractedRegions(); ++r) {
    if (static_cast<std::size_t>(sizes->GetValue(r)) >= params.min_fragment_triangles) {
      regions->AddSpecifiedRegion(static_cast<int>(r));
    }
  }
  regions->ReleaseDataFlagOn();
  auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
  clean->SetInputConnection(regions->GetOutputPort());
  clean->ReleaseDataFlagOn();
  vtkAlgorithmOutput* last = clean->GetOutputPort();
  auto smoother = vtkSmartPointer<vtkWindowedSincPolyDataFilter>::New();
  if (params.smoothing_iterations > 0) {
    smoother->SetInputConnection(last);
    smoother->SetNumberOfIterations(params.smoothing_iterations);
    smoother->SetPassBand(params.smoothing_passband);
    smoother->NonManifoldSmoothingOn();
    smoother->NormalizeCoordinatesOn();
    smoother->BoundarySmoothingOff();
    smoother->ReleaseDataFlagOn();
    last = smoother->GetOutputPort();
  }
  auto decimate = vtkSmartPointer<vtkQuadricDecimation>::New();
  if (params.decimate > 0.0) {
    decimate->SetInputConnection(last);
    decimate->SetTargetReduction(params.decimate);
    decimate->ReleaseDataFlagOn();
    last = decimate->GetOutputPort();
  }
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputConnection(last);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->Update();
  vtkPolyData* out = normals->GetOutput();

  Mesh mesh;
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  vtkDataArray* point_normals = out->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    mesh.vertices.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]),
                               static_cast<float>(p[2]));
    double n[3] = {0, 0, 1};
    if (point_normals != nullptr) {
      point_normals->GetTuple(i, n);
    }
    mesh.normals.emplace_back(static_cast<float>(n[0]), static_cast<float>(n[1]),
                              static_cast<float>(n[2]));
    const SurfacePoint& nearest = points[static_cast<std::size_t>(locator->FindClosestPoint(p))];
    mesh.intensity.push_back(nearest.intensity);
    mesh.views.push_back(nearest.views);
  }
  mesh.triangles = trianglesOf(out);
  return mesh;
}

}  // namespace sonarcarve
