#include "cablefit/formats/centerline_csv.h"

#include <charconv>

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/number_text.h"
#include "csv_table.h"

namespace cablefit {

Polyline ReadCenterlineCsv(const std::string& path) {
  const csv::Table table = csv::ReadTable(path);
  int xyz[3];
  const char* names[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const auto col = csv::FindColumn(table, names[k]);
    if (!col)
      throw FileError(path, std::string("missing column '") + names[k] +
                                "' (expected header s,x,y,z or x,y,z)");
    xyz[k] = *col;
  }
  const int n = static_cast<int>(table.cells.size());
  if (n < 2)
    throw FileError(path, "has " + std::to_string(n) + " point(s), a centreline needs at least 2");

  Polyline line;
  line.points.resize(3, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) line.points(k, i) = csv::FiniteCell(table, path, i, xyz[k]);

  const auto s_col = csv::FindColumn(table, "s");
  int given = 0;
  if (s_col)
    for (int i = 0; i < n; ++i) given += csv::CellIsEmpty(table, i, *s_col) ? 0 : 1;
  if (given == 0) {
    line.ParameteriseByChords(0.0);
    return line;
  }
  if (given != n)
    throw FileError(path, "column 's' is filled in " + std::to_string(given) + " of " +
                              std::to_string(n) + " rows (give it in every row or in none)");
  line.s.resize(n);
  for (int i = 0; i < n; ++i) {
    line.s[i] = csv::FiniteCell(table, path, i, *s_col);
    if (i > 0 && line.s[i] < line.s[i - 1])
      throw FileError(path, "line " + std::to_string(table.line[i]) + ": s decreases from " +
                                FormatDouble(line.s[i - 1]) + " to " + FormatDouble(line.s[i]));
  }
  return line;
}

void WriteCenterlineCsv(const std::string& path, const Polyline& line) {
  const bool has_s = line.s.size() > 0;
  if (has_s && line.s.size() != line.points.cols())
    throw FileError(path, "cannot write centreline: " + std::to_string(line.s.size()) +
                              " arc lengths for " + std::to_string(line.points.cols()) + " points");
  if (!line.points.allFinite() || (has_s && !line.s.allFinite()))
    throw FileError(path, "cannot write centreline: it holds non-finite values");
  // One buffer, numbers written straight into it: a simulate writes 1600 of them.
  std::string text = "s,x,y,z\n";
  text.reserve(text.size() + static_cast<size_t>(line.size()) * 100);
  char buf[32];
  auto number = [&](double v) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    text.append(buf, r.ptr);
  };
  for (int i = 0; i < line.size(); ++i) {
    if (has_s) number(line.s[i]);
    for (int k = 0; k < 3; ++k) {
      text += ',';
      number(line.points(k, i));
    }
    text += '\n';
  }
  WriteFileAtomically(path, text);
}

}  // namespace cablefit
