// Converting a polar sonar frame into a QImage for display: rows are range bins with the
// nearest at the bottom (as an analyst reads a sonar display), columns are beams from port
// (left) to starboard (right); intensities are mapped linearly from [low, high] onto a
// colour map. Pure function, safe to call from any thread.
#pragma once

#include <QImage>
#include <opencv2/core.hpp>

#include "colour_maps.h"
#include "sonar/fan_image.h"

namespace sonarcarve::widgets {

/// Intensities to show from black to full colour: from the 1st to the 99.8th percentile, so
/// that a few saturated specular returns do not darken the whole frame.
DisplayWindow displayRange(const cv::Mat& image);

/// `image`: CV_32F polar image. Values <= low map to the first colour, >= high to the last.
QImage polarImageToQImage(const cv::Mat& image, float low, float high,
                          ColourMap map = ColourMap::Copper);

}  // namespace sonarcarve::widgets
