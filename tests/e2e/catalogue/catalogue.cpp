#include "e2e/catalogue/catalogue.h"

#include <sys/resource.h>
#include <sys/stat.h>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/cli_runner.h"

namespace sonarcarve::test {
namespace {

constexpr int kTimeLimitS = 60;
constexpr long kMemoryLimitKib = 2L * 1024 * 1024;

// Runs `sonarcarve-cli ARGS` in `folder` under the time limit and, if given, a file size limit.
// A write beyond that limit fails with EFBIG as on a full disk (SIGXFSZ is ignored).
RunResult runLimited(const std::filesystem::path& folder, const std::string& args,
                     int file_size_limit_kib, const std::string& wrapper) {
  std::string command = "cd " + quoted(folder) + " && (trap '' XFSZ; ";
  if (file_size_limit_kib > 0) {
    command += "ulimit -f " + std::to_string(file_size_limit_kib) + "; ";
  }
  command += "exec timeout -k 5 " + std::to_string(kTimeLimitS) + " " + wrapper + " '" +
             SONARCARVE_CLI + "' " + args + ") 2>&1";
  return runShell(command);
}

std::vector<std::string> temporaryFilesUnder(const std::filesystem::path& root) {
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) {
      found.push_back(entry.path().string());
    }
  }
  return found;
}

}  // namespace

Workspace::Workspace() {
  copyExampleMission(root(), "mission");
}

void PrintTo(const CatalogueCase& c, std::ostream* out) {
  *out << c.name;
}

void runCatalogueCase(const CatalogueCase& c) {
  const Workspace ws;
  const std::string args = c.prepare(ws);
  const RunResult r = runLimited(ws.root(), args, c.file_size_limit_kib, c.wrapper);
  const std::string context = "sonarcarve-cli " + args + "\n" + r.output;
  ASSERT_NE(r.exit_code, 124) << "still running after " << kTimeLimitS << " s: " << context;
  ASSERT_GE(r.exit_code, 0) << context;
  ASSERT_LT(r.exit_code, 128) << "ended by a signal: " << context;
  EXPECT_NE(r.exit_code, 70) << "an exception that is not a sonarcarve::Error: " << context;
  if (c.outcome == Outcome::Fails) {
    EXPECT_NE(r.exit_code, 0) << context;
  } else {
    EXPECT_EQ(r.exit_code, 0) << context;
  }
  for (const std::string& fragment : c.message) {
    EXPECT_NE(r.output.find(fragment), std::string::npos)
        << "'" << fragment << "' not in the output of " << context;
  }
  for (const std::string& relative : c.absent) {
    std::error_code ec;
    EXPECT_FALSE(std::filesystem::exists(ws / relative, ec)) << relative << " left by " << context;
  }
  for (const std::string& relative : c.intact) {
    EXPECT_EQ(readText(ws / relative), kPreviousContent) << relative << " changed by " << context;
  }
  for (const auto& [relative, fragment] : c.holds) {
    std::error_code ec;
    EXPECT_TRUE(std::filesystem::is_regular_file(ws / relative, ec)) << relative << ": " << context;
    if (std::filesystem::is_regular_file(ws / relative, ec)) {
      EXPECT_NE(readText(ws / relative).find(fragment), std::string::npos)
          << "'" << fragment << "' not in " << relative << " after " << context;
    }
  }
  for (const std::string& relative : c.fifos) {
    std::error_code ec;
    EXPECT_TRUE(std::filesystem::is_fifo(std::filesystem::symlink_status(ws / relative, ec)))
        << relative << " replaced by " << context;
  }
  EXPECT_EQ(temporaryFilesUnder(ws.root()), std::vector<std::string>{}) << context;
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LE(usage.ru_maxrss, kMemoryLimitKib) << "memory peak (KiB) of " << context;
}

void runCliIn(const Workspace& ws, const std::string& args) {
  const RunResult made =
      runShell("cd " + quoted(ws.root()) + " && '" + SONARCARVE_CLI + "' " + args + " 2>&1");
  EXPECT_EQ(made.exit_code, 0) << args << ": " << made.output;
}

void writePrevious(const std::filesystem::path& path) {
  writeBytes(path, kPreviousContent);
}

void writeBytes(const std::filesystem::path& path, const std::string& bytes) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  ASSERT_TRUE(out.flush()) << path;
}

void replaceIn(const std::filesystem::path& path, const std::string& from, const std::string& to) {
  std::string text = readText(path);
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << "'" << from << "' not in " << path;
  text.replace(at, from.size(), to);
  writeBytes(path, text);
}

void setFrameFile(const std::filesystem::path& mission, int index, const std::string& file) {
  char name[32];
  std::snprintf(name, sizeof name, "frames/%06d.png", index);
  replaceIn(mission / "frames.csv", name, file);
}

void makeFifo(const std::filesystem::path& path) {
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0) << path;
}

std::string asciiPly(const std::vector<std::array<double, 3>>& points,
                     const std::vector<std::array<long, 3>>& faces) {
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\nelement vertex " << points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n";
  if (!faces.empty()) {
    out << "element face " << faces.size() << "\nproperty list uchar int vertex_indices\n";
  }
  out << "end_header\n";
  for (const auto& p : points) {
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  for (const auto& f : faces) {
    out << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
  }
  return out.str();
}

std::string tetrahedronPly() {
  return asciiPly({{2, 0, 10}, {2.1, 0, 10}, {2, 0.1, 10}, {2, 0, 10.1}},
                  {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}});
}

std::string pngHeader(std::uint32_t width, std::uint32_t height) {
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8);
  for (const std::uint32_t v : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) {
      png += static_cast<char>((v >> shift) & 0xff);
    }
  }
  png += std::string("\x10\0\0\0\0", 5);  // 16-bit grey, no interlace
  png += std::string("\0\0\0\0", 4);      // CRC, never reached
  png += std::string("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return png;
}

void putNotAFile(const std::filesystem::path& path, NotAFile kind) {
  std::filesystem::remove(path);
  switch (kind) {
    case NotAFile::Directory:
      std::filesystem::create_directories(path);
      break;
    case NotAFile::Fifo:
      makeFifo(path);
      break;
    case NotAFile::Device:
      std::filesystem::create_symlink("/dev/zero", path);
      break;
  }
}

std::string describe(NotAFile kind) {
  static const char* const kMessages[] = {"is a directory", "is a FIFO", "is a device"};
  return kMessages[static_cast<int>(kind)];
}

}  // namespace sonarcarve::test
