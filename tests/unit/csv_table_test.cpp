#include <gtest/gtest.h>

#include "common/error.h"
#include "io/files/csv_table.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

using test::ScratchDir;
using test::writeText;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(CsvTable, ReadsNamedColumnsSkippingCommentsAndBlankLines) {
  ScratchDir dir;
  writeText(dir.path() / "a.csv", "# comment\n\na_m, b_deg\n1.5,2\n\n-3e2 , 4\n");
  const CsvTable t = CsvTable::read(dir.path() / "a.csv");
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[1].line, 6);
  EXPECT_DOUBLE_EQ(t.number(t.rows()[0], t.column("a_m")), 1.5);
  EXPECT_DOUBLE_EQ(t.number(t.rows()[1], t.column("a_m")), -300.0);
  EXPECT_DOUBLE_EQ(t.number(t.rows()[1], t.column("b_deg")), 4.0);
}

TEST(CsvTable, ErrorsNameFileLineAndColumn) {
  ScratchDir dir;
  const auto f = dir.path() / "b.csv";
  writeText(f, "x,y\n1,nan\n");
  const CsvTable t = CsvTable::read(f);
  const std::string nan_error = errorOf([&] { t.number(t.rows()[0], t.column("y")); });
  EXPECT_NE(nan_error.find("b.csv: line 2: column 'y'"), std::string::npos) << nan_error;
  const std::string missing = errorOf([&] { t.column("z"); });
  EXPECT_NE(missing.find("line 1: missing column 'z'"), std::string::npos) << missing;

  writeText(f, "x,y\n1,2\n3\n");
  EXPECT_NE(errorOf([&] { CsvTable::read(f); }).find("line 3: expected 2 values, found 1"),
            std::string::npos);
  writeText(f, "");
  EXPECT_NE(errorOf([&] { CsvTable::read(f); }).find("file is empty"), std::string::npos);
  writeText(f, std::string("x,y\n1,\0\n", 8));
  EXPECT_NE(errorOf([&] { CsvTable::read(f); }).find("binary data"), std::string::npos);
  EXPECT_NE(errorOf([&] {
              CsvTable::read(dir.path() / "none.csv");
            }).find("none.csv: not found: expected a CSV table"),
            std::string::npos);
  writeText(f, "x\n1.5abc\n");
  const CsvTable garbage = CsvTable::read(f);
  EXPECT_THROW(garbage.number(garbage.rows()[0], 0), Error);
  writeText(f, "x\ninf\n");
  const CsvTable inf = CsvTable::read(f);
  EXPECT_THROW(inf.number(inf.rows()[0], 0), Error);
}

}  // namespace
}  // namespace sonarcarve
