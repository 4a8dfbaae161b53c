// Private: a numeric CSV table (header row + rows of numbers) with line-accurate errors, shared by
// the centreline and force-curve readers.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace cablefit::csv {

struct Table {
  std::vector<std::string> header;               // trimmed column names
  std::vector<std::vector<std::string>> cells;   // raw cells, one vector per data row
  std::vector<int> line;                         // 1-based file line of each data row
};

/// Reads `path` as comma-separated text. Blank lines are skipped; every data row must have as
/// many cells as the header. Throws FileError on unreadable files, an empty file or ragged rows.
Table ReadTable(const std::string& path);

/// Index of column `name`, or nullopt.
std::optional<int> FindColumn(const Table& table, const std::string& name);

/// The numeric value of row `row`, column `col`: throws FileError(path, "line N, column 'x': ...")
/// for empty, non-numeric, NaN or infinite cells.
double FiniteCell(const Table& table, const std::string& path, int row, int col);

/// True when the cell holds only spaces.
bool CellIsEmpty(const Table& table, int row, int col);

}  // namespace cablefit::csv
