// Pictures of a map for the survey report (pipeline/report_html.h): its surface points seen
// from above (north up), from the north (looking south) and from the east (looking west),
// each point a square of its voxel coloured by its height, drawn nearest last, with a scale
// bar, the height's colour key and the compass directions at the picture's sides. OpenCV
// only: core has no Qt, and VTK's offscreen rendering needs a display.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace sonarcarve {

struct MapPicture {
  std::string title;  ///< "From above"
  cv::Mat image;      ///< BGR, 8 bits
};

/// The three views of `points` (local NED, metres), each `width_px` wide; none when there are
/// no points.
std::vector<MapPicture> mapPictures(const std::vector<Eigen::Vector3f>& points, double voxel_m,
                                    int width_px = 560);

/// A round length for a scale bar at most `max_m` long: 1, 2 or 5 times a power of ten.
double scaleBarLength(double max_m);

/// A length as a scale bar labels it: "50 cm", "2 m", "1 km".
std::string lengthLabel(double metres);

}  // namespace sonarcarve
