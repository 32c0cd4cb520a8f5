// A test pickle writer: writes what Python's pickler writes for a HoloOcean / NeuSIS frame (a
// dict of numpy float32 arrays) in protocols 2 to 5, as numpy 1.x reduces its arrays
// (numpy.core.multiarray._reconstruct and a BUILD state; _frombuffer and an in-band buffer in
// protocol 5; bytes as _codecs.encode(text, 'latin1') in protocol 2). Its opcodes can also be
// written one by one, for the bad pickles of the reader's tests.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "io/mission/mission.h"

namespace sonarcarve::test {

class PickleWriter {
 public:
  explicit PickleWriter(int protocol);
  int protocol() const { return protocol_; }

  PickleWriter& op(unsigned char opcode);
  PickleWriter& raw(std::string_view bytes);
  PickleWriter& text(std::string_view text);
  PickleWriter& integer(std::int64_t value);
  PickleWriter& real(double value);
  PickleWriter& bytes(std::string_view data);
  PickleWriter& global(std::string_view module, std::string_view name);
  PickleWriter& memoize();
  /// A numpy array of float32 (`double_precision`: float64) of `shape`, C order.
  PickleWriter& numpyArray(const std::vector<double>& values, const std::vector<int>& shape,
                           bool double_precision = false);
  /// A numpy array as numpy 1.x reduces it below protocol 5: _reconstruct(ndarray, (0,), b'b')
  /// and the state (1, shape, dtype, fortran_order, data), shape and data as given (a test may
  /// make them disagree). `dtype` as numpy.dtype's first argument ("f4"), `order` its state's.
  PickleWriter& reconstructedArray(const std::vector<std::int64_t>& shape, std::string_view dtype,
                                   std::string_view order, bool fortran_order,
                                   std::string_view data);
  /// numpy.dtype(`text`, False, True) with the state (3, `order`, None, None, None, -1, -1, 0).
  PickleWriter& dtype(std::string_view text, std::string_view order);
  /// The pickle: the opcodes written, framed in protocols 4 and 5, and STOP.
  std::string finish() const;

 private:
  int protocol_;
  std::string body_;
  int memo_ = 0;
};

/// One frame as HoloOcean's env.tick() state pickled by NeuSIS: {"ImagingSonar": image (float32,
/// HoloOcean's columns: starboard first), "PoseSensor": 4 x 4 float32}.
std::string holoOceanFramePickle(const cv::Mat& holo_image, const Eigen::Matrix4d& pose,
                                 int protocol);

/// A NeuSIS dataset folder (Config.json, Data/000000.pkl ...) from a mission whose sonar has a
/// uniform bearing table: each frame's image (power, columns mirrored to HoloOcean's) and its
/// sonar's world pose (navigation and mounting, in HoloOcean's frame).
void writeNeusisDataset(const Mission& mission, const std::filesystem::path& out, int protocol);

/// The Config.json of a NeuSIS dataset for `sonar` (its range window and uniform bearings).
std::string neusisConfigJson(const SonarModel& sonar);

}  // namespace sonarcarve::test
