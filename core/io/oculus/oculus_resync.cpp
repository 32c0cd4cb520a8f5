#include "io/oculus/oculus_resync.h"

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

std::size_t findNextOculusMessage(std::span<const std::uint8_t> bytes, std::size_t from) {
  for (std::size_t at = from; at + kOculusHeaderSize <= bytes.size(); ++at) {
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
