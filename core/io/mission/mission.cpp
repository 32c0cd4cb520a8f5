#include "io/mission/mission.h"

#include <algorithm>
#include <optional>

#include "common/error.h"
#include "io/files/csv_table.h"
#include "io/files/frame_png.h"
#include "io/files/yaml_fields.h"
#include "io/frame_source.h"
#include "io/mission/mission_place.h"
#include "io/mission/nav_csv.h"
#include "io/mission/sonar_yaml.h"

namespace sonarcarve {
namespace {

// A frame file named by a relative path that does not climb out with "..": what a mission folder
// that is copied or shared needs, and what keeps it from reading files elsewhere on the machine.
bool staysInsideFolder(const std::string& file) {
  const std::filesystem::path relative(file);
  if (relative.has_root_path()) {
    return false;
  }
  for (const auto& part : relative.lexically_normal()) {
    if (part == "..") {
      return false;
    }
  }
  return true;
}

// Where `file` leads once its symbolic links are resolved (a `frames` folder that is a link to
// "/"), when that is outside `root` (the mission folder, resolved) and could hold a frame's
// bytes; nothing when it is inside, cannot be resolved, or is no regular file (a link to
// /dev/zero): the frame reader refuses that by its kind and skips the frame, reading nothing.
std::optional<std::filesystem::path> resolvedOutside(const std::filesystem::path& root,
                                                     const std::string& file) {
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::weakly_canonical(root / file, ec);
  if (ec) {
    return std::nullopt;
  }
  const auto [in_root, in_real] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
  const bool other_kind =
      std::filesystem::exists(real, ec) && !std::filesystem::is_regular_file(real, ec);
  if (in_root == root.end() || other_kind) {
    return std::nullopt;
  }
  return real;
}

// frames.files_outside_folder: "refused" (the default) or "allowed".
bool allowsFilesOutside(const YAML::Node& frames_node, const YamlFields& fields) {
  const YAML::Node node = frames_node["files_outside_folder"];
  if (!node) {
    return false;
  }
  const std::string value = fields.text(node, "frames.files_outside_folder");
  if (value != "allowed" && value != "refused") {
    fields.fail(node, "frames.files_outside_folder", "expected 'allowed' or 'refused'");
  }
  return value == "allowed";
}

std::vector<FrameRecord> readFrameIndex(const std::filesystem::path& folder,
                                        const std::filesystem::path& path, bool allow_outside) {
  const CsvTable table = CsvTable::read(path);
  std::error_code ec;
  const std::filesystem::path root = std::filesystem::weakly_canonical(folder, ec);
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
    if (!allow_outside && !staysInsideFolder(record.file)) {
      throw Error(table.file(), linePlace(row.line),
                  "column 'file': '" + record.file +
                      "' leaves the mission folder: expected a path inside it (or "
                      "frames.files_outside_folder: allowed in mission.yaml)");
    }
    const auto outside = allow_outside || ec ? std::nullopt : resolvedOutside(root, record.file);
    if (outside) {
      throw Error(table.file(), linePlace(row.line),
                  "column 'file': '" + record.file + "' leads to '" + outside->string() +
                      "', outside the mission folder, through a symbolic link: expected a path "
                      "inside it (or frames.files_outside_folder: allowed in mission.yaml)");
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

// The frames of a mission folder: 16-bit PNGs named by the frame index, holding the sonar's
// counts.
class MissionFolderSource final : public FrameSource {
 public:
  explicit MissionFolderSource(const Mission& mission)
      : folder_(mission.folder), sonar_(mission.sonar), frames_(mission.frames) {}

  std::string kind() const override { return "mission folder"; }
  std::size_t size() const override { return frames_.size(); }
  Frame load(std::size_t index) const override {
    const FrameRecord& record = frames_.at(index);
    const std::filesystem::path path = folder_ / record.file;
    Frame frame;
    frame.time_s = record.time_s;
    frame.sonar_id = record.sonar_id;
    if (record.sonar_id != sonar_.id()) {
      throw Error(
          path.string(), "frame " + std::to_string(index),
          "sonar id '" + record.sonar_id + "' is not the mission's sonar '" + sonar_.id() + "'");
    }
    frame.image = readFramePng(path, FrameShape{sonar_.rows(), sonar_.cols()});
    return frame;
  }

 private:
  std::filesystem::path folder_;
  SonarModel sonar_;
  std::vector<FrameRecord> frames_;
};

// A folder holding mission.yaml, or a YAML file that says it is a mission.
bool looksLikeMission(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    // Any mission.yaml, so that one that is not a regular file is read and refused with why.
    return std::filesystem::exists(path / kMissionFileName, ec);
  }
  return path.filename() == kMissionFileName && std::filesystem::is_regular_file(path, ec);
}

[[maybe_unused]] const bool registered =
    registerFrameSourceReader({"mission folder", looksLikeMission,
                               [](const std::filesystem::path& path, const OpenOptions& options) {
                                 Mission mission = readMission(path);
                                 applyOpenOptions(mission, options);
                                 return mission;
                               }});

}  // namespace

std::shared_ptr<const FrameSource> makeMissionFolderSource(const Mission& mission) {
  return std::make_shared<const MissionFolderSource>(mission);
}

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

  std::string crs = declaredCrs(root, fields);
  NavTrack nav = readNavCsv(folder / nav_file, crs);
  const std::optional<Eigen::Vector3d> origin = declaredOrigin(root, fields, crs);
  if (origin) {
    nav = translatedTrack(nav, -*origin);
  }
  std::vector<FrameRecord> frames =
      readFrameIndex(folder, folder / index_file, allowsFilesOutside(frames_node, fields));
  Mission mission{folder,
                  std::move(name),
                  std::move(sonar),
                  mounting,
                  std::move(nav),
                  std::move(frames),
                  nav_file,
                  index_file,
                  nullptr,
                  {},
                  {},
                  origin.value_or(Eigen::Vector3d::Zero()),
                  std::move(crs)};
  mission.source = makeMissionFolderSource(mission);
  return mission;
}

Frame loadFrame(const Mission& mission, std::size_t index) {
  if (!mission.source) {
    throw Error(mission.folder.string(), "frame " + std::to_string(index),
                "the mission has no frame source");
  }
  Frame frame = mission.source->load(index);
  const FrameRecord& record = mission.frames.at(index);
  frame.time_s = record.time_s;
  // Every source gives the sonar's counts; the engine works on power.
  mission.sonar.intensityScale().countsToPower(frame.image, mission.folder.string(), record.file);
  return frame;
}

NavTrack worldTrack(const Mission& mission) {
  return translatedTrack(mission.nav, mission.origin_ned_m);
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
