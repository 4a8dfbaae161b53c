// The pictures of a case report: deviation colour maps (nominal above fitted, one colour scale,
// the blamed interval or clamp highlighted, sub-sampled scan points), deviation along arc length
// with the unseen stretches shaded, and force curves (recorded, nominal, fitted, loop shaded).
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/diagnose/diagnose_case.h"

namespace cablefit::addin {

struct CasePicture {
  std::string file;     // PNG name inside the case folder
  std::string caption;  // one sentence for the report
};

/// Renders and writes the pictures of `d` into `dir`, returning them in report order. The 3-D
/// renderer (OSMesa) is entered by one thread at a time, so workers of a batch may call this
/// concurrently.
std::vector<CasePicture> WriteCasePictures(const std::string& dir, const DiagnosedCase& d);

}  // namespace cablefit::addin
