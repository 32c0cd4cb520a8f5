// The mission origin: survey navigation comes in world coordinates far from zero (UTM: north
// about 5,000,000 m, east 500,000 m), where float32 keeps only half a metre and OctoMap's keys
// (+-2^15 voxels: +-655 m at 2 cm) wrap. A mission whose navigation lies farther than
// kNearZeroLimit_m from zero is moved, in double, to an origin near its track (the centre of its
// positions rounded to whole kOriginStep_m), so that the map is carved near zero; its outputs
// are local to that origin and carry it (docs/conventions.md, "Mission origin").
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sonar/mounting.h"
#include "sonar/nav_track.h"

namespace sonarcarve {

/// Navigation within this distance of zero on every axis keeps origin 0 (and the outputs it
/// always had). 100 m: float32 resolves 8 micrometres there, and OctoMap's keys reach the whole
/// sonar range around it down to 3 mm voxels.
inline constexpr double kNearZeroLimit_m = 100.0;
/// An origin is a whole multiple of this (easy to read and to add back by hand).
inline constexpr double kOriginStep_m = 100.0;
/// No survey position lies this far from zero (the Earth's circumference is 4e7 m): a
/// navigation coordinate beyond it is an error in the file, not a place.
inline constexpr double kMaxNavCoordinate_m = 1e8;

/// The origin for `nav`: zero when every position is within kNearZeroLimit_m of zero on every
/// axis, otherwise the centre of the positions' box rounded to whole kOriginStep_m.
Eigen::Vector3d chooseMissionOrigin(const NavTrack& nav);

/// The track with `offset_m` added to every position (in double; attitudes and times kept);
/// the track itself, unchanged to the bit, for a zero offset.
NavTrack translatedTrack(const NavTrack& nav, const Eigen::Vector3d& offset_m);

/// Throws Error naming `file` and `place` if a coordinate of `position_m` is NaN, infinite or
/// beyond kMaxNavCoordinate_m.
void requirePlausiblePosition(const Eigen::Vector3d& position_m, const std::string& file,
                              const std::string& place);

/// What is wrong with a mounting `translation_m` (NaN, or beyond kMaxMountingOffset_m), in words
/// ending with what was expected; nothing when it is plausible.
std::optional<std::string> mountingOffsetProblem(const Eigen::Vector3d& translation_m);

/// "5000000 500000 0": a point (north, east, down) as text, each coordinate the shortest fixed
/// notation that reads back exactly (origins in comments, boxes in messages).
std::string nedText(const Eigen::Vector3d& p_ned_m);

/// The first word of the comment that carries an origin in an output's header (PLY, OBJ, .bt).
inline constexpr const char* kOriginCommentKeyword = "origin_ned_m";
/// "origin_ned_m N E D (local coordinates: world NED = local + origin)".
std::string originComment(const Eigen::Vector3d& origin_ned_m);

}  // namespace sonarcarve
