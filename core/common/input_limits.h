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
/// Uncompressed bytes of one chunk of an MCAP bag: recorders write chunks of 1 to 8 MB (a
/// message larger than that gets a chunk of its own, and a sonar frame is below 64 MB).
inline constexpr std::uint64_t kMaxBagChunkBytes = std::uint64_t{256} << 20;
/// Bytes of the files that are read whole into memory, checked on the file's size before a byte
/// is read (a sparse file of 20 GB is refused at once, not read): a text table such as nav.csv
/// or frames.csv, 2 GiB (a day of navigation at 100 Hz takes 0.5 GB); a YAML file (mission,
/// parameters, a bag's metadata), 16 MiB (real ones are below 100 KiB, an explicit bearing
/// table included); a mesh read as text (OBJ), 4 GiB; a map file, 16 GiB (4 billion voxels as
/// 4-byte values); a noise model (YAML text of two numbers a pixel of the largest frame), 1 GiB;
/// a run's own JSON records (manifest), 64 MiB; a simulator's elevation beam table, 16 MiB
/// (a row a millidegree over +-90 degrees takes 4 MB).
inline constexpr std::uint64_t kMaxTableFileBytes = std::uint64_t{2} << 30;
inline constexpr std::uint64_t kMaxYamlFileBytes = std::uint64_t{16} << 20;
inline constexpr std::uint64_t kMaxMeshFileBytes = std::uint64_t{4} << 30;
inline constexpr std::uint64_t kMaxMapFileBytes = std::uint64_t{16} << 30;
inline constexpr std::uint64_t kMaxNoiseModelFileBytes = std::uint64_t{1} << 30;
inline constexpr std::uint64_t kMaxRecordFileBytes = std::uint64_t{64} << 20;
inline constexpr std::uint64_t kMaxBeamTableFileBytes = std::uint64_t{16} << 20;
/// Bytes of a PNG frame of rows x cols 16-bit pixels: a PNG that does not compress at all holds
/// its pixels, a filter byte a row and a few bytes a chunk; twice its pixel bytes plus 1 MiB is
/// far above any frame a PNG encoder writes.
constexpr std::uint64_t maxFramePngBytes(std::int64_t rows, std::int64_t cols) {
  return 2 * (std::uint64_t(rows) * std::uint64_t(cols) * 2 + std::uint64_t(rows)) +
         (std::uint64_t{1} << 20);
}
/// Voxels in the box a map covers (its bounds over the voxel size cubed): the riser demo at
/// the default voxel size needs about 3 % of this.
inline constexpr double kMaxMapVoxels = 4.0e9;

/// The simulator's own sizes (`simulate`): the distance between frames, 1 mm to 100 m (a step
/// of 0 never ended, and 1 mm already gives 1000 frames a metre of track); the frames of one
/// run (100,000: a day of pings at one a second takes 86,400); the rays across each beam (32:
/// the image is averaged over them, 2 is the default); and the rays of one frame, beams x rays
/// per beam x elevation steps (2^24: one frame then takes seconds, not hours).
inline constexpr double kMinSimStep_m = 0.001;
inline constexpr double kMaxSimStep_m = 100.0;
inline constexpr int kMaxSimFrames = 100000;
inline constexpr int kMaxRaysPerBeam = 32;
inline constexpr double kMaxSimRaysPerFrame = 16777216.0;

}  // namespace sonarcarve
