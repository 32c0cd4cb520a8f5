// An STL file checked before VTK's reader sees it: VTK reads a binary STL cut short as the
// triangles it holds, without a word, and reports a broken one with its own source line. A
// binary STL must hold the 84-byte header and the 50 bytes of every triangle it declares; an
// ASCII STL ("solid ...") must reach its "endsolid".
#pragma once

#include <filesystem>

namespace sonarcarve {

/// Throws Error naming the file, the byte and what was expected if `path` is a binary STL
/// shorter than its triangle count says, shorter than its header, or an ASCII STL without
/// "endsolid".
void checkStlFile(const std::filesystem::path& path);

}  // namespace sonarcarve
