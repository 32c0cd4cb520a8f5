#include "pipeline/heading_sectors.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/angles.h"

namespace sonarcarve {

std::optional<double> lookHeadingDeg(const PosedFrame& frame) {
  const Eigen::Vector3d axis = frame.T_world_sonar.linear().col(0);
  if (std::hypot(axis.x(), axis.y()) < std::sin(degToRad(10.0))) {
    return std::nullopt;
  }
  const double heading = radToDeg(std::atan2(axis.y(), axis.x()));
  return heading < 0.0 ? heading + 360.0 : heading;
}

std::vector<std::vector<PosedFrame>> headingSectors(const std::vector<PosedFrame>& frames,
                                                    double width_deg, std::size_t min_frames) {
  std::vector<std::pair<double, std::size_t>> headings;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (const std::optional<double> heading = lookHeadingDeg(frames[i])) {
      headings.emplace_back(*heading, i);
    }
  }
  std::vector<std::vector<PosedFrame>> sectors;
  if (headings.empty()) {
    return sectors;
  }
  std::sort(headings.begin(), headings.end());
  // Start after the widest gap, so that a sector never straddles it.
  std::size_t start = 0;
  double widest = headings.front().first + 360.0 - headings.back().first;
  for (std::size_t i = 1; i < headings.size(); ++i) {
    if (headings[i].first - headings[i - 1].first > widest) {
      widest = headings[i].first - headings[i - 1].first;
      start = i;
    }
  }
  std::rotate(headings.begin(), headings.begin() + static_cast<std::ptrdiff_t>(start),
              headings.end());
  const double first = headings.front().first;
  const auto unwrapped = [first](double heading) {
    return heading < first ? heading + 360.0 : heading;
  };
  std::vector<std::size_t> members;
  double sector_start = first;
  const auto close = [&] {
    if (members.size() >= min_frames) {
      std::sort(members.begin(), members.end());  // the mission's order
      std::vector<PosedFrame>& sector = sectors.emplace_back();
      for (const std::size_t i : members) {
        sector.push_back(frames[i]);
      }
    }
    members.clear();
  };
  for (const auto& [heading, index] : headings) {
    const double h = unwrapped(heading);
    if (h >= sector_start + width_deg) {
      close();
      sector_start = h;
    }
    members.push_back(index);
  }
  close();
  return sectors;
}

std::vector<std::vector<PosedFrame>> sectorsToCarve(const std::vector<PosedFrame>& frames,
                                                    double max_range_m) {
  Eigen::AlignedBox2d track;
  for (const PosedFrame& frame : frames) {
    track.extend(frame.T_world_sonar.translation().head<2>());
  }
  if (frames.empty() || track.diagonal().norm() > kSectorTrackRanges * max_range_m) {
    return {};
  }
  std::vector<std::vector<PosedFrame>> sectors = headingSectors(frames);
  return sectors.size() >= 2 ? sectors : std::vector<std::vector<PosedFrame>>{};
}

}  // namespace sonarcarve
