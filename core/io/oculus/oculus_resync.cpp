#include "io/oculus/oculus_resync.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "common/error.h"
#include "io/oculus/oculus_message.h"

namespace sonarcarve {
namespace {

template <typename T>
T readAt(std::span<const std::uint8_t> bytes, std::size_t offset) {
  T value{};
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

constexpr std::size_t kPayloadSizeField = 10;
constexpr std::size_t kMsgIdField = 6;
constexpr std::size_t kMsgVersionField = 8;

}  // namespace

bool oculusPingDecodesAt(std::span<const std::uint8_t> bytes, std::size_t offset) {
  try {
    decodeOculusPing(bytes, offset, std::string(), false);
    return true;
  } catch (const Error&) {
    return false;
  }
}

bool oculusHeaderFitsAt(std::span<const std::uint8_t> bytes, std::size_t offset) {
  if (offset > bytes.size() || bytes.size() - offset < kOculusHeaderSize ||
      readAt<std::uint16_t>(bytes, offset) != kOculusId) {
    return false;
  }
  const auto payload = readAt<std::uint32_t>(bytes, offset + kPayloadSizeField);
  return payload <= bytes.size() - offset - kOculusHeaderSize;
}

bool oculusSizeLeadsToAMessage(std::span<const std::uint8_t> bytes, std::size_t offset) {
  if (!oculusHeaderFitsAt(bytes, offset)) {
    return false;
  }
  const std::size_t next =
      offset + kOculusHeaderSize + readAt<std::uint32_t>(bytes, offset + kPayloadSizeField);
  return next == bytes.size() || oculusHeaderFitsAt(bytes, next);
}

std::size_t findNextOculusMessage(std::span<const std::uint8_t> bytes, std::size_t from,
                                  const MappedFile* file) {
  constexpr std::size_t kWindow = std::size_t{1} << 20;  // a hole is looked for once a MiB
  constexpr auto kIdFirstByte = static_cast<std::uint8_t>(kOculusId & 0xff);  // little-endian
  std::size_t window_end = from;
  for (std::size_t at = from; at + kOculusHeaderSize <= bytes.size(); ++at) {
    if (at >= window_end) {
      at = file ? file->dataAtOrAfter(at) : at;
      window_end = at + kWindow;
      if (at + kOculusHeaderSize > bytes.size()) {
        break;
      }
    }
    const std::size_t stop = std::min(window_end, bytes.size() - kOculusHeaderSize + 1);
    const void* found = std::memchr(bytes.data() + at, kIdFirstByte, stop - at);
    if (found == nullptr) {
      at = stop - 1;
      continue;
    }
    at = static_cast<std::size_t>(static_cast<const std::uint8_t*>(found) - bytes.data());
    if (!oculusHeaderFitsAt(bytes, at) || readAt<std::uint16_t>(bytes, at + kMsgVersionField) > 2) {
      continue;
    }
    if (oculusSizeLeadsToAMessage(bytes, at) ||
        (readAt<std::uint16_t>(bytes, at + kMsgIdField) == kOculusSimplePingResult &&
         oculusPingDecodesAt(bytes, at))) {
      return at;
    }
  }
  return kNoOculusMessage;
}

}  // namespace sonarcarve
