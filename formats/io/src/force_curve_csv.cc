#include "cablefit/formats/force_curve_csv.h"

#include "cablefit/core/base/errors.h"
#include "cablefit/formats/atomic_file.h"
#include "cablefit/formats/number_text.h"
#include "csv_table.h"

namespace cablefit {
namespace {

struct ColumnPair {
  const char* x;
  const char* y;
};
constexpr ColumnPair kPairs[] = {{"displacement", "force"}, {"angle", "moment"}};

bool IsKnownPair(const std::string& x, const std::string& y) {
  for (const auto& p : kPairs)
    if (x == p.x && y == p.y) return true;
  return false;
}

}  // namespace

ForceCurve ReadForceCurveCsv(const std::string& path) {
  const csv::Table table = csv::ReadTable(path);
  const auto step_col = csv::FindColumn(table, "step");
  if (!step_col)
    throw FileError(path, "missing column 'step' (expected step,displacement,force or "
                          "step,angle,moment)");
  ForceCurve curve;
  int x_col = -1, y_col = -1;
  for (const auto& p : kPairs) {
    const auto x = csv::FindColumn(table, p.x);
    const auto y = csv::FindColumn(table, p.y);
    if (x || y) {
      if (!x) throw FileError(path, std::string("missing column '") + p.x + "' next to '" + p.y + "'");
      if (!y) throw FileError(path, std::string("missing column '") + p.y + "' next to '" + p.x + "'");
      curve.x_name = p.x;
      curve.y_name = p.y;
      x_col = *x;
      y_col = *y;
      break;
    }
  }
  if (x_col < 0)
    throw FileError(path, "missing data columns (expected displacement,force or angle,moment)");

  const int n = static_cast<int>(table.cells.size());
  if (n < 2) throw FileError(path, "has " + std::to_string(n) + " row(s), a force curve needs at least 2");
  curve.step.resize(n);
  curve.x.resize(n);
  curve.y.resize(n);
  for (int i = 0; i < n; ++i) {
    long step = 0;
    if (!ParseInteger(table.cells[i][*step_col], &step))
      throw FileError(path, "line " + std::to_string(table.line[i]) +
                                ", column 'step' is not an integer: '" +
                                table.cells[i][*step_col] + "'");
    curve.step[i] = step;
    curve.x[i] = csv::FiniteCell(table, path, i, x_col);
    curve.y[i] = csv::FiniteCell(table, path, i, y_col);
  }
  return curve;
}

void WriteForceCurveCsv(const std::string& path, const ForceCurve& curve) {
  if (!IsKnownPair(curve.x_name, curve.y_name))
    throw FileError(path, "cannot write force curve with columns '" + curve.x_name + "," +
                              curve.y_name + "' (expected displacement,force or angle,moment)");
  const auto n = curve.x.size();
  if (curve.y.size() != n || (!curve.step.empty() && curve.step.size() != static_cast<size_t>(n)))
    throw FileError(path, "cannot write force curve: columns have different lengths");
  if (!curve.x.allFinite() || !curve.y.allFinite())
    throw FileError(path, "cannot write force curve: it holds non-finite values");
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "step," << curve.x_name << ',' << curve.y_name << '\n';
    for (Eigen::Index i = 0; i < n; ++i) {
      out << (curve.step.empty() ? static_cast<long>(i) : curve.step[i]) << ','
          << FormatDouble(curve.x[i]) << ',' << FormatDouble(curve.y[i]) << '\n';
    }
  });
}

}  // namespace cablefit
