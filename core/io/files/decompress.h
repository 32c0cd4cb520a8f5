// Decompressing one lz4 frame or one zstd frame (MCAP chunks, rosbag2's compressed messages),
// growing the output only as far as the data really expands, up to a size the caller expects:
// a corrupt size field cannot make us allocate what is not there. Errors name the source and
// the place.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sonarcarve {

/// At most `max_size` bytes; throws Error if the frame is corrupt, cut short or larger.
std::vector<std::uint8_t> decompressLz4Frame(std::span<const std::uint8_t> in,
                                             std::uint64_t max_size, const std::string& source,
                                             const std::string& place);
std::vector<std::uint8_t> decompressZstdFrame(std::span<const std::uint8_t> in,
                                              std::uint64_t max_size, const std::string& source,
                                              const std::string& place);
/// True if `bytes` start with the zstd frame magic (28 B5 2F FD).
bool isZstdFrame(std::span<const std::uint8_t> bytes);

}  // namespace sonarcarve
