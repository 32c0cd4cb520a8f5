// The file primitives every reader and writer goes through: io/files/input_file.h (only regular
// files are read), io/files/atomic_file.h (a write either completes or leaves the previous
// file, and replaces only a regular file) and io/files/output_folder.h (output folders, and
// the lock that keeps two runs out of one).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/atomic_file.h"
#include "io/files/input_file.h"
#include "io/files/output_folder.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;
using test::ScratchDir;

TEST(InputFile, RefusesWhatIsNotARegularFile) {
  ScratchDir dir;
  const auto fifo = dir.path() / "nav.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectError([&] { readInputFile(fifo, "a CSV table", 1000); },
              {"nav.csv: is a FIFO (named pipe): expected a regular file (a CSV table)"});
  expectError([&] { readInputFile(dir.path(), "a frame", 1000); },
              {dir.path().string() + ": is a directory: expected a regular file (a frame)"});
  expectError([&] { requireRegularFile("/dev/zero", "a mesh"); },
              {"/dev/zero: is a device: expected a regular file (a mesh)"});
  expectError([&] { readInputFile(dir.path() / "missing.yaml", "a YAML file", 1000); },
              {"missing.yaml: not found: expected a YAML file"});
}

TEST(InputFile, AFileOverItsFormatsBoundIsRefusedBeforeItIsRead) {
  ScratchDir dir;
  const auto nav = dir.path() / "nav.csv";
  test::writeSparseFile(nav, std::uint64_t{20} << 30);
  const auto start = std::chrono::steady_clock::now();
  expectError([&] { readInputFile(nav, "a CSV table", kMaxTableFileBytes); },
              {"nav.csv: is 21474836480 bytes, more than the 2147483648 bytes a CSV table may "
               "have"});
  expectError([&] { requireInputSize(nav, "a noise model", kMaxNoiseModelFileBytes); },
              {"nav.csv: is 21474836480 bytes, more than the 1073741824 bytes a noise model"});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  test::writeText(nav, "time_s\n1\n");
  expectError([&] { readInputFile(nav, "a CSV table", 5); }, {"is 9 bytes, more than the 5"});
  EXPECT_EQ(readInputFile(nav, "a CSV table", 9), "time_s\n1\n");
}

TEST(InputFile, ReadsAWholeFileAndSkipsAByteOrderMark) {
  ScratchDir dir;
  const std::string text = "\xEF\xBB\xBFtime_s,north_m\n1,2\n";
  test::writeText(dir.path() / "nav.csv", text);
  EXPECT_EQ(readInputFile(dir.path() / "nav.csv", "a CSV table", 1000), text);
  EXPECT_EQ(withoutByteOrderMark(text), "time_s,north_m\n1,2\n");
  EXPECT_EQ(withoutByteOrderMark("time_s"), "time_s");
  EXPECT_EQ(withoutByteOrderMark("\xEF\xBB"), "\xEF\xBB");
}

// Runs `body` in a child process; returns its exit status, or -signal.
template <typename Body>
int inChild(Body body) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::_exit(body());
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

TEST(AtomicFile, AFullDiskFailsTheWriteAndKeepsThePreviousFile) {
  ScratchDir dir;
  const auto target = dir.path() / "mesh.obj";
  writeFileAtomically(target, "previous");
  const std::string big(64 * 1024, 'v');
  // A file size limit makes write() fail with EFBIG as a full disk fails with ENOSPC.
  const int status = inChild([&] {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{16 * 1024, 16 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      writeFileAtomically(target, big);
    } catch (const Error& e) {
      const std::string what = e.what();
      return what.find("mesh.obj: byte 16384: write failed: File too large") != std::string::npos
                 ? 3
                 : 4;
    }
    return 5;
  });
  EXPECT_EQ(status, 3) << "3: failed as expected, 4: another message, 5: no error";
  EXPECT_EQ(test::readText(target), "previous");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(AtomicFile, AKillDuringTheWriteLeavesThePreviousFile) {
  ScratchDir dir;
  const auto target = dir.path() / "ground_truth.ply";
  writeFileAtomically(target, "previous");
  const std::string big(256 * 1024 * 1024, 'v');  // allocated before the fork
  const pid_t child = ::fork();
  if (child == 0) {
    writeFileAtomically(target, big);
    ::_exit(0);
  }
  const auto temporary = dir.path() / (".ground_truth.ply.tmp-" + std::to_string(child));
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!std::filesystem::exists(temporary) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the write finished before the kill: make it larger";
  EXPECT_EQ(test::readText(target), "previous");
}

// The names in a folder, dot files (temporary files, locks) included.
std::vector<std::string> namesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(AtomicFile, RefusesAFifoAndLeavesIt) {
  ScratchDir dir;
  const auto fifo = dir.path() / "mesh.ply";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectError([&] { writeFileAtomically(fifo, "mesh"); },
              {"mesh.ply: is a FIFO (named pipe): expected a regular file or a new path"});
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"mesh.ply"});  // no temporary file
}

TEST(AtomicFile, RefusesDevNullAndLeavesIt) {
  struct stat before {};
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  expectError([&] { writeFileAtomically("/dev/null", "mesh"); },
              {"/dev/null: is a device: expected a regular file or a new path"});
  expectError([&] { (void)outputFileTarget("/dev/null"); }, {"/dev/null: is a device"});
  struct stat after {};
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_rdev, before.st_rdev);
  EXPECT_EQ(after.st_ino, before.st_ino);
  // Nor through a link to it.
  ScratchDir dir;
  std::filesystem::create_symlink("/dev/null", dir.path() / "out.ply");
  expectError([&] { writeFileAtomically(dir.path() / "out.ply", "mesh"); },
              {"out.ply: is a symbolic link to /dev/null, which is a device: expected a regular "
               "file or a new path"});
  EXPECT_TRUE(std::filesystem::is_symlink(dir.path() / "out.ply"));
}

TEST(AtomicFile, RefusesAFolder) {
  ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "mesh.ply");
  expectError([&] { writeFileAtomically(dir.path() / "mesh.ply", "mesh"); },
              {"mesh.ply: is a directory: expected a regular file or a new path"});
}

// A symbolic link is written through: the link stays, the file it leads to gets the content,
// replaced by a temporary file beside it (in its own folder, here another one).
TEST(AtomicFile, WritesThroughASymbolicLink) {
  ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "runs");
  std::filesystem::create_directories(dir.path() / "latest");
  const auto file = dir.path() / "runs/mesh.ply";
  test::writeText(file, "old");
  const auto link = dir.path() / "latest/mesh.ply";
  std::filesystem::create_symlink("../runs/mesh.ply", link);
  const auto chained = dir.path() / "mesh.ply";  // a link to the link
  std::filesystem::create_symlink("latest/mesh.ply", chained);
  EXPECT_EQ(outputFileTarget(link), dir.path() / "latest/../runs/mesh.ply");

  writeFileAtomically(link, "new");
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(std::filesystem::read_symlink(link), "../runs/mesh.ply");
  EXPECT_EQ(test::readText(file), "new");
  writeFileAtomically(chained, "newer");
  EXPECT_TRUE(std::filesystem::is_symlink(chained));
  EXPECT_EQ(test::readText(file), "newer");
  EXPECT_EQ(namesIn(dir.path() / "runs"), std::vector<std::string>{"mesh.ply"});
  EXPECT_EQ(namesIn(dir.path() / "latest"), std::vector<std::string>{"mesh.ply"});
}

TEST(AtomicFile, RefusesADanglingLinkAndALoop) {
  ScratchDir dir;
  const auto dangling = dir.path() / "mesh.ply";
  std::filesystem::create_symlink("missing/mesh.ply", dangling);
  expectError([&] { writeFileAtomically(dangling, "mesh"); },
              {"mesh.ply: is a symbolic link to",
               "missing/mesh.ply, which is missing: expected a "
               "regular file or a new path"});
  EXPECT_TRUE(std::filesystem::is_symlink(dangling));
  EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"mesh.ply"});
  std::filesystem::create_symlink("b", dir.path() / "a");
  std::filesystem::create_symlink("a", dir.path() / "b");
  expectError([&] { writeFileAtomically(dir.path() / "a", "mesh"); },
              {"a: is a symbolic link to", "which is a loop of symbolic links"});
}

TEST(OutputFolder, RefusesWhatIsNotAFolder) {
  ScratchDir dir;
  const auto fifo = dir.path() / "sim";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectError([&] { prepareOutputFolder(fifo); },
              {"sim: is a FIFO (named pipe): expected a folder or a new path"});
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  test::writeText(dir.path() / "file", "kept");
  expectError([&] { requireOutputFolder(dir.path() / "file"); },
              {"file: is a regular file: expected a folder or a new path"});
  expectError([&] { requireOutputFolder("/dev/null"); },
              {"/dev/null: is a device: expected a folder or a new path"});
  std::filesystem::create_symlink("nowhere", dir.path() / "link");
  expectError([&] { requireOutputFolder(dir.path() / "link"); },
              {"link: is a symbolic link that leads nowhere"});
  requireOutputFolder(dir.path() / "new");  // a new path: nothing made yet
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "new"));
  std::filesystem::create_symlink(dir.path(), dir.path() / "here");
  requireOutputFolder(dir.path() / "here");
}

TEST(OutputFolder, HoldingOneFileRefusesAFifoOrAMissingFolderFirst) {
  ScratchDir dir;
  expectError([&] { (void)holdOutputFile("/dev/null"); }, {"/dev/null: is a device"});
  expectError([&] { (void)holdOutputFile(dir.path() / "missing/noise.yaml"); },
              {"noise.yaml: cannot create a file in", "missing: No such file or directory"});
  EXPECT_NE(holdOutputFile(dir.path() / "noise.yaml"), nullptr);
}

TEST(OutputFolderLock, ASecondHoldFailsNamingTheHolderAndNoFileIsLeft) {
  ScratchDir dir;
  const auto out = dir.path() / "out";
  prepareOutputFolder(out);
  const std::string holder = "(pid " + std::to_string(::getpid()) + ")";
  {
    const OutputFolderLock first(out);
    EXPECT_TRUE(first.held());
    expectError([&] { OutputFolderLock second(out); },
                {"out: is being written by another sonarcarve run " + holder});
    expectError([&] { OutputFolderLock reader(out, FolderUse::Shared); },
                {"is being written by another sonarcarve run"});
  }
  {
    // Commands writing one file each share it, and keep a run out meanwhile.
    const OutputFolderLock a(out, FolderUse::Shared);
    const OutputFolderLock b(out, FolderUse::Shared);
    expectError([&] { OutputFolderLock run(out); }, {"is being written by another sonarcarve run"});
  }
  // Released on an error as on a normal end (the object dies with the scope).
  EXPECT_THROW(
      {
        const OutputFolderLock failing(out);
        throw Error("out", "", "the run fails");
      },
      Error);
  const OutputFolderLock again(out);
  EXPECT_TRUE(namesIn(out).empty());  // the lock leaves no file behind
}

TEST(OutputFolderLock, IsReleasedWhenItsProcessIsKilled) {
  ScratchDir dir;
  const auto out = dir.path() / "out";
  prepareOutputFolder(out);
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    const OutputFolderLock held(out);
    (void)!::write(ready[1], "x", 1);
    ::pause();
    ::_exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  expectError([&] { OutputFolderLock second(out); }, {"(pid " + std::to_string(child) + ")"});
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  ::close(ready[0]);
  ::close(ready[1]);
  const OutputFolderLock after(out);
  EXPECT_TRUE(after.held());
}

}  // namespace
}  // namespace sonarcarve
