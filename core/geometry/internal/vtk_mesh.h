// Conversion between VTK poly data and Scene, for core's VTK-based steps (mesh files, demo
// scenes, surface extraction, evaluation). Internal to core: VTK types never appear in core's
// public headers (core/CMakeLists.txt).
#pragma once

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/scene.h"

namespace sonarcarve {

/// Triangulates, computes smooth normals (split at sharp edges) and copies into a Scene.
Scene sceneFromPolyData(vtkPolyData* poly, float reflectivity, const std::string& name);
vtkSmartPointer<vtkPolyData> polyDataFromScene(const Scene& scene);

/// Poly data of vertices and triangles (float points).
vtkSmartPointer<vtkPolyData> triangleMesh(
    const std::vector<Eigen::Vector3f>& vertices,
    const std::vector<std::array<std::uint32_t, 3>>& triangles);
/// Throws Error naming `file` and the vertex or face for a vertex that is not finite or a
/// face whose vertex index is out of range. Run on every mesh read before any filter sees it.
void requireValidPolyData(vtkPolyData* poly, const std::string& file);
/// The triangles of a poly data's polygons (other polygons are skipped).
std::vector<std::array<std::uint32_t, 3>> trianglesOf(vtkPolyData* poly);

}  // namespace sonarcarve
