// Class "vendor logs": Oculus message streams with a corrupt size field, garbage, a cut-off
// end or nothing in them. The reader resynchronises on the next valid message, keeps every
// intact ping and says how many bytes and messages it skipped (issue 17, item 4).
#include "e2e/catalogue/catalogue.h"

namespace sonarcarve::test {
namespace {

constexpr std::size_t kPingBytes = 182016;  // tests/data/oculus/one_ping_8bit.raw
constexpr std::size_t kPayloadSizeField = 10;

std::string fixture() {
  return readText(testData("oculus/one_ping_8bit.raw"));
}

// Twelve copies of the real ping, bit 20 of the third one's payloadSize flipped: its size then
// runs 1 MiB on, over the next five pings (which used to be dropped without a word).
std::string flippedLog() {
  std::string log;
  for (int k = 0; k < 12; ++k) {
    log += fixture();
  }
  log[2 * kPingBytes + kPayloadSizeField + 2] ^= 0x10;
  return log;
}

const std::string kFlippedProblem = "log.raw: byte " + std::to_string(2 * kPingBytes + 10) +
                                    ": payloadSize 1230576 is corrupt: it runs over the next "
                                    "valid message, at byte " +
                                    std::to_string(3 * kPingBytes);
const std::string kFlippedSkip =
    "skipped " + std::to_string(kPingBytes) + " corrupt bytes (1 messages), resynchronised 1 times";

CatalogueCase logCase(const std::string& name, std::function<std::string()> bytes,
                      const std::string& args, Outcome outcome,
                      const std::vector<std::string>& message,
                      const std::vector<std::string>& absent = {}) {
  return {.name = name,
          .prepare =
              [bytes, args](const Workspace& ws) {
                writeBytes(ws / "log.raw", bytes());
                return args;
              },
          .outcome = outcome,
          .message = message,
          .absent = absent};
}

}  // namespace

std::vector<CatalogueCase> oculusCases() {
  return {
      logCase("FlippedSizeBitInfoText", flippedLog, "info log.raw", Outcome::Succeeds,
              {"log.raw (oculus messages, 11 pings)", kFlippedProblem,
               "Skipped      182016 bytes, 1 messages, 1 resyncs"}),
      logCase("FlippedSizeBitInfoJson", flippedLog, "info --json log.raw", Outcome::Succeeds,
              {"\"pings\": 11", "\"bytes\": 182016", "\"resyncs\": 1", kFlippedProblem}),
      logCase("FlippedSizeBitImport", flippedLog, "import --format oculus log.raw --out imported",
              Outcome::Succeeds,
              {"imported 11 frames of 11 pings", "warning: log.raw: " + kFlippedSkip,
               "problem: " + kFlippedProblem}),
      logCase("FlippedSizeBitReconstruct", flippedLog, "reconstruct log.raw --out out",
              Outcome::Succeeds, {"warning: log.raw: " + kFlippedSkip}),
      logCase("LogCutInsideTheThirdPing",
              [] {
                const std::string one = fixture();
                return one + one + one.substr(0, 5000);
              },
              "info log.raw", Outcome::Succeeds,
              {"(oculus messages, 2 pings)",
               "log.raw: byte " + std::to_string(2 * kPingBytes + 10) + ": truncated message",
               "the last message is cut off: skipped 5000 bytes (1 message) up to the end"}),
      logCase("GarbageBetweenPings",
              [] { return fixture() + std::string(777, '\xab') + fixture(); }, "info log.raw",
              Outcome::Succeeds,
              {"(oculus messages, 2 pings)",
               "log.raw: byte 182016: 777 bytes that are not an Oculus message",
               "resynchronised on the next valid message at byte 182793"}),
      logCase("EmptyLog", [] { return std::string(); },
              "import --format oculus log.raw --out imported", Outcome::Fails,
              {"log.raw: byte 0: empty file: expected Oculus messages"}, {"imported"}),
      logCase("LogOfAHeaderOnly", [] { return fixture().substr(0, 16); },
              "import --format oculus log.raw --out imported", Outcome::Fails,
              {"log.raw: byte 10: truncated message: payloadSize 182000 runs past the end",
               "no usable ping in the file"},
              {"imported"}),
      logCase("LogOfGarbageAfterAnOculusId",
              [] { return std::string("\x53\x4f", 2) + std::string(4000, '\x01'); },
              "import --format oculus log.raw --out imported", Outcome::Fails,
              {"log.raw: byte 10: truncated message: payloadSize 16843009 runs past the end of the "
               "data (3986 bytes after the header)",
               "no usable ping in the file"},
              {"imported"}),
      logCase("LogWhoseOnlyPingHasACorruptSize",
              [] {
                std::string one = fixture();
                one[kPayloadSizeField + 3] ^= 0x01;
                return one;
              },
              "reconstruct log.raw --out out", Outcome::Fails,
              {"log.raw: byte 10: truncated message: payloadSize", "no usable ping in the file"},
              {"out/report.json"}),
  };
}

}  // namespace sonarcarve::test
