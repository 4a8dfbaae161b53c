// The cards of the relax report that harness.json's clearance, motion and tolerance settings
// add, over every input of the run.
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/output/relax_file.h"

namespace cablefit::addin {

/// The "Clearance" card: every violation of every input, or one line saying there is none (and
/// how many pairs were measured).
std::string ClearanceReportSection(const std::vector<RelaxedFile>& files);
/// The "Motion" card with its animation and slider (empty string when no input has a motion).
std::string MotionReportSection(const std::vector<RelaxedFile>& files);
/// The "Tolerance envelope" card (empty string when no input has tolerances).
std::string ToleranceReportSection(const std::vector<RelaxedFile>& files);

}  // namespace cablefit::addin
