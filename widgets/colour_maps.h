// Colour tables of 256 RGB entries for sonar images and 3D points. Pure functions; the
// tables are built once and safe to read from any thread.
#pragma once

#include <array>

namespace sonarcarve::widgets {

using Rgb = std::array<unsigned char, 3>;
using ColourTable = std::array<Rgb, 256>;

enum class ColourMap { Grey, Copper };

/// Black -> orange -> pale: the classic look of sonar displays.
const ColourTable& copperColours();
const ColourTable& greyColours();
/// Perceptually uniform, for intensities and depths of 3D points (OpenCV's viridis).
const ColourTable& viridisColours();
/// Green (on the ground truth) -> yellow -> red (10 cm off and more).
const ColourTable& errorColours();
const ColourTable& coloursOf(ColourMap map);

}  // namespace sonarcarve::widgets
