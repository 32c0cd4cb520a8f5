// Limits on sizes that come from input files, checked before anything is allocated from them,
// so that a corrupt or hostile file gives an error instead of a run that eats the machine.
// Each is far above any real sonar or mission; docs/reliability.md gives the reasons.
#pragma once

#include <cstdint>

namespace sonarcarve {

/// Beams of a sonar: the widest imaging sonars have 512 to 1024.
inline constexpr int kMaxBeams = 4096;
/// Range bins of a sonar: real ones have 500 to 4000.
inline constexpr int kMaxRangeBins = 16384;
/// Pixels of one frame (beams x range bins), 64 MB as floats; real frames are below 4 M.
inline constexpr std::int64_t kMaxFramePixels = std::int64_t{1} << 24;
/// Voxels in the box a map covers (its bounds over the voxel size cubed): the riser demo at
/// the default voxel size needs about 3 % of this.
inline constexpr double kMaxMapVoxels = 4.0e9;

}  // namespace sonarcarve
