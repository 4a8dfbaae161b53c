// Force-curve CSV (recording-v1.md): `step,displacement,force` (pinned bending) or
// `step,angle,moment` (clamped torsion), rows in recorded order.
#pragma once

#include <string>

#include "cablefit/core/rod/recording_case.h"

namespace cablefit {

/// Reads a force curve; the column pair (displacement/force or angle/moment) is recognised from
/// the header, `step` must hold integers. Throws FileError for a missing column, empty,
/// non-numeric, NaN or infinite cells, or fewer than 2 rows.
ForceCurve ReadForceCurveCsv(const std::string& path);

/// Writes `curve` atomically as `step,<x_name>,<y_name>`; rows without a step are numbered from
/// 0 when `curve.step` is empty. Throws FileError for unknown column names, mismatched sizes or
/// non-finite values.
void WriteForceCurveCsv(const std::string& path, const ForceCurve& curve);

}  // namespace cablefit
