// Resynchronisation of Oculus message streams (issue 17, item 4): the real ping of
// tests/data/oculus repeated with distinct ping ids, one size field corrupted by a flipped bit;
// every other ping must be read back and the skip reported in bytes and messages.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "common/error.h"
#include "io/oculus/oculus_log.h"
#include "io/oculus/oculus_message.h"
#include "support/oculus_encoder.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

constexpr std::size_t kPingIdField = 53;       // version 0/1 layout
constexpr std::size_t kPayloadSizeField = 10;  // in the message header
constexpr std::uint32_t kFirstPingId = 1000;

// Writes `value` little-endian at `at` (as the Oculus messages hold their fields).
void putLittleEndian(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t value) {
  for (std::size_t i = 0; i < 4; ++i) {
    bytes.at(at + i) = static_cast<std::uint8_t>(value >> (8 * i));
  }
}

// `copies` of the real ping back to back, the k-th with ping id kFirstPingId + k.
std::vector<std::uint8_t> repeatedFixture(std::size_t copies) {
  const auto one = test::readBytes(test::oculusFixture().string());
  std::vector<std::uint8_t> all;
  for (std::size_t k = 0; k < copies; ++k) {
    std::vector<std::uint8_t> copy = one;
    const std::uint32_t id = kFirstPingId + static_cast<std::uint32_t>(k);
    putLittleEndian(copy, kPingIdField, id);
    all.insert(all.end(), copy.begin(), copy.end());
  }
  return all;
}

std::size_t messageSize() {
  return test::readBytes(test::oculusFixture().string()).size();
}

std::vector<std::uint32_t> pingIds(const OculusLog& log) {
  std::vector<std::uint32_t> ids;
  for (const OculusLogEntry& e : log.pings()) {
    ids.push_back(e.ping.ping_id);
  }
  return ids;
}

std::vector<std::uint32_t> idsWithout(std::size_t copies, std::size_t missing) {
  std::vector<std::uint32_t> ids;
  for (std::size_t k = 0; k < copies; ++k) {
    if (k != missing) {
      ids.push_back(kFirstPingId + static_cast<std::uint32_t>(k));
    }
  }
  return ids;
}

TEST(OculusResync, AnIntactStreamSkipsNothing) {
  const OculusLog log = OculusLog::fromBytes(repeatedFixture(4), "intact.raw");
  EXPECT_EQ(pingIds(log), idsWithout(4, 99));
  EXPECT_TRUE(log.problems().empty());
  EXPECT_EQ(log.skipped().bytes, 0u);
  EXPECT_EQ(log.skipped().messages, 0u);
  EXPECT_EQ(log.skipped().resyncs, 0u);
  EXPECT_EQ(log.skippedSummary(), "");
}

// Every one of the 32 bits of payloadSize, in a message at the start, in the middle and last.
TEST(OculusResync, AFlippedBitInAnySizeFieldLosesOnlyThatMessage) {
  constexpr std::size_t kCopies = 8;
  const std::size_t size = messageSize();
  const auto intact = repeatedFixture(kCopies);
  for (std::size_t corrupt : {0ul, 3ul, kCopies - 1}) {
    for (int bit = 0; bit < 32; ++bit) {
      SCOPED_TRACE("message " + std::to_string(corrupt) + ", bit " + std::to_string(bit));
      auto bytes = intact;
      bytes[corrupt * size + kPayloadSizeField + bit / 8] ^=
          static_cast<std::uint8_t>(1u << (bit % 8));
      const OculusLog log = OculusLog::fromBytes(bytes, "flipped.raw");
      EXPECT_EQ(pingIds(log), idsWithout(kCopies, corrupt));
      EXPECT_EQ(log.skipped().bytes, size);
      EXPECT_EQ(log.skipped().messages, 1u);
      EXPECT_EQ(log.skipped().resyncs, corrupt + 1 < kCopies ? 1u : 0u);
      ASSERT_EQ(log.problems().size(), 1u);
      // The size field, or the image that no longer fits a smaller size.
      const std::string size_field = "flipped.raw: byte " + std::to_string(corrupt * size + 10);
      const std::string image_field = "flipped.raw: byte " + std::to_string(corrupt * size + 110);
      EXPECT_TRUE(log.problems()[0].rfind(size_field, 0) == 0 ||
                  log.problems()[0].rfind(image_field, 0) == 0)
          << log.problems()[0];
      if (corrupt + 1 < kCopies) {
        EXPECT_NE(log.problems()[0].find("skipped " + std::to_string(size) +
                                         " bytes (1 message), resynchronised on the next valid "
                                         "message at byte " +
                                         std::to_string((corrupt + 1) * size)),
                  std::string::npos)
            << log.problems()[0];
      }
    }
  }
}

TEST(OculusResync, ASizeThatRunsOverLaterMessagesIsNamed) {
  const std::size_t size = messageSize();
  auto bytes = repeatedFixture(8);
  bytes[size + kPayloadSizeField + 2] ^= 0x10;  // + 1 MiB: used to jump over six pings
  const OculusLog log = OculusLog::fromBytes(bytes, "jump.raw");
  EXPECT_EQ(pingIds(log), idsWithout(8, 1));
  ASSERT_EQ(log.problems().size(), 1u);
  EXPECT_NE(log.problems()[0].find("jump.raw: byte " + std::to_string(size + kPayloadSizeField) +
                                   ": payloadSize " + std::to_string(182000 + (1 << 20)) +
                                   " is corrupt: it runs over the next valid message, at byte " +
                                   std::to_string(2 * size)),
            std::string::npos)
      << log.problems()[0];
  EXPECT_EQ(log.skippedSummary(),
            "jump.raw: skipped " + std::to_string(size) +
                " corrupt bytes (1 messages), resynchronised 1 times on the next valid message");
}

TEST(OculusResync, GarbageWithAFalseOculusIdIsSkippedToTheRealMessage) {
  const std::size_t size = messageSize();
  const auto good = repeatedFixture(2);
  // Garbage that starts like a header (0x4f53, msgId 0x5a5a, a payload of 100 bytes that fits)
  // but leads nowhere.
  std::vector<std::uint8_t> garbage(300, 0x5a);
  garbage[0] = 0x53;
  garbage[1] = 0x4f;
  const std::uint32_t payload = 100;
  putLittleEndian(garbage, kPayloadSizeField, payload);
  std::vector<std::uint8_t> bytes(good.begin(), good.begin() + static_cast<long>(size));
  bytes.insert(bytes.end(), garbage.begin(), garbage.end());
  bytes.insert(bytes.end(), good.begin() + static_cast<long>(size), good.end());
  const OculusLog log = OculusLog::fromBytes(bytes, "false_id.raw");
  EXPECT_EQ(pingIds(log), idsWithout(2, 99));
  // The false header's 116 bytes hold no confirmed message: it is kept as an unknown message
  // (a note), and the 184 bytes after it are skipped to the real ping.
  EXPECT_EQ(log.skipped().bytes, garbage.size() - 116);
  EXPECT_EQ(log.skipped().messages, 0u);
  EXPECT_EQ(log.skipped().resyncs, 1u);
  ASSERT_EQ(log.notes().size(), 1u);
  EXPECT_NE(log.notes()[0].find("1 x message id 23130 (unknown) skipped"), std::string::npos)
      << log.notes()[0];
}

TEST(OculusResync, ALogCutInsideTheSecondMessageKeepsTheFirst) {
  const std::size_t size = messageSize();
  auto bytes = repeatedFixture(3);
  for (std::size_t cut : {size + 1, size + 15, size + 16, size + 5000, 2 * size - 1}) {
    SCOPED_TRACE("cut at " + std::to_string(cut));
    const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + static_cast<long>(cut));
    const OculusLog log = OculusLog::fromBytes(part, "cut.raw");
    EXPECT_EQ(pingIds(log), idsWithout(1, 99));
    EXPECT_EQ(log.skipped().bytes, cut - size);
    EXPECT_EQ(log.skipped().resyncs, 0u);
    ASSERT_EQ(log.problems().size(), 1u);
    const std::string expected =
        cut == size + 1
            ? "cut.raw: byte " + std::to_string(size) + ": 1 bytes that are not an Oculus message"
            : "the last message is cut off: skipped " + std::to_string(cut - size) + " bytes";
    EXPECT_NE(log.problems()[0].find(expected), std::string::npos) << log.problems()[0];
  }
}

TEST(OculusResync, ALogWhoseOnlyMessageIsCorruptNamesTheByte) {
  auto bytes = repeatedFixture(1);
  bytes[kPayloadSizeField + 3] ^= 0x80;
  test::expectError([&] { OculusLog::fromBytes(bytes, "alone.raw"); },
                    {"alone.raw: byte 10", "payloadSize", "no usable ping in the file"});
  test::expectError([] { OculusLog::fromBytes({}, "empty.raw"); },
                    {"empty.raw: byte 0: empty file"});
}

}  // namespace
}  // namespace sonarcarve
