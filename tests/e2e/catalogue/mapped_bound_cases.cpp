// Class "files mapped or read by their declared sizes" (issue 44): Oculus logs and MCAP bags
// are mapped, not read whole, and a reference STL is read by VTK. Each is bounded by what it
// declares and by its size: a payload, a record or a triangle count that needs more than the
// file holds is refused before anything is allocated, and a sparse file of 20 GiB (made with
// truncate, its holes reading as zeros) ends in a second: its holes are jumped over (Oculus),
// a record of zeros stops the reading (MCAP), a mesh is refused by the memory it would need.
#include <cstring>

#include "e2e/catalogue/catalogue.h"
#include "io/mission/mission.h"
#include "io/rosbag/bag_writer.h"

namespace sonarcarve::test {
namespace {

constexpr std::uint64_t k20GiB = std::uint64_t{20} << 30;
constexpr std::size_t kPingBytes = 182016;  // tests/data/oculus/one_ping_8bit.raw

void extendSparsely(const std::filesystem::path& path, std::uint64_t bytes) {
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(bytes)), 0) << path;
}

template <typename T>
void setAt(std::string& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

CatalogueCase oculusLog(const std::string& name, std::function<void(const Workspace&)> make,
                        Outcome outcome, const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [make](const Workspace& ws) {
                make(ws);
                return std::string("info log.raw");
              },
          .outcome = outcome,
          .message = message};
}

// The example mission as an MCAP bag of uncompressed records (in chunks, or in the data
// section), changed by `change`.
CatalogueCase mcapBag(const std::string& name, BagFormat format,
                      std::function<void(const Workspace&, const std::filesystem::path&)> change,
                      Outcome outcome, const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [format, change](const Workspace& ws) {
                BagWriteOptions options;
                options.format = format;
                writeRosBag(readMission(ws.mission()), ws / "bag.mcap", options);
                change(ws, ws / "bag.mcap");
                return std::string("info bag.mcap");
              },
          .outcome = outcome,
          .message = message};
}

// A binary STL of one triangle whose header declares `declared`, extended to `bytes`.
CatalogueCase stlReference(const std::string& name, std::uint32_t declared, std::uint64_t bytes,
                           const std::vector<std::string>& message) {
  return {
      .name = name,
      .prepare =
          [declared, bytes](const Workspace& ws) {
            std::string stl(84 + 50, '\0');
            setAt(stl, 80, declared);
            const float triangle[12] = {0, 0, 1, 2, 0, 10, 2.1F, 0, 10, 2, 0.1F, 10};
            std::memcpy(stl.data() + 84, triangle, sizeof triangle);
            writeBytes(ws / "reference.stl", stl);
            if (bytes > stl.size()) {
              extendSparsely(ws / "reference.stl", bytes);
            }
            writeBytes(ws / "points.ply", asciiPly({{2, 0, 10}}));
            return std::string("evaluate --reference reference.stl --reconstruction points.ply");
          },
      .message = message};
}

}  // namespace

std::vector<CatalogueCase> mappedBoundCases() {
  const auto ping = [](const Workspace& ws) {
    std::filesystem::copy_file(testData("oculus/one_ping_8bit.raw"), ws / "log.raw");
  };
  // The ping's payloadSize set to 4 GiB.
  const auto declaringTooMuch = [](const Workspace& ws) {
    std::string bytes = readText(testData("oculus/one_ping_8bit.raw"));
    setAt(bytes, 10, std::uint32_t{0xFFFFFFF0});
    writeBytes(ws / "log.raw", bytes);
  };
  return {
      oculusLog("OculusPingThenA20GiBHole",
                [ping](const Workspace& ws) {
                  ping(ws);
                  extendSparsely(ws / "log.raw", k20GiB);
                },
                Outcome::Succeeds,
                {"log.raw: byte 182016: " + std::to_string(k20GiB - kPingBytes) +
                     " bytes that are not an Oculus message",
                 "1 pings"}),
      oculusLog("OculusPingDeclaringMoreThanTheFile", declaringTooMuch, Outcome::Fails,
                {"log.raw: byte 10: truncated message: payloadSize 4294967280 runs past the end "
                 "of the data (182000 bytes after the header)"}),
      oculusLog("OculusPingDeclaringMoreThanTheFileBeforeAHole",
                [declaringTooMuch](const Workspace& ws) {
                  declaringTooMuch(ws);
                  extendSparsely(ws / "log.raw", k20GiB);
                },
                // Within the file now: the ping is read, the rest of its 4 GiB and the hole
                // after it are skipped and reported.
                Outcome::Succeeds, {"1 pings", "Skipped      17179869184 bytes"}),
      mcapBag(
          "McapThenA20GiBHole", BagFormat::McapNone,
          [](const Workspace&, const std::filesystem::path& bag) { extendSparsely(bag, k20GiB); },
          Outcome::Succeeds, {"/sonar/image"}),
      mcapBag("McapCutThenA20GiBHole", BagFormat::McapUnchunked,
              [](const Workspace&, const std::filesystem::path& bag) {
                extendSparsely(bag, std::filesystem::file_size(bag) * 2 / 3);
                extendSparsely(bag, k20GiB);
              },
              Outcome::Succeeds,
              {"bag.mcap: byte ",
               "opcode 0x00 is no MCAP record (zeros: a hole or corrupt "
               "data); reading stopped"}),
      mcapBag("McapRecordDeclaringMoreThanTheFile", BagFormat::McapNone,
              [](const Workspace&, const std::filesystem::path& bag) {
                std::string bytes = readText(bag);
                setAt(bytes, 9, std::uint64_t{1} << 60);
                writeBytes(bag, bytes);
              },
              Outcome::Fails,
              {"bag.mcap: byte 8: record 0x01 claims 1152921504606846976 bytes, only",
               "left: cut short or corrupt; reading stopped"}),
      stlReference("StlDeclaringMoreTrianglesThanTheFile", 0x80000000U, 0,
                   {"reference.stl: byte 134: truncated binary STL: the header declares "
                    "2147483648 triangles (84 + 50 x 2147483648 = 107374182484 bytes), the file "
                    "has 134"}),
      // Small enough to be read: VTK read what the file's size holds, whatever its count said.
      stlReference("StlDeclaringOneTriangleBeforeA64MiBHole", 1, std::uint64_t{64} << 20,
                   {"reference.stl: byte 134: binary STL longer than its header says: the header "
                    "declares 1 triangles (84 + 50 x 1 = 134 bytes), the file has 67108864, room "
                    "for 1342175 triangles: expected the count of the triangles it holds"}),
      stlReference("StlOf20GiBDeclaringOneTriangle", 1, k20GiB,
                   {"reference.stl: ", "needs up to 163840 MiB to read, more than the"}),
      stlReference("StlOf20GiBDeclaringItsTriangles",
                   static_cast<std::uint32_t>((k20GiB - 84) / 50), 84 + (k20GiB - 84) / 50 * 50,
                   {"reference.stl: ", "MiB to read, more than the"}),
  };
}

}  // namespace sonarcarve::test
