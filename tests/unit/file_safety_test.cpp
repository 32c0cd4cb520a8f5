// The file primitive every reader goes through: io/input_file.h (only regular files are read).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "common/error.h"
#include "io/input_file.h"
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

}  // namespace
}  // namespace sonarcarve
