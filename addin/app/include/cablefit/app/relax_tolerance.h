// The tolerance envelope of harness.json "tolerances": every relaxed single-rod cable solved at
// each corner of its length x bending stiffness x density box (2^k corners for k varied
// quantities), and its largest excursion from the nominal shape (same relative arc length).
// Corners bound the envelope when the shape moves monotonically with each quantity; that is
// checked, not assumed: a few interior points of the box (fixed pseudo-random) are solved too,
// and the output says whether any went further than the corners.
#pragma once

#include <string>
#include <vector>

#include "cablefit/app/harness_config.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// One varied set-up: the relative change of each quantity and how far the shape went.
struct ToleranceCase {
  double length = 0.0, bending_stiffness = 0.0, linear_density = 0.0;  ///< signed fractions
  bool converged = false;
  double excursion = 0.0;     ///< [m] largest distance to the nominal shape at the same s / L
  double s = 0.0;             ///< [m] nominal arc length where it is largest
  Vec3 point = Vec3::Zero();  ///< [m] the varied cable's point there
  Polyline centreline;        ///< the varied relaxed shape (s [m], 3 x n [m]); empty if not converged
};

struct CableTolerance {
  int cable = 0;
  std::string name;
  std::vector<ToleranceCase> corners, interior;
  int worst_corner = -1;        ///< index into corners, -1 when none converged
  bool interior_within = true;  ///< no interior case went further than the worst corner
  double seconds = 0.0;
};

struct FileTolerance {
  ToleranceConfig config;
  std::vector<CableTolerance> cables;
  std::vector<std::string> problems;  ///< cables not varied, and why
};

/// `spec` with its length changed by the fraction `length` (support, load and curvature arc
/// lengths scaled with it, positions kept), EI and GJ by `stiffness`, mass by `density`.
RodSpec VariedSpec(const RodSpec& spec, double length, double stiffness, double density);

/// Pseudo-random interior points of the box solved to check the corners cover it.
inline constexpr int kInteriorChecks = 8;

struct RelaxedFile;
/// Runs the envelope on every relaxed cable of `f` solved alone (not a network).
void RunFileTolerance(const HarnessConfig& config, const SimulationOptions& options,
                      RelaxedFile* f);

json::Json CableToleranceToJson(const CableTolerance& t);
/// One line per varied cable (and per problem) for stdout and the report.
std::vector<std::string> ToleranceLines(const FileTolerance& t);
/// The report's "Tolerance envelope" card (empty string when no input has tolerances).
std::string ToleranceReportSection(const std::vector<RelaxedFile>& files);

}  // namespace cablefit::addin
