// The bad-input catalogue (docs/reliability.md): inputs a user can get wrong and faults of the
// machine we can provoke, each with the answer SonarCarve must give. A case prepares its
// inputs in a fresh folder and runs sonarcarve-cli as a user would, under a time limit; the
// runner checks the exit code, that the message names the file, the place and what was
// expected, that no partial output is left and that previous files are intact.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "support/test_support.h"

namespace sonarcarve::test {

/// A fresh folder for one case, holding a copy of the example mission at mission/.
class Workspace {
 public:
  Workspace();
  const std::filesystem::path& root() const { return dir_.path(); }
  std::filesystem::path mission() const { return root() / "mission"; }
  std::filesystem::path operator/(const std::string& relative) const { return root() / relative; }

 private:
  ScratchDir dir_;
};

enum class Outcome { Fails, Succeeds };

struct CatalogueCase {
  std::string name;  ///< the GoogleTest name: letters, digits and underscores
  /// Prepares the inputs; returns the arguments of sonarcarve-cli, paths quoted.
  std::function<std::string(const Workspace&)> prepare;
  Outcome outcome = Outcome::Fails;
  /// Fragments the output must hold: the file, the place, what was expected.
  std::vector<std::string> message;
  /// Paths under the workspace that must not exist afterwards: no partial output.
  std::vector<std::string> absent = {};
  /// Files prepare() wrote with writePrevious() that must still hold that content.
  std::vector<std::string> intact = {};
  /// Largest file the command may write (a full disk), in the units of sh's `ulimit -f`: blocks
  /// of 512 bytes for dash, the /bin/sh that runs the cases; 0 = no limit.
  int file_size_limit_kib = 0;
  /// A command run around sonarcarve-cli, in the workspace: "flock -o out" (holds out/ locked).
  std::string wrapper = "";
  /// Files under the workspace that must exist and hold a fragment: (path, fragment).
  std::vector<std::pair<std::string, std::string>> holds = {};
  /// FIFOs prepare() made that must still be FIFOs: not replaced by a file.
  std::vector<std::string> fifos = {};
};

/// GoogleTest prints a failing case's parameter: its name, not its bytes.
void PrintTo(const CatalogueCase& c, std::ostream* out);

/// Runs one case and checks it (see the file comment), and that the command ended by itself
/// within 60 s, with no signal, and peaked under 2 GB of memory.
void runCatalogueCase(const CatalogueCase& c);

/// The cases, by class (catalogue_*.cpp).
std::vector<CatalogueCase> fileKindCases();
std::vector<CatalogueCase> contentCases();
std::vector<CatalogueCase> limitCases();
std::vector<CatalogueCase> outputCases();
std::vector<CatalogueCase> oculusCases();
std::vector<CatalogueCase> readerCases();
std::vector<CatalogueCase> bagCases();
std::vector<CatalogueCase> geoCases();
std::vector<CatalogueCase> boundCases();
std::vector<CatalogueCase> senseCases();
std::vector<CatalogueCase> messageCases();
std::vector<CatalogueCase> failedRunCases();
std::vector<CatalogueCase> recordedSonarCases();
std::vector<CatalogueCase> pathCases();
std::vector<CatalogueCase> mappedBoundCases();
std::vector<CatalogueCase> holoOceanCases();

// Inputs for the cases.
/// Runs `sonarcarve-cli ARGS` in the workspace to make an input, and expects it to succeed.
void runCliIn(const Workspace& ws, const std::string& args);
inline constexpr const char* kPreviousContent = "a file of an earlier run\n";
void writePrevious(const std::filesystem::path& path);
void writeBytes(const std::filesystem::path& path, const std::string& bytes);
/// Replaces the one occurrence of `from` in a text file (fails the test if absent).
void replaceIn(const std::filesystem::path& path, const std::string& from, const std::string& to);
/// Points the frame index's row `index` at `file`.
void setFrameFile(const std::filesystem::path& mission, int index, const std::string& file);
void makeFifo(const std::filesystem::path& path);
/// An ASCII PLY: points, and faces of three vertex indices (a mesh when not empty).
std::string asciiPly(const std::vector<std::array<double, 3>>& points,
                     const std::vector<std::array<long, 3>>& faces = {});
/// A small valid mesh: a tetrahedron of 10 cm edges near the example mission's pipe.
std::string tetrahedronPly();
/// A PNG file whose header declares width x height, with no image data after it.
std::string pngHeader(std::uint32_t width, std::uint32_t height);
/// Kinds of non-regular file put where a file is expected.
enum class NotAFile { Directory, Fifo, Device };
/// Replaces `path` (removing any file there) with a folder, a FIFO or a link to /dev/zero.
void putNotAFile(const std::filesystem::path& path, NotAFile kind);
std::string describe(NotAFile kind);  ///< the message's word: "a directory", ...

}  // namespace sonarcarve::test
