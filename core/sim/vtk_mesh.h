// Conversion between VTK poly data and Scene. Internal to core: VTK types never appear in
// core's public headers.
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "sim/scene.h"

namespace sonarcarve {

/// Triangulates, computes smooth normals (split at sharp edges) and copies into a Scene.
Scene sceneFromPolyData(vtkPolyData* poly, float reflectivity, const std::string& name);
vtkSmartPointer<vtkPolyData> polyDataFromScene(const Scene& scene);

}  // namespace sonarcarve
