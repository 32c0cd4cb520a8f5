// An STL file checked before VTK's reader sees it: VTK reads a binary STL cut short as the
// triangles it holds, without a word, and reports a broken one with its own source line. A
// binary STL must hold the 84-byte header and the 50 bytes of every triangle it declares; an
// ASCII STL ("solid ...") must reach its "endsolid". A binary STL holding more triangles than it
// declares is refused too: VTK reads what the file's size holds, whatever the count says (a
// count of 1 before 1000 triangles, or before a hole of zeros in a sparse file).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

namespace sonarcarve {

/// Throws Error naming the file, the byte and what was expected if `path` is a binary STL
/// shorter or (by a triangle or more) longer than its triangle count says, shorter than its
/// header, or an ASCII STL without "endsolid". Returns the triangles a binary STL declares,
/// nothing for an ASCII one. Only an ASCII STL is read whole.
std::optional<std::uint32_t> checkStlFile(const std::filesystem::path& path);

}  // namespace sonarcarve
