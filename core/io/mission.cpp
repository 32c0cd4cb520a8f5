#include "io/mission.h"

#include "common/error.h"
#include "io/csv_table.h"
#include "io/frame_png.h"
#include "io/nav_csv.h"
#include "io/sonar_yaml.h"
#include "io/yaml_fields.h"

namespace sonarcarve {
namespace {

std::vector<FrameRecord> readFrameIndex(const std::filesystem::path& path) {
  const CsvTable table = CsvTable::read(path);
  const std::size_t t = table.column("time_s");
  const std::size_t id = table.column("sonar_id");
  const std::size_t file = table.column("file");
  std::vector<FrameRecord> frames;
  frames.reserve(table.rows().size());
  for (const auto& row : table.rows()) {
    FrameRecord record{table.number(row, t), table.text(row, id), table.text(row, file), row.line};
    if (record.file.empty()) {
      throw Error(table.file(), linePlace(row.line), "column 'file': expected a file name");
    }
    if (!frames.empty() && record.time_s < frames.back().time_s) {
      throw Error(table.file(), linePlace(row.line),
                  "time goes backwards: " + table.text(row, t) + " s after " +
                      shortestNumber(frames.back().time_s) + " s");
    }
    frames.push_back(std::move(record));
  }
  return frames;
}

}  // namespace

Mission readMission(const std::filesystem::path& folder_or_yaml) {
  const bool is_dir = std::filesystem::is_directory(folder_or_yaml);
  const std::filesystem::path yaml_path =
      is_dir ? folder_or_yaml / kMissionFileName : folder_or_yaml;
  const std::filesystem::path folder = is_dir ? folder_or_yaml : folder_or_yaml.parent_path();
  const YamlFields fields(yaml_path.string());
  const YAML::Node root = fields.load();

  const std::string format = fields.text(fields.child(root, "", "format"), "format");
  if (format != "sonarcarve-mission") {
    fields.fail(root["format"], "format", "expected 'sonarcarve-mission', found '" + format + "'");
  }
  const YAML::Node version_node = fields.child(root, "", "version");
  const int version = fields.positiveInt(version_node, "version");
  if (version != kMissionFormatVersion) {
    fields.fail(version_node, "version",
                "unknown format version " + std::to_string(version) + ": this build reads " +
                    std::to_string(kMissionFormatVersion));
  }
  std::string name = root["name"] ? fields.text(root["name"], "name") : folder.filename().string();
  SonarModel sonar = sonarFromYaml(fields.child(root, "", "sonar"), fields);
  Mounting mounting = mountingFromYaml(fields.child(root, "", "mounting"), fields);
  const std::string nav_file = fields.text(fields.child(root, "", "navigation"), "navigation");
  const YAML::Node frames_node = fields.child(root, "", "frames");
  const std::string index_file =
      fields.text(fields.child(frames_node, "frames", "index"), "frames.index");
  const YAML::Node encoding = fields.child(frames_node, "frames", "encoding");
  if (fields.text(encoding, "frames.encoding") != "png16") {
    fields.fail(encoding, "frames.encoding", "expected 'png16' (the only v1 encoding)");
  }

  NavTrack nav = readNavCsv(folder / nav_file);
  std::vector<FrameRecord> frames = readFrameIndex(folder / index_file);
  return Mission{folder,         std::move(name),   std::move(sonar), mounting,
                 std::move(nav), std::move(frames), nav_file,         index_file};
}

Frame loadFrame(const Mission& mission, std::size_t index) {
  const FrameRecord& record = mission.frames.at(index);
  const std::filesystem::path path = mission.folder / record.file;
  Frame frame;
  frame.time_s = record.time_s;
  frame.sonar_id = record.sonar_id;
  if (record.sonar_id != mission.sonar.id()) {
    throw Error(path.string(), "frame " + std::to_string(index),
                "sonar id '" + record.sonar_id + "' is not the mission's sonar '" +
                    mission.sonar.id() + "'");
  }
  frame.image = readFramePng(path);
  if (frame.image.rows != mission.sonar.rows() || frame.image.cols != mission.sonar.cols()) {
    throw Error(path.string(), "frame " + std::to_string(index),
                "image is " + std::to_string(frame.image.rows) + " x " +
                    std::to_string(frame.image.cols) + " (rows x cols), expected " +
                    std::to_string(mission.sonar.rows()) + " range bins x " +
                    std::to_string(mission.sonar.cols()) + " beams");
  }
  return frame;
}

std::vector<FrameProblem> checkFrames(const Mission& mission) {
  std::vector<FrameProblem> problems;
  for (std::size_t i = 0; i < mission.frames.size(); ++i) {
    try {
      loadFrame(mission, i);
    } catch (const Error& e) {
      problems.push_back({i, e.what()});
    }
  }
  return problems;
}

}  // namespace sonarcarve
