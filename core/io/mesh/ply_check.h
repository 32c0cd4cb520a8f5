// A check of a PLY file's header and size before VTK's reader sees it: VTK 9.1's PLY reader
// crashes on a header without `end_header` and reads truncated bodies silently. Throws Error
// naming the file, the line or byte offset, and what was expected.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sonarcarve {

struct PlyProperty {
  std::string name;
  std::string type;  ///< scalar type, or the item type of a list
  bool list = false;
  std::string count_type;  ///< lists: the type of the item count
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::string format;  ///< ascii | binary_little_endian | binary_big_endian
  std::vector<PlyElement> elements;
  std::uint64_t body_offset = 0;      ///< byte where the data starts
  std::vector<std::string> comments;  ///< the text of its `comment` lines, in order
};

/// Returns the parsed header of a file that passed the checks.
PlyHeader checkPlyFile(const std::filesystem::path& path);

/// Bytes of a PLY scalar type ("float", "uchar", "int32", ...), 0 for an unknown type.
int plyTypeSize(const std::string& type);

}  // namespace sonarcarve
