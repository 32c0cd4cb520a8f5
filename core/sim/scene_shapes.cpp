#include "sim/scene_shapes.h"

#include <vtkCubeSource.h>
#include <vtkLineSource.h>
#include <vtkPlaneSource.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTubeFilter.h>
#include <cmath>
#include <numbers>

#include "geometry/internal/vtk_mesh.h"

namespace sonarcarve {

Scene tubeShape(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius, int sides,
                float reflectivity) {
  auto line = vtkSmartPointer<vtkLineSource>::New();
  line->SetPoint1(a.data());
  line->SetPoint2(b.data());
  auto tube = vtkSmartPointer<vtkTubeFilter>::New();
  tube->SetInputConnection(line->GetOutputPort());
  tube->SetRadius(radius);
  tube->SetNumberOfSides(sides);
  tube->CappingOn();
  tube->Update();
  return sceneFromPolyData(tube->GetOutput(), reflectivity, "tube");
}

Scene sphereShape(const Eigen::Vector3d& centre, double radius, float reflectivity, int around) {
  auto s = vtkSmartPointer<vtkSphereSource>::New();
  s->SetCenter(centre.data());
  s->SetRadius(radius);
  s->SetThetaResolution(around);
  s->SetPhiResolution(around / 2);
  s->Update();
  return sceneFromPolyData(s->GetOutput(), reflectivity, "sphere");
}

Scene boxShape(const Eigen::Vector3d& centre, const Eigen::Vector3d& size, double yaw_deg,
               float reflectivity) {
  auto cube = vtkSmartPointer<vtkCubeSource>::New();
  cube->SetXLength(size.x());
  cube->SetYLength(size.y());
  cube->SetZLength(size.z());
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->Translate(centre.data());
  transform->RotateZ(yaw_deg);
  auto filter = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  filter->SetInputConnection(cube->GetOutputPort());
  filter->SetTransform(transform);
  filter->Update();
  return sceneFromPolyData(filter->GetOutput(), reflectivity, "box");
}

Scene seabedSquare(const Eigen::Vector3d& centre, double size, double slope_deg, int resolution,
                   float reflectivity) {
  const double half = 0.5 * size;
  const double drop = half * std::tan(slope_deg * std::numbers::pi / 180.0);
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(centre.x() - half, centre.y() - half, centre.z() - drop);
  plane->SetPoint1(centre.x() + half, centre.y() - half, centre.z() + drop);
  plane->SetPoint2(centre.x() - half, centre.y() + half, centre.z() - drop);
  plane->SetResolution(resolution, resolution);
  plane->Update();
  return sceneFromPolyData(plane->GetOutput(), reflectivity, "seabed");
}

}  // namespace sonarcarve
