// STL files checked before VTK reads them (io/mesh/stl_check.h): a binary STL cut short, one
// shorter than its header, an ASCII STL without its end; whole files pass.
#include <gtest/gtest.h>

#include <fstream>

#include "io/mesh/stl_check.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

std::string binaryStl(std::uint32_t declared, std::uint32_t present, const std::string& title) {
  std::string out = title;
  out.resize(80, ' ');
  out.append(reinterpret_cast<const char*>(&declared), 4);
  out.append(50 * static_cast<std::size_t>(present), '\0');
  return out;
}

std::filesystem::path write(const test::ScratchDir& dir, const std::string& bytes) {
  const auto path = dir.path() / "mesh.stl";
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(StlCheck, WholeFilesPass) {
  const test::ScratchDir dir;
  EXPECT_NO_THROW(checkStlFile(write(dir, binaryStl(3, 3, "made by a CAD tool"))));
  // Binary files whose header starts with "solid", as some exporters write them.
  EXPECT_NO_THROW(checkStlFile(write(dir, binaryStl(2, 2, "solid part"))));
  EXPECT_NO_THROW(checkStlFile(write(dir,
                                     "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 "
                                     "0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                                     "endsolid t\n")));
}

TEST(StlCheck, CutFilesNameTheByteAndWhatWasExpected) {
  const test::ScratchDir dir;
  test::expectError([&] { checkStlFile(write(dir, binaryStl(10, 1, "cut"))); },
                    {"mesh.stl: byte 134: truncated binary STL: the header declares 10 triangles",
                     "= 584 bytes), the file has 134"});
  test::expectError([&] { checkStlFile(write(dir, std::string(60, 's'))); },
                    {"mesh.stl: byte 60: truncated binary STL: expected an 80-byte header"});
  // "solid" and "endsolid" but bytes that are not text: VTK reads it as binary, and its count
  // (bytes 80 to 83) asked 6 GB (found by the mesh fuzzer).
  std::string not_text = "solid t\nvertex 2.1 ";
  not_text += std::string("\x01\x00\x00\x00\x00\xe6", 6);
  not_text.resize(112, 'x');
  not_text.replace(90, 10, "endsolid t");
  test::expectError([&] { checkStlFile(write(dir, not_text)); },
                    {"mesh.stl: byte 112: truncated binary STL: the header declares"});
  test::expectError([&] { checkStlFile(write(dir, "solid t\nfacet normal 0 0 1\nouter loop\n")); },
                    {"mesh.stl: byte 38: truncated ASCII STL: expected 'endsolid' at the end"});
}

// VTK reads as many triangles as the file's size holds: a count that says fewer (a triangle
// then a hole of zeros, two files joined) is refused; less than a triangle of trailing bytes
// is not one.
TEST(StlCheck, AFileLongerThanItsCountIsRefusedAndTheCountIsReturned) {
  const test::ScratchDir dir;
  test::expectError([&] { checkStlFile(write(dir, binaryStl(1, 1000, "joined"))); },
                    {"mesh.stl: byte 134: binary STL longer than its header says: the header "
                     "declares 1 triangles",
                     "the file has 50084, room for 1000 triangles"});
  EXPECT_EQ(checkStlFile(write(dir, binaryStl(3, 3, "whole") + std::string(49, '\0'))), 3U);
  EXPECT_EQ(checkStlFile(write(dir, "solid t\nendsolid t\n")), std::nullopt);
}

}  // namespace
}  // namespace sonarcarve
