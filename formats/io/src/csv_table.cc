#include "csv_table.h"

#include <sstream>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/input_file.h"
#include "cablefit/formats/number_text.h"

namespace cablefit::csv {
namespace {

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> cells;
  std::string::size_type start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    cells.push_back(Trim(line.substr(start, comma == std::string::npos ? std::string::npos
                                                                         : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

}  // namespace

Table ReadTable(const std::string& path) {
  std::string text = ReadInputFile(path, kMaxTextInputBytes, "a CSV file");
  // Line ends of any convention: CR LF (Windows) is trimmed per cell; a lone CR (classic Mac OS,
  // some bench loggers) ends a line too, or the whole file would read as one header line.
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
  }
  std::istringstream in(text);
  Table table;
  std::string line;
  int line_no = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 BOM
    if (Trim(line).empty()) continue;
    std::vector<std::string> cells = Split(line);
    if (!have_header) {
      table.header = std::move(cells);
      have_header = true;
      continue;
    }
    if (cells.size() != table.header.size())
      throw FileError(path, "line " + std::to_string(line_no) + " has " +
                                std::to_string(cells.size()) + " cells but the header has " +
                                std::to_string(table.header.size()));
    table.cells.push_back(std::move(cells));
    table.line.push_back(line_no);
  }
  if (in.bad()) throw FileError(path, "read error");
  if (!have_header) throw FileError(path, "is empty (expected a CSV header line)");
  return table;
}

std::optional<int> FindColumn(const Table& table, const std::string& name) {
  for (std::size_t i = 0; i < table.header.size(); ++i)
    if (table.header[i] == name) return static_cast<int>(i);
  return std::nullopt;
}

bool CellIsEmpty(const Table& table, int row, int col) { return table.cells[row][col].empty(); }

double FiniteCell(const Table& table, const std::string& path, int row, int col) {
  const std::string& text = table.cells[row][col];
  const std::string where =
      "line " + std::to_string(table.line[row]) + ", column '" + table.header[col] + "'";
  double value = 0.0;
  switch (ParseDouble(text, &value)) {
    case ParsedNumber::kFinite: return value;
    case ParsedNumber::kNaN: throw FileError(path, where + " is NaN");
    case ParsedNumber::kInfinite: throw FileError(path, where + " is infinite ('" + text + "')");
    case ParsedNumber::kNotANumber: break;
  }
  if (text.empty()) throw FileError(path, where + " is empty");
  throw FileError(path, where + " is not a number: '" + text + "'");
}

}  // namespace cablefit::csv
