#include "io/mission/mission_writer.h"

#include <yaml-cpp/yaml.h>
#include <cstdio>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/frame_png.h"
#include "io/files/output_folder.h"
#include "io/files/yaml_fields.h"
#include "io/mission/nav_csv.h"
#include "io/mission/sonar_yaml.h"

namespace sonarcarve {

MissionWriter::MissionWriter(std::filesystem::path folder, std::string name, SonarModel sonar,
                             Mounting mounting)
    : folder_(std::move(folder)),
      name_(std::move(name)),
      sonar_(std::move(sonar)),
      mounting_(mounting) {
  prepareOutputFolder(folder_ / "frames");
}

void MissionWriter::addFrame(const Frame& frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "frames/%06zu.png", records_.size());
  const std::string what = (folder_ / name).string();
  if (frame.image.rows != sonar_.rows() || frame.image.cols != sonar_.cols()) {
    throw Error(what, "", "frame size does not match the sonar model");
  }
  // The file holds the sonar's own counts: a decibel sonar's 80 dB of power do not fit 16 bits.
  writeFileAtomically(folder_ / name,
                      encodeFramePng(sonar_.intensityScale().powerToCounts(frame.image), what));
  records_.push_back({frame.time_s, sonar_.id(), name, 0});
}

void MissionWriter::finish(const NavTrack& nav, const std::string& crs) {
  writeFileAtomically(folder_ / "nav.csv", navCsvText(nav));
  std::string index = "time_s,sonar_id,file\n";
  for (const FrameRecord& r : records_) {
    index += shortestNumber(r.time_s) + "," + r.sonar_id + "," + r.file + "\n";
  }
  writeFileAtomically(folder_ / "frames.csv", index);

  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << "sonarcarve-mission";
  out << YAML::Key << "version" << YAML::Value << kMissionFormatVersion;
  out << YAML::Key << "name" << YAML::Value << name_;
  out << YAML::Key << "sonar" << YAML::Value;
  emitSonar(out, sonar_);
  out << YAML::Key << "mounting" << YAML::Value;
  emitMounting(out, mounting_);
  out << YAML::Key << "navigation" << YAML::Value << "nav.csv";
  out << YAML::Key << "frames" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "index" << YAML::Value << "frames.csv";
  out << YAML::Key << "encoding" << YAML::Value << "png16";
  out << YAML::EndMap;
  if (!crs.empty()) {
    out << YAML::Key << "crs" << YAML::Value << crs;
  }
  out << YAML::EndMap;
  writeFileAtomically(folder_ / kMissionFileName, std::string(out.c_str()) + "\n");
}

}  // namespace sonarcarve
