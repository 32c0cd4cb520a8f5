#include "io/files/csv_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "common/error.h"
#include "common/input_limits.h"
#include "io/files/input_file.h"

namespace sonarcarve {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) {
    return {};
  }
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> splitCells(const std::string& line, char delimiter) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(delimiter, start);
    cells.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string::npos) {
      return cells;
    }
    start = comma + 1;
  }
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path, const CsvOptions& options) {
  return parse(readInputFile(path, "a CSV table", kMaxTableFileBytes), path.string(), options);
}

CsvTable CsvTable::parse(std::string_view text, std::string file, const CsvOptions& options) {
  CsvTable table;
  table.file_ = std::move(file);
  text = withoutByteOrderMark(text);
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t newline = text.find('\n', start);
    const std::string line(text.substr(
        start, newline == std::string_view::npos ? text.size() - start : newline - start));
    start = newline == std::string_view::npos ? text.size() : newline + 1;
    ++line_number;
    const std::string content = trim(line);
    if (content.empty() || content.front() == '#') {
      continue;
    }
    if (line.find('\0') != std::string::npos) {
      throw Error(table.file_, linePlace(line_number), "binary data in a text file");
    }
    auto cells = splitCells(content, options.delimiter);
    if (table.header_.empty()) {
      table.header_line_ = line_number;
      if (options.header) {
        table.header_ = std::move(cells);
        continue;
      }
      for (std::size_t i = 0; i < cells.size(); ++i) {
        table.header_.push_back(std::to_string(i));
      }
    }
    if (cells.size() != table.header_.size()) {
      throw Error(table.file_, linePlace(line_number),
                  "expected " + std::to_string(table.header_.size()) + " values, found " +
                      std::to_string(cells.size()));
    }
    table.rows_.push_back(Row{line_number, std::move(cells)});
  }
  if (table.header_.empty()) {
    throw Error(table.file_, "",
                options.header ? "file is empty: expected a header line of column names"
                               : "file is empty: expected lines of values");
  }
  return table;
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) {
      return i;
    }
  }
  throw Error(file_, linePlace(header_line_), "missing column '" + name + "'");
}

bool CsvTable::has(const std::string& name) const {
  return std::find(header_.begin(), header_.end(), name) != header_.end();
}

std::string CsvTable::headerPlace() const {
  return linePlace(header_line_);
}

const std::string& CsvTable::text(const Row& row, std::size_t column) const {
  return row.cells.at(column);
}

double CsvTable::number(const Row& row, std::size_t column) const {
  const std::string& cell = row.cells.at(column);
  double value = 0.0;
  const char* end = cell.data() + cell.size();
  const auto [ptr, ec] = std::from_chars(cell.data(), end, value);
  if (cell.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw Error(file_, linePlace(row.line),
                "column '" + header_[column] + "': expected a finite number, found '" + cell + "'");
  }
  return value;
}

}  // namespace sonarcarve
