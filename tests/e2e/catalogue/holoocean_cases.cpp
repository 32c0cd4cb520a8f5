// Class "HoloOcean / NeuSIS datasets" (docs/formats.md, "HoloOcean / NeuSIS datasets"): the
// example mission written in the NeuSIS layout by the test writer (support/pickle_writer.h),
// then one frame's pickle emptied, cut, turned into a pickle that would run code, a bomb of
// nesting or of memo references, or an array declaring more than it holds (each frame left out
// and reported by `info`, which exits 0, naming the file, the byte and the opcode); its
// Config.json missing a key, with a key of the wrong type, not JSON, or without an imaging
// sonar, and its Data folder without a .pkl file (each refused naming the file and the key).
#include "e2e/catalogue/catalogue.h"
#include "io/mission/mission.h"
#include "support/pickle_writer.h"

namespace sonarcarve::test {
namespace {

using namespace std::string_literals;

// The example mission as a NeuSIS dataset at neusis/ (protocol 4, as Python 3.8+ writes).
void writeDataset(const Workspace& ws) {
  writeNeusisDataset(readMission(ws.mission()), ws / "neusis", 4);
}

// Frame 1's pickle replaced by `bytes` (a function of its own bytes), then `info neusis`: the
// frame is reported and skipped, the other frames read.
CatalogueCase badFrame(const std::string& name,
                       const std::function<std::string(const std::string&)>& bytes,
                       const std::vector<std::string>& message) {
  std::vector<std::string> expected = {"neusis/Data/000001.pkl: "};
  expected.insert(expected.end(), message.begin(), message.end());
  expected.push_back("(frame skipped)");
  expected.push_back("HoloOcean / NeuSIS dataset: 9 of 10 frames");
  return {.name = name,
          .prepare =
              [bytes](const Workspace& ws) {
                writeDataset(ws);
                const auto file = ws / "neusis" / "Data" / "000001.pkl";
                writeBytes(file, bytes(readText(file)));
                return std::string("info neusis");
              },
          .outcome = Outcome::Succeeds,
          .message = expected};
}

// Config.json's text changed by replacing `from` with `to`, then `reconstruct neusis`.
CatalogueCase badConfig(const std::string& name, const std::string& from, const std::string& to,
                        const std::vector<std::string>& message) {
  return {.name = name,
          .prepare =
              [from, to](const Workspace& ws) {
                writeDataset(ws);
                replaceIn(ws / "neusis" / "Config.json", from, to);
                return std::string("reconstruct neusis --out out");
              },
          .message = message,
          .absent = {"out"}};
}

std::string proto2(const std::string& body) {
  return "\x80\x02"s + body;
}

}  // namespace

std::vector<CatalogueCase> holoOceanCases() {
  return {
      badFrame("EmptyPickle", [](const std::string&) { return std::string(); },
               {"empty file: expected a pickle (protocol 2 to 5)"}),
      badFrame("CutPickle",
               [](const std::string& whole) { return whole.substr(0, whole.size() / 2); },
               {"byte 2: opcode 0x95: a frame longer than the bytes left in the file"}),
      badFrame("PickleRunningCode",
               [](const std::string&) {
                 return proto2("cos\nsystem\nq\x00X\x02\x00\x00\x00idq\x01\x85R."s);
               },
               {"byte 2: opcode 0x63 'c': global 'os.system' is not one this reader allows",
                "nothing in a pickle is ever run"}),
      badFrame("PickleNestingBomb",
               [](const std::string&) { return proto2("]" + std::string(1000000, '\x85') + "."); },
               {"byte 66: opcode 0x85: containers nested deeper than 64 levels"}),
      badFrame("PickleMemoLoop", [](const std::string&) { return proto2("]q\x00h\x00\x61."s); },
               {"byte 7: opcode 0x61 'a': a list put inside itself (a reference loop through the "
                "memo)"}),
      badFrame(
          "PickleArrayDeclaringTooMuch",
          [](const std::string&) {
            PickleWriter w(4);
            w.op('}').memoize().text("ImagingSonar");
            w.reconstructedArray({4000000000, 4000000000}, "f4", "<", false, "1234");
            return w.op('s').finish();
          },
          {"byte ", "opcode 0x62 'b': numpy array of shape 4000000000 x 4000000000 of f4 needs",
           "but holds 4", "expected its shape to match its data"}),
      badConfig("ConfigMissingKey", "\"RangeMax\"", "\"RangeMaximum\"",
                {"neusis/Config.json: key agents[0].sensors[0].configuration.RangeMax: missing: "
                 "expected a range in metres"}),
      badConfig("ConfigKeyOfTheWrongType", "\"AzimuthBins\": 64", "\"AzimuthBins\": \"64\"",
                {"neusis/Config.json: key agents[0].sensors[0].configuration.AzimuthBins: is "
                 "string \"64\": expected a whole number from 1 to 4096"}),
      badConfig("ConfigNotJson", "\"agents\"", "agents", {"neusis/Config.json: byte ", "not JSON"}),
      badConfig("ConfigWithoutImagingSonar", "\"ImagingSonar\"", "\"SidescanSonar\"",
                {"neusis/Config.json: key agents: no agent has a sensor of sensor_type "
                 "ImagingSonar"}),
      {.name = "DataFolderWithoutPickles",
       .prepare =
           [](const Workspace& ws) {
             writeDataset(ws);
             std::filesystem::remove_all(ws / "neusis" / "Data");
             std::filesystem::create_directories(ws / "neusis" / "Data");
             writeBytes(ws / "neusis" / "Data" / "notes.txt", "no frames here\n");
             return std::string("reconstruct neusis --out out");
           },
       .message = {"neusis/Data: no .pkl file: expected one pickle a frame"},
       .absent = {"out"}},
  };
}

}  // namespace sonarcarve::test
