// The readers under fuzzing, one entry point each: `bytes` is handed to the reader (split
// into files where the reader reads several, written to a scratch folder where it reads
// paths). Each returns normally when the reader accepts the input or rejects it with a
// sonarcarve::Error; anything else (another exception, a crash, a sanitizer report) is a bug.
// The libFuzzer targets (SONARCARVE_FUZZ) and the regression replay unit test share them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sonarcarve::fuzz {

using Reader = void (*)(std::span<const std::uint8_t> bytes);

/// Oculus message streams and ViewPoint recordings: OculusLog, then every ping decoded.
void oculusLog(std::span<const std::uint8_t> bytes);
/// Mission format v1: mission.yaml, nav.csv and frames.csv separated by NUL bytes.
void mission(std::span<const std::uint8_t> bytes);
/// A frame image (readFramePng).
void framePng(std::span<const std::uint8_t> bytes);
/// A PLY file: checkPlyFile, then readPointCloudPly.
void plyPointCloud(std::span<const std::uint8_t> bytes);
/// Navigation import: a mapping YAML and a CSV separated by a NUL byte.
void navImport(std::span<const std::uint8_t> bytes);

/// Reconstruction parameters: ReconstructionParams::fromYamlText, then validate().
void paramsYaml(std::span<const std::uint8_t> bytes);
/// A noise model file (OpenCV FileStorage YAML): NoiseModel::load.
void noiseModel(std::span<const std::uint8_t> bytes);
/// A reference or scene mesh: loadSceneMesh on the same bytes as an STL, an OBJ and a PLY.
void referenceMesh(std::span<const std::uint8_t> bytes);
/// An ARIS recording: ArisFile::open, then every frame's image.
void arisFile(std::span<const std::uint8_t> bytes);
/// A ROS 2 bag in MCAP storage: openMcapBag, then every message's payload decoded as its
/// topic's type (sonar images also converted to frames).
void mcapBag(std::span<const std::uint8_t> bytes);
/// A ROS 2 bag in SQLite3 storage (.db3): openSqliteBag, then the same decoding.
void sqliteBag(std::span<const std::uint8_t> bytes);
/// A HoloOcean / NeuSIS frame's pickle: decodePickle, then its PoseSensor and ImagingSonar.
void holoOceanPickle(std::span<const std::uint8_t> bytes);
/// A workbench session file (loadSession: YAML with the parameters embedded).
void sessionFile(std::span<const std::uint8_t> bytes);

struct Target {
  std::string name;  ///< also the folder of its corpus: tests/fuzz/corpus/<name>
  Reader reader;
};
const std::vector<Target>& targets();

}  // namespace sonarcarve::fuzz
