// Class "work bounded by what a file declares" (issue 44): a file is checked by its size before
// it is read, and a PNG frame by its header before it is decoded; the decoder stops at the size
// the header declares. A frame that fails so is reported and skipped by `info`.
#include "e2e/catalogue/catalogue.h"
#include "support/png_bombs.h"

namespace sonarcarve::test {
namespace {

constexpr const char* kFrame = "frames/000003.png";

// A file of 20 GiB that takes no disk: reading it whole ended in std::bad_alloc (exit 70).
void makeSparse(const std::filesystem::path& path) {
  writeSparseFile(path, std::uint64_t{20} << 30);
}

// `info` on the mission with `file` made a sparse 20 GiB file: refused, naming it.
CatalogueCase sparseInput(const std::string& name, const std::string& file,
                          const std::string& message) {
  return {.name = name,
          .prepare =
              [file](const Workspace& ws) {
                makeSparse(ws.mission() / file);
                return std::string("info mission");
              },
          .message = {file + ": is 21474836480 bytes, more than the " + message}};
}

// The example mission's sonar has 200 range bins x 64 beams: a frame of 25,800 bytes inflated
// (a filter byte and 128 bytes a row), 1,100,176 bytes of file at most.
const std::string kInflatesPast = "goes on past the 25800 bytes of the 200 x 64 pixels";

CatalogueCase throughFrame(const std::string& name, std::function<void(const Workspace&)> make,
                           std::vector<std::string> message) {
  return {.name = name,
          .prepare =
              [make](const Workspace& ws) {
                make(ws);
                return std::string("frame mission --index 3 --polar polar.png");
              },
          .message = std::move(message),
          .absent = {"polar.png"}};
}

CatalogueCase throughInfo(const std::string& name, std::function<void(const Workspace&)> make,
                          std::vector<std::string> message) {
  message.push_back("Failed       1 frames");
  return {.name = name,
          .prepare =
              [make](const Workspace& ws) {
                make(ws);
                return std::string("info mission");
              },
          .outcome = Outcome::Succeeds,
          .message = std::move(message)};
}

}  // namespace

std::vector<CatalogueCase> boundCases() {
  // 1000 MiB of image data in 1.04 MB, under the frame's bound on its file.
  const auto bomb = [](const Workspace& ws) {
    writeBytes(ws.mission() / kFrame, inflationBombPng(200, 64, 1000));
  };
  // 12 GiB of image data in 12.7 MB: the adversarial run's frame, 60 s per read before.
  const auto big_bomb = [](const Workspace& ws) {
    writeBytes(ws.mission() / kFrame, inflationBombPng(200, 64, 12288));
  };
  const auto other_size = [](const Workspace& ws) {
    writeBytes(ws.mission() / kFrame, zeroPng(100, 64));
  };
  const auto sparse_frame = [](const Workspace& ws) { makeSparse(ws.mission() / kFrame); };
  const std::string frame_file = "000003.png: ";
  const std::string other = "image is 100 x 64 (rows x cols), expected 200 range bins x 64 beams";
  const std::string sparse =
      "is 21474836480 bytes, more than the 1100176 bytes a 16-bit PNG "
      "frame image may have";
  return {
      throughFrame("FramePngInflationBomb", bomb, {frame_file, kInflatesPast}),
      throughInfo("FramePngInflationBombIsSkippedByInfo", bomb, {frame_file, kInflatesPast}),
      throughFrame("FramePngOf12GiBInflated", big_bomb,
                   {frame_file + "is 12", "more than the 1100176 bytes"}),
      throughFrame("FramePngOfAnotherSize", other_size, {frame_file + "byte 16: " + other}),
      throughInfo("FramePngOfAnotherSizeIsSkippedByInfo", other_size, {other}),
      throughFrame("FrameSparse20GiB", sparse_frame, {frame_file + sparse}),
      throughInfo("FrameSparse20GiBIsSkippedByInfo", sparse_frame, {frame_file + sparse}),
      sparseInput("NavSparse20GiB", "nav.csv", "2147483648 bytes a CSV table may have"),
      sparseInput("FrameIndexSparse20GiB", "frames.csv", "2147483648 bytes a CSV table may have"),
      sparseInput("MissionYamlSparse20GiB", "mission.yaml", "16777216 bytes a YAML file may have"),
      {.name = "ReconstructMeshSmoothingHuge",
       .prepare =
           [](const Workspace&) {
             return std::string("reconstruct mission --mesh-smoothing 100000000 --out out");
           },
       .message = {"--mesh-smoothing: expected a whole number, from 0 to 1000, got 100000000"},
       .absent = {"out"}},
      {.name = "NoiseModelSmoothingHuge",
       .prepare =
           [](const Workspace&) {
             return std::string("noise-model mission --out model.yaml --smoothing 100001");
           },
       .message = {"--smoothing", "expected an odd whole number, from 1 to 255, got 100001"},
       .absent = {"model.yaml"}},
  };
}

}  // namespace sonarcarve::test
