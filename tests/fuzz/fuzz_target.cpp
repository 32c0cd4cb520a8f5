// A libFuzzer target: built once per reader with SONARCARVE_FUZZ_READER naming its function in
// fuzz_readers.h (tests/fuzz/CMakeLists.txt, docs/fuzzing.md).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_readers.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  sonarcarve::fuzz::SONARCARVE_FUZZ_READER({data, size});
  return 0;
}
