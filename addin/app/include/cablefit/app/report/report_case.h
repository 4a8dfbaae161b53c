// The HTML report of one diagnosed case (DIR/<case>/report.html): verdict, explanation, fitted
// parameters with units, every candidate with its score, the pictures, and the output files.
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/diagnose/diagnose_case.h"
#include "cablefit/app/report/report_pictures.h"

namespace cablefit::addin {

/// The whole page (self-contained: only relative links to files in the same folder).
std::string CaseReportHtml(const DiagnosedCase& d, const std::vector<CasePicture>& pictures);

/// Renders the pictures and writes report.html into `dir` (atomically).
void WriteCaseReport(const std::string& dir, const DiagnosedCase& d);

}  // namespace cablefit::addin
