// A minimal MCAP writer (profile ros2): schemas and channels in the data section, messages in
// chunks (uncompressed, lz4 or zstd, with their CRC) or directly in the data section, then
// Data End and a Footer without a summary. The whole file is built in memory.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sonarcarve {

enum class McapChunks { None, Uncompressed, Lz4, Zstd };

class McapWriter {
 public:
  McapWriter(McapChunks chunks, std::size_t chunk_bytes);
  void addSchema(std::uint16_t id, const std::string& name, const std::string& definition);
  void addChannel(std::uint16_t id, std::uint16_t schema, const std::string& topic);
  void addMessage(std::uint16_t channel, std::uint64_t log_time_ns, std::uint64_t publish_time_ns,
                  std::span<const std::uint8_t> data);
  /// The file's bytes (ends the data section).
  std::vector<std::uint8_t> finish();

 private:
  void flushChunk();
  McapChunks chunks_;
  std::size_t chunk_bytes_;
  std::vector<std::uint8_t> file_;
  std::vector<std::uint8_t> chunk_;
  std::uint64_t chunk_start_ns_ = 0;
  std::uint64_t chunk_end_ns_ = 0;
  std::uint32_t sequence_ = 0;
};

}  // namespace sonarcarve
