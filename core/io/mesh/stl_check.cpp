#include "io/mesh/stl_check.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "common/error.h"

namespace sonarcarve {
namespace {

constexpr std::uintmax_t kHeaderBytes = 84;  // 80 bytes of text, u32 triangle count
constexpr std::uintmax_t kTriangleBytes = 50;

std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// VTK reads a file as ASCII only if its first 256 bytes are text; "solid" at the start is not
// enough (binary headers often begin so). The same rule here, so that both agree.
bool looksLikeText(const std::string& bytes) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 256);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c > 127 || (c < 32 && c != '\t' && c != '\n' && c != '\r')) {
      return false;
    }
  }
  return true;
}

}  // namespace

void checkStlFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string bytes = fileText(path);
  const std::uintmax_t size = bytes.size();
  std::uint32_t declared = 0;
  if (size >= kHeaderBytes) {
    std::memcpy(&declared, bytes.data() + 80, sizeof declared);
  }
  const std::uintmax_t binary_size = kHeaderBytes + kTriangleBytes * std::uintmax_t{declared};
  const auto first = bytes.find_first_not_of(" \t\r\n");
  const bool says_solid =
      first != std::string::npos && bytes.compare(first, 5, "solid") == 0 && looksLikeText(bytes);
  if (says_solid && !(size >= kHeaderBytes && size >= binary_size && declared > 0)) {
    if (bytes.find("endsolid") == std::string::npos) {
      throw Error(file, bytePlace(size), "truncated ASCII STL: expected 'endsolid' at the end");
    }
    return;
  }
  if (size < kHeaderBytes) {
    throw Error(file, bytePlace(size),
                "truncated binary STL: expected an 80-byte header and a triangle count (84 "
                "bytes), the file has " +
                    std::to_string(size));
  }
  if (size < binary_size) {
    throw Error(file, bytePlace(size),
                "truncated binary STL: the header declares " + std::to_string(declared) +
                    " triangles (84 + 50 x " + std::to_string(declared) + " = " +
                    std::to_string(binary_size) + " bytes), the file has " + std::to_string(size));
  }
}

}  // namespace sonarcarve
