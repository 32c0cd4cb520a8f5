// From ProjectedSonarImage messages to our sonar model and frames (docs/formats.md, "ROS 2
// bags"): ranges (bin centres, equally spaced) -> range bins; beam_directions, in the chosen
// axis convention -> a bearing table (sorted port to starboard, non-uniform tables kept as
// they are); tx_beamwidths -> vertical aperture; data (uint8 ... float64, either layout) ->
// a CV_32F image of the sonar's counts.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "io/rosbag/bag_options.h"
#include "io/rosbag/ros_messages.h"
#include "sonar/sonar_model.h"

namespace sonarcarve {

/// The vertical aperture assumed when a message gives no tx_beamwidths (the seed paper's).
inline constexpr double kBagDefaultApertureDeg = 20.0;

struct BagSonarGeometry {
  SonarModel sonar;
  SonarAxes axes = SonarAxes::ZForward;  ///< as resolved (never Auto)
  ImageLayout layout = ImageLayout::RangeMajor;
  std::vector<Eigen::Vector3d> beam_directions;  ///< of the first message
  std::vector<int> beam_of_column;               ///< message beam of each image column
  std::size_t ranges = 0;
  std::vector<std::string> notes;  ///< what was assumed, for `info`
  /// The aperture is the messages' (tx_beamwidths), not --aperture-deg's: each message's is
  /// checked against the physical range, as the first's was.
  bool aperture_from_messages = false;
};

/// The geometry of the first message. Throws Error (source, place, what was expected) for
/// inconsistent sizes, non-increasing or unequally spaced ranges, or repeated bearings.
BagSonarGeometry bagSonarGeometry(const ProjectedSonarImageMsg& msg, SonarAxes axes,
                                  ImageLayout layout, std::optional<double> aperture_deg,
                                  const std::string& sonar_id, const std::string& source,
                                  const std::string& place);

/// Throws Error unless the message has `geometry`'s beams and ranges and data of that size, a
/// sound speed within the physical range (or 0) and, when the aperture is the messages', an
/// aperture (tx_beamwidths) within it.
void checkBagSonarMessage(const ProjectedSonarImageMsg& msg, const BagSonarGeometry& geometry,
                          const std::string& source, const std::string& place);

/// A message's image as our frame image (rows: ranges near to far, columns: port to
/// starboard). Throws Error if its geometry is not `geometry`'s or its data is short.
cv::Mat bagSonarImage(const ProjectedSonarImageMsg& msg, const BagSonarGeometry& geometry,
                      const std::string& source, const std::string& place);

}  // namespace sonarcarve
