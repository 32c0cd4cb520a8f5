// MCAP (mcap.dev, format version 0): the constants shared by our reader (mcap_bag.cpp) and
// writer (bag_writer.cpp). A file is the magic, records of `opcode:u8, length:u64, content`,
// and the magic again; all integers little-endian; strings and byte arrays are prefixed by a
// u32 length, chunk records by a u64 length.
#pragma once

#include <array>
#include <cstdint>

namespace sonarcarve::mcap {

inline constexpr std::array<std::uint8_t, 8> kMagic = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
inline constexpr std::size_t kRecordHeaderSize = 9;  ///< opcode + u64 length

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kAttachment = 0x09,
  kAttachmentIndex = 0x0A,
  kStatistics = 0x0B,
  kMetadata = 0x0C,
  kMetadataIndex = 0x0D,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

}  // namespace sonarcarve::mcap
