// ARIS recordings (.aris) opened in place: every frame of the file is a frame, decoded on
// demand. Placement: the navigation CSV given with --nav if any; otherwise the vehicle fields
// the frame headers carry (Depth, Heading, Pitch, Roll: position (0, 0, depth) in NED, the
// vehicle's attitude) when any of them is non-zero; otherwise a stationary vehicle at the
// origin (with a warning). See docs/formats.md.
#include <cmath>

#include "common/angles.h"
#include "common/error.h"
#include "common/number_text.h"
#include "io/aris/aris_file.h"
#include "io/aris/aris_lens.h"
#include "io/frame_source.h"
#include "io/import.h"
#include "sonar/attitude.h"
#include "sonar/mission_origin.h"

namespace sonarcarve {
namespace {

// ARIS files do not state the elevation beam width; the ARIS lenses' is about 14 degrees.
constexpr double kArisVerticalApertureDeg = 14.0;
// A heading, pitch or roll of a frame header beyond a turn either way is not an attitude.
constexpr double kMaxAngleDeg = 360.0;

// ARIS samples are logarithmic: bytes 0..255 span 0..80 dB (the ARIS file SDK's
// docs/understanding-aris-data.md). loadFrame gives them as power.
IntensityScale arisIntensityScale() {
  return IntensityScale::decibel(80.0, 255.0);
}

class ArisSource final : public FrameSource {
 public:
  ArisSource(std::shared_ptr<const ArisFile> file, std::string sonar_id, double time_offset_s)
      : file_(std::move(file)), sonar_id_(std::move(sonar_id)), time_offset_s_(time_offset_s) {}

  std::string kind() const override { return "ARIS recording"; }
  std::size_t size() const override { return file_->frames().size(); }
  Frame load(std::size_t index) const override {
    Frame frame;
    frame.time_s = file_->frames().at(index).time_us * 1e-6 + time_offset_s_;
    frame.sonar_id = sonar_id_;
    frame.image = file_->image(index);
    return frame;
  }

 private:
  std::shared_ptr<const ArisFile> file_;
  std::string sonar_id_;
  double time_offset_s_;
};

bool hasVehicleFields(const ArisFile& file) {
  for (const ArisFrameInfo& f : file.frames()) {
    if (f.depth_m != 0.0F || f.heading_deg != 0.0F || f.pitch_deg != 0.0F || f.roll_deg != 0.0F) {
      return true;
    }
  }
  return false;
}

// A vehicle field of frame `k`'s header must be a number within `limit` of zero (a depth
// within the navigation's bound, an angle within a turn); the error names the file, the frame
// and the field.
void requireField(const std::filesystem::path& path, std::size_t k, const char* field, float value,
                  double limit, const char* unit) {
  if (!(std::abs(value) <= limit)) {
    throw Error(path.string(), "frame " + std::to_string(k),
                std::string("vehicle field ") + field + " is " + shortestNumber(value) +
                    ": expected a number within +-" + shortestNumber(limit) + " " + unit);
  }
}

// The vehicle fields as a track (frames whose time does not increase are left out).
NavTrack vehicleTrack(const ArisFile& file, const std::filesystem::path& path,
                      double time_offset_s) {
  std::vector<NavSample> samples;
  for (std::size_t k = 0; k < file.frames().size(); ++k) {
    const ArisFrameInfo& f = file.frames()[k];
    requireField(path, k, "Depth", f.depth_m, kMaxNavCoordinate_m, "m");
    requireField(path, k, "Heading", f.heading_deg, kMaxAngleDeg, "degrees");
    requireField(path, k, "Pitch", f.pitch_deg, kMaxAngleDeg, "degrees");
    requireField(path, k, "Roll", f.roll_deg, kMaxAngleDeg, "degrees");
    const double t = f.time_us * 1e-6 + time_offset_s;
    if (!samples.empty() && t <= samples.back().time_s) {
      continue;
    }
    NavSample s;
    s.time_s = t;
    s.position_m = Eigen::Vector3d(0.0, 0.0, f.depth_m);
    s.q_world_vehicle = quaternionFromRollPitchYaw(
        {degToRad(f.roll_deg), degToRad(f.pitch_deg), degToRad(f.heading_deg)});
    samples.push_back(s);
  }
  return NavTrack(std::move(samples));
}

Mission openArisFile(const std::filesystem::path& path, const OpenOptions& options) {
  auto file = std::make_shared<const ArisFile>(ArisFile::open(path));
  const ArisFrameInfo& first = file->frames().front();
  const ArisLensBeams lens = arisLensBeams(first.beams, first.large_lens);
  const double aperture_deg = options.vertical_aperture_deg.value_or(kArisVerticalApertureDeg);
  // Sample i covers [start + i * length, start + (i + 1) * length): the SDK's RangeStart and
  // RangeEnd are the window's edges.
  const RangeBins range{first.windowStart(), first.sampleLength(),
                        static_cast<int>(first.samples_per_beam)};
  const SonarModel sonar =
      SonarModel("aris", range, BearingTable::fromCentres(lens.centres_rad), degToRad(aperture_deg))
          .withIntensityScale(arisIntensityScale());
  std::vector<double> times;
  for (const ArisFrameInfo& f : file->frames()) {
    times.push_back(f.time_us * 1e-6 + options.time_offset_s);
  }
  Mission mission = recordingMission(path, sonar, times,
                                     [](std::size_t k) { return "frame " + std::to_string(k); });
  for (const std::string& problem : file->problems()) {
    mission.warnings.push_back(problem);
  }
  mission.warnings.push_back("beam bearings: " + lens.source);
  if (!options.vertical_aperture_deg) {
    mission.warnings.push_back("vertical aperture " + std::to_string(aperture_deg).substr(0, 4) +
                               " degrees assumed (ARIS files do not state it); override it "
                               "with --aperture-deg");
  }
  if (options.nav_csv.empty() && hasVehicleFields(*file)) {
    mission.nav = vehicleTrack(*file, path, options.time_offset_s);
    mission.nav_file = path.filename().string() + " (frame headers: depth, heading, pitch, roll)";
  } else if (options.nav_csv.empty()) {
    mission.warnings.push_back(
        "no navigation given (--nav) and the frame headers carry none: the vehicle is "
        "stationary at the origin with zero attitude");
  }
  applyNavigationAndMounting(mission, options);
  mission.source = std::make_shared<const ArisSource>(file, sonar.id(), options.time_offset_s);
  return mission;
}

[[maybe_unused]] const bool registered = registerFrameSourceReader(
    {"aris", [](const std::filesystem::path& path) { return looksLikeArisFile(path); },
     openArisFile});

}  // namespace
}  // namespace sonarcarve
