// Reading scene meshes (STL, OBJ, PLY through VTK's readers) and writing meshes and point
// clouds as PLY. Writes are atomic (temporary file, then rename).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "geometry/scene.h"

namespace sonarcarve {

/// The reflectivity a mesh file gets when it does not say (it never does).
inline constexpr float kDefaultReflectivity = 0.8f;

/// Loads a mesh in world coordinates (NED, metres) with one reflectivity for all of it, minus
/// `origin_ned_m` (a mission's origin: PLY and OBJ subtract it in double; STL stores floats).
/// Throws Error naming the file if it is missing, of an unknown type, empty or unreadable.
Scene loadSceneMesh(const std::filesystem::path& path, float reflectivity = kDefaultReflectivity,
                    const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero());

/// Writes the scene's triangles as binary PLY.
void writeScenePly(const Scene& scene, const std::filesystem::path& path);

/// Writes points (with an optional scalar per point, named `scalar_name`) as binary PLY.
void writePointsPly(const std::vector<Eigen::Vector3f>& points, const std::filesystem::path& path,
                    const std::vector<float>& scalars = {}, const char* scalar_name = "value");
/// Reads the points of a PLY file (vertices only), minus `origin_ned_m` in double. Throws Error
/// if it cannot.
std::vector<Eigen::Vector3f> readPointsPly(
    const std::filesystem::path& path,
    const Eigen::Vector3d& origin_ned_m = Eigen::Vector3d::Zero());

}  // namespace sonarcarve
