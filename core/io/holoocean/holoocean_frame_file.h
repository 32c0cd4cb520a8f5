// One frame of a HoloOcean / NeuSIS dataset: a Data/*.pkl pickle holding a dict of the sensors'
// readings (io/pickle/pickle_reader.h), of which the ImagingSonar image and the PoseSensor
// matrix are read (docs/formats.md, "HoloOcean / NeuSIS datasets").
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

#include "io/pickle/pickle_value.h"

namespace sonarcarve {

/// The PoseSensor's 4 x 4 matrix under `key` of the pickle's dict: finite, its last row
/// (0, 0, 0, 1), its rotation orthonormal with determinant 1 (within float32's rounding).
/// Throws Error naming `file` and the key.
Eigen::Matrix4d holoOceanPose(const pickle::Value& state, const std::string& key,
                              const std::string& file);

/// The image under `key`: a 2-D array of `rows` x `cols` finite numbers >= 0, as a CV_32F image
/// in our column order (port to starboard: HoloOcean's columns mirrored). Throws Error naming
/// `file` and the key.
cv::Mat holoOceanImage(const pickle::Value& state, const std::string& key, int rows, int cols,
                       const std::string& file);

/// The rows and columns of the 2-D array under `key`. Throws Error naming `file` and the key.
std::pair<int, int> holoOceanImageSize(const pickle::Value& state, const std::string& key,
                                       const std::string& file);

/// The Data folder's .pkl files in natural order (frame_2 before frame_10).
std::vector<std::filesystem::path> holoOceanFrameFiles(const std::filesystem::path& data_folder);

}  // namespace sonarcarve
