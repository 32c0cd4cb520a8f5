#include "io/holoocean/holoocean_frame_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "common/error.h"
#include "common/input_limits.h"
#include "common/number_text.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// Rounding of a float32 matrix: a rotation written as float32 is orthonormal to about 1e-7.
constexpr double kRotationTolerance = 1e-4;

const pickle::NumpyArray& arrayAt(const pickle::Value& state, const std::string& key,
                                  const std::string& file) {
  if (state.kind != pickle::Kind::Dict) {
    throw Error(file, "",
                std::string("the pickle holds a ") + pickle::kindName(state.kind) +
                    ": expected a dict of sensor readings");
  }
  const pickle::Value* value = pickle::dictItem(state, key);
  if (value == nullptr) {
    throw Error(file, "key " + key, "missing: expected the sensor's reading (a numpy array)");
  }
  if (value->kind != pickle::Kind::Array) {
    throw Error(file, "key " + key,
                std::string("is a ") + pickle::kindName(value->kind) + ": expected a numpy array");
  }
  return value->array;
}

std::string shapeText(const std::vector<std::int64_t>& shape) {
  std::string text;
  for (std::int64_t d : shape) {
    text += (text.empty() ? "" : " x ") + std::to_string(d);
  }
  return text.empty() ? "()" : text;
}

// Natural order: runs of digits compare as numbers.
bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) &&
        std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie])))
        ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je])))
        ++je;
      std::string da = a.substr(i, ie - i), db = b.substr(j, je - j);
      da.erase(0, std::min(da.find_first_not_of('0'), da.size()));
      db.erase(0, std::min(db.find_first_not_of('0'), db.size()));
      if (da.size() != db.size())
        return da.size() < db.size();
      if (da != db)
        return da < db;
      i = ie;
      j = je;
    } else {
      if (a[i] != b[j])
        return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

}  // namespace

Eigen::Matrix4d holoOceanPose(const pickle::Value& state, const std::string& key,
                              const std::string& file) {
  const pickle::NumpyArray& array = arrayAt(state, key, file);
  if (array.shape != std::vector<std::int64_t>{4, 4}) {
    throw Error(file, "key " + key,
                "a numpy array of shape " + shapeText(array.shape) + ": expected 4 x 4");
  }
  const std::vector<double> v = pickle::numpyElements(array);
  Eigen::Matrix4d T;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      T(r, c) = v[static_cast<std::size_t>(r * 4 + c)];
    }
  }
  if (!T.allFinite() || T.topRightCorner<3, 1>().cwiseAbs().maxCoeff() > kMaxNavCoordinate_m) {
    throw Error(file, "key " + key,
                "a position that is not finite or beyond " + shortestNumber(kMaxNavCoordinate_m) +
                    " m: expected a pose in metres");
  }
  if ((T.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > kRotationTolerance) {
    throw Error(file, "key " + key, "last row is not (0, 0, 0, 1): expected a 4 x 4 pose matrix");
  }
  const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
  const double off = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (off > kRotationTolerance || R.determinant() < 0.0) {
    throw Error(file, "key " + key,
                "its 3 x 3 part is not a rotation (R'R - I off by " + shortestNumber(off) +
                    ", determinant " + shortestNumber(R.determinant()) +
                    "): expected a rotation and a translation");
  }
  return T;
}

std::pair<int, int> holoOceanImageSize(const pickle::Value& state, const std::string& key,
                                       const std::string& file) {
  const pickle::NumpyArray& array = arrayAt(state, key, file);
  if (array.shape.size() != 2 || array.shape[0] < 1 || array.shape[1] < 1 ||
      array.shape[0] > kMaxRangeBins || array.shape[1] > kMaxBeams) {
    throw Error(file, "key " + key,
                "a numpy array of shape " + shapeText(array.shape) +
                    ": expected range bins x beams (at most " + std::to_string(kMaxRangeBins) +
                    " x " + std::to_string(kMaxBeams) + ")");
  }
  return {static_cast<int>(array.shape[0]), static_cast<int>(array.shape[1])};
}

cv::Mat holoOceanImage(const pickle::Value& state, const std::string& key, int rows, int cols,
                       const std::string& file) {
  const auto [r, c] = holoOceanImageSize(state, key, file);
  if (r != rows || c != cols) {
    throw Error(file, "key " + key,
                "an image of " + std::to_string(r) + " x " + std::to_string(c) + ": expected " +
                    std::to_string(rows) + " x " + std::to_string(cols) +
                    " (RangeBins x AzimuthBins of Config.json)");
  }
  const std::vector<double> v = pickle::numpyElements(arrayAt(state, key, file));
  cv::Mat image(rows, cols, CV_32F);
  for (int i = 0; i < rows; ++i) {
    auto* row = image.ptr<float>(i);
    for (int j = 0; j < cols; ++j) {
      const double value = v[static_cast<std::size_t>(i) * static_cast<std::size_t>(cols) +
                             static_cast<std::size_t>(j)];
      if (!(value >= 0.0) || !std::isfinite(value)) {
        throw Error(file, "key " + key,
                    "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") is " +
                        shortestNumber(value) + ": expected a finite intensity >= 0");
      }
      row[cols - 1 - j] = static_cast<float>(value);  // HoloOcean's column 0 is starboard
    }
  }
  return image;
}

std::vector<std::filesystem::path> holoOceanFrameFiles(const std::filesystem::path& data_folder) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(data_folder, ec)) {
    if (entry.path().extension() == ".pkl") {
      files.push_back(entry.path());
    }
  }
  if (ec) {
    throw Error(data_folder.string(), "", "cannot be listed: " + ec.message());
  }
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    return naturalLess(a.filename().string(), b.filename().string());
  });
  return files;
}

}  // namespace sonarcarve
