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

std::string fileText(const std::filesystem::path& path, std::streamsize at_most) {
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(at_most), '\0');
  in.read(text.data(), at_most);
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
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

std::optional<std::uint32_t> checkStlFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::uintmax_t size = std::filesystem::file_size(path);
  const std::string head = fileText(path, 256);
  std::uint32_t declared = 0;
  if (size >= kHeaderBytes) {
    std::memcpy(&declared, head.data() + 80, sizeof declared);
  }
  const std::uintmax_t binary_size = kHeaderBytes + kTriangleBytes * std::uintmax_t{declared};
  const auto first = head.find_first_not_of(" \t\r\n");
  const bool says_solid =
      first != std::string::npos && head.compare(first, 5, "solid") == 0 && looksLikeText(head);
  if (says_solid && !(size >= kHeaderBytes && size >= binary_size && declared > 0)) {
    const std::string bytes = fileText(path, static_cast<std::streamsize>(size));
    if (bytes.find("endsolid") == std::string::npos) {
      throw Error(file, bytePlace(size), "truncated ASCII STL: expected 'endsolid' at the end");
    }
    return std::nullopt;
  }
  if (size < kHeaderBytes) {
    throw Error(file, bytePlace(size),
                "truncated binary STL: expected an 80-byte header and a triangle count (84 "
                "bytes), the file has " +
                    std::to_string(size));
  }
  const std::string declares = "the header declares " + std::to_string(declared) +
                               " triangles (84 + 50 x " + std::to_string(declared) + " = " +
                               std::to_string(binary_size) + " bytes), the file has " +
                               std::to_string(size);
  if (size < binary_size) {
    throw Error(file, bytePlace(size), "truncated binary STL: " + declares);
  }
  if (size - binary_size >= kTriangleBytes) {
    throw Error(file, bytePlace(binary_size),
                "binary STL longer than its header says: " + declares + ", room for " +
                    std::to_string((size - kHeaderBytes) / kTriangleBytes) +
                    " triangles: expected the count of the triangles it holds");
  }
  return declared;
}

}  // namespace sonarcarve
