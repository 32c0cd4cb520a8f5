// The two file primitives every reader and writer goes through: io/files/input_file.h (only regular
// files are read) and io/files/atomic_file.h (a write either completes or leaves the previous
// file).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "common/error.h"
#include "io/files/atomic_file.h"
#include "io/files/input_file.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::expectError;
using test::ScratchDir;

TEST(InputFile, RefusesWhatIsNotARegularFile) {
  ScratchDir dir;
  const auto fifo = dir.path() / "nav.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectError([&] { readInputFile(fifo, "a CSV table"); },
              {"nav.csv: is a FIFO (named pipe): expected a regular file (a CSV table)"});
  expectError([&] { readInputFile(dir.path(), "a frame"); },
              {dir.path().string() + ": is a directory: expected a regular file (a frame)"});
  expectError([&] { requireRegularFile("/dev/zero", "a mesh"); },
              {"/dev/zero: is a device: expected a regular file (a mesh)"});
  expectError([&] { readInputFile(dir.path() / "missing.yaml", "a YAML file"); },
              {"missing.yaml: not found: expected a YAML file"});
}

TEST(InputFile, ReadsAWholeFileAndSkipsAByteOrderMark) {
  ScratchDir dir;
  const std::string text = "\xEF\xBB\xBFtime_s,north_m\n1,2\n";
  test::writeText(dir.path() / "nav.csv", text);
  EXPECT_EQ(readInputFile(dir.path() / "nav.csv", "a CSV table"), text);
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

}  // namespace
}  // namespace sonarcarve
