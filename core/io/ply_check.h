// A check of a PLY file's header and size before VTK's reader sees it: VTK 9.1's PLY reader
// crashes on a header without `end_header` and reads truncated bodies silently. Throws Error
// naming the file, the line or byte offset, and what was expected.
#pragma once

#include <filesystem>
#include <string>

namespace sonarcarve {

void checkPlyFile(const std::filesystem::path& path);

/// Bytes of a PLY scalar type ("float", "uchar", "int32", ...), 0 for an unknown type.
int plyTypeSize(const std::string& type);

}  // namespace sonarcarve
