// CsvTable: a small, strict reader for the comma-separated files of the mission format.
// The first non-comment line is the header of named columns; lines starting with '#' and
// blank lines are skipped. Every value lookup that fails throws an Error naming the file,
// the line and the column.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sonarcarve {

struct CsvOptions {
  char delimiter = ',';
  /// Without a header line, the columns are named by their 0-based index: "0", "1", ...
  bool header = true;
};

class CsvTable {
 public:
  struct Row {
    int line = 0;  ///< 1-based line number in the file
    std::vector<std::string> cells;
  };

  /// Reads the whole file. Throws Error if it is missing, empty (no header) or a row has a
  /// different number of cells than the header.
  static CsvTable read(const std::filesystem::path& path, const CsvOptions& options = {});
  /// The same from text in memory; `file` names it in messages.
  static CsvTable parse(std::string_view text, std::string file, const CsvOptions& options = {});

  const std::string& file() const { return file_; }
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<Row>& rows() const { return rows_; }

  /// Index of a column; throws Error naming the missing column and the header line.
  std::size_t column(const std::string& name) const;
  /// Whether the header names the column.
  bool has(const std::string& name) const;
  /// The header's line, as an Error place ("line 3").
  std::string headerPlace() const;
  /// A finite number; throws Error on text, NaN or infinity.
  double number(const Row& row, std::size_t column) const;
  const std::string& text(const Row& row, std::size_t column) const;

 private:
  std::string file_;
  int header_line_ = 0;
  std::vector<std::string> header_;
  std::vector<Row> rows_;
};

}  // namespace sonarcarve
