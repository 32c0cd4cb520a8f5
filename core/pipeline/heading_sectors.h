// Heading sectors: the views of a mission grouped by where the sonar looks on the compass, so
// that each group can be carved as a pass of its own (pipeline/sector_restore.h). A face seen
// head-on from one heading returns at grazing incidence to another, spread over many range
// bins and under the keep level: a map carved from every heading at once keeps a third of the
// visible surface of a structure seen from four sides (docs/validation.md), each heading's own
// map keeps most of what it sees.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "pipeline/frame_stage.h"

namespace sonarcarve {

/// Width of a sector of headings, degrees: a face seen head-on from a sector's middle is seen
/// at most 30 degrees off its normal from the sector's edges, where carving keeps it.
inline constexpr double kSectorWidth_deg = 60.0;
/// A track whose extent is within this many sonar ranges circles one structure (an orbit of
/// half the range's radius spans 1.41 ranges; a lawnmower of 20 m lines at 10 m range, 1.97).
inline constexpr double kSectorTrackRanges = 1.5;
/// A sector needs this many frames to be carved as a pass of its own (fewer leave ghosts).
inline constexpr std::size_t kSectorMinFrames = 24;

/// The compass heading of a frame's look direction (the sonar's axis on the horizontal plane),
/// degrees in [0, 360); none for a frame looking within 10 degrees of straight up or down.
std::optional<double> lookHeadingDeg(const PosedFrame& frame);

/// The frames grouped by heading (the sonar's axis on the horizontal plane): sectors of at
/// most `width_deg`, the first starting after the widest gap between headings, each next one
/// at the first heading past the one before. Frames looking within 10 degrees of straight up or
/// down, and sectors of fewer than `min_frames` frames, are left out. One sector (or none) when
/// the mission looks one way.
std::vector<std::vector<PosedFrame>> headingSectors(const std::vector<PosedFrame>& frames,
                                                    double width_deg = kSectorWidth_deg,
                                                    std::size_t min_frames = kSectorMinFrames);

/// The sectors a run carves alone (none when it does not): at least two, over a track whose
/// horizontal extent (its box's diagonal) stays within kSectorTrackRanges times the sonar's
/// range `max_range_m`: an inspection around a structure. A survey's lines, whose map is let go
/// as the track leaves it, are left as they are (not measured with sectors).
std::vector<std::vector<PosedFrame>> sectorsToCarve(const std::vector<PosedFrame>& frames,
                                                    double max_range_m);

}  // namespace sonarcarve
