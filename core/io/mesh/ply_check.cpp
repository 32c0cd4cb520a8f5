#include "io/mesh/ply_check.h"

#include <charconv>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.h"
#include "io/files/input_file.h"

namespace sonarcarve {
int plyTypeSize(const std::string& type) {
  static const std::map<std::string, int> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

PlyHeader checkPlyFile(const std::filesystem::path& path) {
  const auto bytesOf = [](const std::string& type) {
    return static_cast<std::uint64_t>(plyTypeSize(type));
  };
  const std::string file = path.string();
  requireRegularFile(path, "a PLY file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw Error(file, "", "cannot open PLY file");
  }
  std::error_code size_error;
  const std::uint64_t file_size = std::filesystem::file_size(path, size_error);
  if (size_error) {
    throw Error(file, "", "cannot open PLY file: " + size_error.message());
  }
  std::string line;
  int line_number = 0;
  const auto fail = [&](const std::string& what) {
    throw Error(file, "line " + std::to_string(line_number), what);
  };
  if (!std::getline(in, line) || (++line_number, line.rfind("ply", 0) != 0)) {
    throw Error(file, "byte 0", "not a PLY file: expected 'ply' on the first line");
  }
  PlyHeader header;
  std::string& format = header.format;
  std::vector<PlyElement>& elements = header.elements;
  bool ended = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      words >> format;
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian") {
        fail("unknown PLY format '" + format + "'");
      }
    } else if (keyword == "element") {
      PlyElement e;
      std::string count;
      if (!(words >> e.name >> count)) {
        fail("expected 'element NAME COUNT'");
      }
      // Every element takes at least a byte of the body: a count above the file's size is
      // corrupt (and would overflow the size checks below).
      const char* end = count.data() + count.size();
      const auto [ptr, ec] = std::from_chars(count.data(), end, e.count);
      if (ec != std::errc() || ptr != end || e.count > file_size) {
        fail("element '" + e.name + "': count '" + count +
             "' is not a whole number within the file's size");
      }
      elements.push_back(e);
    } else if (keyword == "property") {
      if (elements.empty()) {
        fail("property before any element");
      }
      std::string type;
      words >> type;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type;
        std::string name;
        words >> name;
        if (bytesOf(count_type) == 0 || bytesOf(item_type) == 0) {
          fail("unknown list property types");
        }
        elements.back().properties.push_back({name, item_type, true, count_type});
      } else {
        std::string name;
        words >> name;
        if (bytesOf(type) == 0) {
          fail("unknown property type '" + type + "'");
        }
        elements.back().properties.push_back({name, type, false, ""});
      }
    } else if (keyword == "end_header") {
      ended = true;
      break;
    } else if (keyword == "comment") {
      const std::size_t text = line.find_first_not_of(" \t", line.find("comment") + 7);
      header.comments.push_back(text == std::string::npos ? "" : line.substr(text));
    } else if (keyword != "obj_info" && !keyword.empty()) {
      fail("unexpected header line '" + line + "'");
    }
  }
  if (!ended) {
    throw Error(file, "line " + std::to_string(line_number),
                "truncated PLY header: expected 'end_header'");
  }
  if (format.empty()) {
    throw Error(file, "", "PLY header has no 'format' line");
  }
  const auto body_start = static_cast<std::uint64_t>(in.tellg());
  header.body_offset = body_start;
  const std::uint64_t size = file_size;
  if (format == "ascii") {
    std::uint64_t needed = 0;
    for (const auto& e : elements) {
      needed += e.count;
    }
    std::uint64_t lines = 0;
    while (lines < needed && std::getline(in, line)) {
      if (line.find_first_not_of(" \t\r") != std::string::npos) {
        ++lines;
      }
    }
    if (lines < needed) {
      throw Error(file, bytePlace(size),
                  "truncated PLY: expected " + std::to_string(needed) + " element lines, found " +
                      std::to_string(lines));
    }
    return header;
  }
  // Lower bound of the body's size: lists counted as triangles (a count and three items).
  std::uint64_t needed = 0;
  for (const auto& e : elements) {
    std::uint64_t record = 0;
    for (const auto& p : e.properties) {
      record += p.list ? bytesOf(p.count_type) + 3 * bytesOf(p.type) : bytesOf(p.type);
    }
    needed += e.count * record;
  }
  if (size < body_start + needed) {
    throw Error(file, bytePlace(size),
                "truncated PLY: the header declares at least " + std::to_string(needed) +
                    " bytes of data after byte " + std::to_string(body_start));
  }
  return header;
}

}  // namespace sonarcarve
