// Replays every input of the fuzz corpora (tests/fuzz/corpus/<target>/: the seeds and every
// input that once crashed a reader, docs/fuzzing.md) through the same entry points as the
// libFuzzer targets, in the ordinary build: each must be read or rejected with a
// sonarcarve::Error, never crash or throw anything else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>

#include "fuzz/fuzz_readers.h"

namespace sonarcarve {
namespace fuzz {
// Test names and failure messages show the target's name.
void PrintTo(const Target& target, std::ostream* os) {
  *os << target.name;
}
}  // namespace fuzz

namespace {

class FuzzRegression : public ::testing::TestWithParam<fuzz::Target> {};

TEST_P(FuzzRegression, EveryCorpusInputIsReadOrRejectedCleanly) {
  const auto folder = std::filesystem::path(SONARCARVE_FUZZ_CORPUS_DIR) / GetParam().name;
  ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
  std::size_t inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(GetParam().reader(bytes));
    ++inputs;
  }
  EXPECT_GT(inputs, 0u);
}

INSTANTIATE_TEST_SUITE_P(Readers, FuzzRegression, ::testing::ValuesIn(fuzz::targets()),
                         [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace sonarcarve
