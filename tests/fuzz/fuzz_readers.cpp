#include "fuzz/fuzz_readers.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string_view>

#include "common/error.h"
#include "denoise/noise_model.h"
#include "geometry/scene_io.h"
#include "io/aris/aris_file.h"
#include "io/files/frame_png.h"
#include "io/holoocean/holoocean_frame_file.h"
#include "io/mesh/ply_check.h"
#include "io/mesh/point_cloud_ply.h"
#include "io/mission/mission.h"
#include "io/mission/nav_import.h"
#include "io/oculus/oculus_log.h"
#include "io/pickle/pickle_reader.h"
#include "io/rosbag/bag_oculus.h"
#include "io/rosbag/bag_sonar.h"
#include "io/rosbag/ros_bag.h"
#include "io/rosbag/ros_messages.h"
#include "pipeline/reconstruction_params.h"
#include "session/session_file.h"

namespace sonarcarve::fuzz {
namespace {

// A scratch folder for this process, kept between inputs: $SONARCARVE_FUZZ_SCRATCH (set by
// run.sh, which removes it: libFuzzer ends without running destructors), else one in memory
// (/dev/shm) removed at a normal exit.
struct ScratchFolder {
  ScratchFolder() {
    const char* given = std::getenv("SONARCARVE_FUZZ_SCRATCH");
    const std::filesystem::path shm = "/dev/shm";
    const auto base =
        std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path();
    path = given != nullptr && *given != '\0'
               ? std::filesystem::path(given)
               : base / ("sonarcarve-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::filesystem::path path;
};

const std::filesystem::path& scratch() {
  static const ScratchFolder folder;
  return folder.path;
}

void write(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string_view text(std::span<const std::uint8_t> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

// The parts of `bytes` between NUL bytes; missing parts are empty.
std::vector<std::string_view> parts(std::span<const std::uint8_t> bytes, std::size_t count) {
  std::vector<std::string_view> out;
  std::string_view rest = text(bytes);
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const auto nul = rest.find('\0');
    out.push_back(rest.substr(0, nul));
    rest = nul == std::string_view::npos ? std::string_view{} : rest.substr(nul + 1);
  }
  out.push_back(rest);
  return out;
}

template <typename Run>
void acceptingErrors(Run run) {
  try {
    run();
  } catch (const Error&) {
    // A clear rejection is a correct answer to a broken file.
  }
}

// Every message of a bag decoded as its topic's type, as the bag frame source does.
void decodeBag(const RosBag& bag) {
  const std::string source = bag.path().string();
  std::optional<BagSonarGeometry> geometry;
  for (const BagMessage& m : bag.messages()) {
    acceptingErrors([&] {
      const std::vector<std::uint8_t> bytes = bag.payload(m);
      const std::string& type = bag.topics().at(m.topic).type;
      switch (rosMessageKind(type)) {
        case RosMessageKind::SonarImage: {
          const ProjectedSonarImageMsg msg = decodeSonarImage(type, bytes, source, m.place);
          if (!geometry) {
            const bool legacy = isLegacySonarImage(type);
            geometry = bagSonarGeometry(msg, legacy ? SonarAxes::Frd : SonarAxes::Auto,
                                        legacy ? ImageLayout::BeamMajor : ImageLayout::RangeMajor,
                                        std::nullopt, "fuzz", source, m.place);
          }
          bagSonarImage(msg, *geometry, source, m.place);
          break;
        }
        case RosMessageKind::VehiclePose:
          decodeRosPose(type, bytes, source, m.place);
          break;
        case RosMessageKind::Transforms:
          decodeTfMessage(bytes, source, m.place);
          break;
        case RosMessageKind::GeoFix:
          decodeNavSatFix(bytes, source, m.place);
          break;
        case RosMessageKind::GeoOrigin:
          decodeGeoPoint(type, bytes, source, m.place);
          break;
        case RosMessageKind::Other:
          decodeRosHeader(bytes, source, m.place);
          break;
      }
    });
  }
  // Raw Oculus pings, as the bag frame source reads them.
  for (std::size_t t = 0; t < bag.topics().size(); ++t) {
    acceptingErrors([&] {
      if (!isOculusTopic(bag, t)) {
        return;
      }
      std::vector<std::string> problems;
      const BagOculusFrames pings =
          indexOculusFrames(bag, t, BagTime::Header, 0.0, std::nullopt, problems);
      for (const BagFrameRef& f : pings.frames) {
        const BagMessage& m = bag.messages()[f.message];
        acceptingErrors([&] { bagOculusImage(bag.payload(m), *pings.sonar, source, m.place); });
      }
    });
  }
}

}  // namespace

void mcapBag(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "fuzz.mcap";
  write(path, text(bytes));
  acceptingErrors([&] { decodeBag(*openMcapBag(path)); });
}

void sqliteBag(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "fuzz.db3";
  write(path, text(bytes));
  acceptingErrors([&] { decodeBag(*openSqliteBag(path)); });
}

void oculusLog(std::span<const std::uint8_t> bytes) {
  acceptingErrors([&] {
    const OculusLog log = OculusLog::fromBytes({bytes.begin(), bytes.end()}, "fuzz.raw");
    for (std::size_t i = 0; i < log.pings().size(); ++i) {
      acceptingErrors([&] { log.decode(i); });
    }
  });
  acceptingErrors([&] { decodeOculusPing(bytes, 0, "fuzz.raw"); });
}

void arisFile(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "fuzz.aris";
  write(path, text(bytes));
  acceptingErrors([&] {
    const ArisFile file = ArisFile::open(path);
    for (std::size_t k = 0; k < file.frames().size(); ++k) {
      acceptingErrors([&] { file.image(k); });
    }
  });
}

void mission(std::span<const std::uint8_t> bytes) {
  const auto files = parts(bytes, 3);
  const auto dir = scratch() / "mission";
  std::filesystem::create_directories(dir);
  write(dir / "mission.yaml", files[0]);
  write(dir / "nav.csv", files[1]);
  write(dir / "frames.csv", files[2]);
  acceptingErrors([&] { readMission(dir); });
}

void framePng(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "frame.png";
  write(path, text(bytes));
  acceptingErrors([&] { readFramePng(path); });
}

void plyPointCloud(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "cloud.ply";
  write(path, text(bytes));
  acceptingErrors([&] { checkPlyFile(path); });
  acceptingErrors([&] { readPointCloudPly(path); });
  acceptingErrors([&] { readPlyMesh(path); });
}

void navImport(std::span<const std::uint8_t> bytes) {
  const auto files = parts(bytes, 2);
  acceptingErrors([&] {
    const NavMapping mapping = parseNavMapping(files[0], "fuzz-map.yaml");
    acceptingErrors([&] { importNavCsvText(files[1], "fuzz-nav.csv", mapping); });
  });
  acceptingErrors([&] { importNavCsvText(files[1], "fuzz-nav.csv", NavMapping{}); });
}

void paramsYaml(std::span<const std::uint8_t> bytes) {
  acceptingErrors([&] {
    ReconstructionParams::fromYamlText(std::string(text(bytes)), "fuzz-params.yaml").validate();
  });
}

void noiseModel(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "noise.yaml";
  write(path, text(bytes));
  acceptingErrors([&] { NoiseModel::load(path); });
}

void sessionFile(std::span<const std::uint8_t> bytes) {
  const auto path = scratch() / "session.sonarcarve";
  write(path, text(bytes));
  acceptingErrors([&] { loadSession(path); });
}

void holoOceanPickle(std::span<const std::uint8_t> bytes) {
  acceptingErrors([&] {
    const pickle::ValuePtr state = pickle::decodePickle(text(bytes), "fuzz.pkl");
    acceptingErrors([&] { holoOceanPose(*state, "PoseSensor", "fuzz.pkl"); });
    acceptingErrors([&] {
      const auto [rows, cols] = holoOceanImageSize(*state, "ImagingSonar", "fuzz.pkl");
      holoOceanImage(*state, "ImagingSonar", rows, cols, "fuzz.pkl");
    });
  });
}

void referenceMesh(std::span<const std::uint8_t> bytes) {
  for (const char* name : {"mesh.stl", "mesh.obj", "mesh.ply"}) {
    const auto path = scratch() / name;
    write(path, text(bytes));
    acceptingErrors([&] { loadSceneMesh(path); });
  }
}

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"oculus", oculusLog},       {"mission", mission},      {"frame_png", framePng},
      {"ply", plyPointCloud},      {"nav_import", navImport}, {"params_yaml", paramsYaml},
      {"noise_model", noiseModel}, {"mesh", referenceMesh},   {"session", sessionFile},
      {"aris", arisFile},          {"mcap", mcapBag},         {"db3", sqliteBag},
      {"pickle", holoOceanPickle}};
  return all;
}

}  // namespace sonarcarve::fuzz
