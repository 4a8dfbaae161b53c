// The one C++ entry point of the FreeCAD workbench: relaxing the cables of a harness file and
// diagnosing a recording case through exactly the functions `cablefit relax` and `cablefit
// diagnose` call, returned as plain values. The Python module binds only this header, so a change
// of the relax/diagnose internals (addin/app) touches cablefit_facade.cc alone.
#pragma once

#include <array>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cablefit/core/base/geometry_types.h"
#include "cablefit/core/solver/statics_solver.h"

namespace cablefit::freecad {

/// One support of a relaxed cable as the solver used it.
struct SupportSummary {
  std::string kind;    ///< "clamp", "clip" or "pin"
  std::string origin;  ///< "start", "end", "harness.json", "clip <solid>"
  double s = 0.0;      ///< [m] arc length
  Vec3 position = Vec3::Zero();  // 3 [m]
  bool sliding = false;
};

/// One drawn cable after the relax: the same numbers `cablefit relax` writes to <stem>.json.
struct CableSummary {
  std::string name;
  bool ok = false;
  std::string error;             ///< one line when !ok
  double length = 0.0;           ///< [m]
  double diameter = 0.0;         ///< [m] as drawn in the output
  Eigen::Matrix3Xd drawn;        // 3 x m [m] drawn route as the solver read it
  Eigen::VectorXd s;             // n [m] arc length of the relaxed samples
  Eigen::Matrix3Xd relaxed;      // 3 x n [m] relaxed centreline samples
  Eigen::VectorXd deviation;     // n [m] distance of each relaxed sample to the drawn route
  double max_deviation = 0.0;    ///< [m]
  double rms_deviation = 0.0;    ///< [m]
  double max_deviation_s = 0.0;  ///< [m]
  double min_bend_radius = 0.0;  ///< [m]
  double bend_limit = 0.0;       ///< [m]
  bool bend_flag = false;
  bool stable = false;
  std::string material_source;
  bool material_defaulted = false;
  double bending_stiffness = 0.0;  ///< [N m^2]
  double linear_density = 0.0;     ///< [kg/m]
  Vec3 gravity = Vec3::Zero();     // 3 [m/s^2]
  std::vector<SupportSummary> supports;
  std::vector<std::string> notes;
  int iterations = 0;
  double seconds = 0.0;  ///< solve wall time
};

/// One pose of a swept cable: the numbers `cablefit relax` writes into the cable's "motion".
struct MotionPoseSummary {
  double q = 0.0;  ///< [rad], [m] or a pose number (MotionSummary::unit)
  bool converged = false, stable = false;
  bool escaped_unstable = false, jumped = false;  ///< the followed branch ended here (and how)
  double min_bend_radius = 0.0;                   ///< [m] (infinity when straight)
  double min_bend_radius_s = 0.0;                 ///< [m]
  bool bend_flag = false;                         ///< tighter than the cable's limit
  double max_tension = 0.0;                       ///< [N]
  double max_tension_s = 0.0;                     ///< [m]
  /// Least clearance to a solid it does not rest on or another cable at the same pose; infinity
  /// (and `clearance_to` empty) when nothing was measured.
  double clearance = std::numeric_limits<double>::infinity();  ///< [m]
  double clearance_s = 0.0;                                    ///< [m]
  double clearance_required = 0.0;  ///< [m] what harness.json asks, 0 = nothing
  std::string clearance_to;         ///< "solid 'name'" or "cable 'name'"
  Eigen::VectorXd s;                // n [m] arc length of the centreline samples
  Eigen::Matrix3Xd centreline;      // 3 x n [m] the cable's shape at this pose
};

/// The sweep of one cable through the motion's poses.
struct SweptCableSummary {
  int cable = 0;  ///< index into HarnessRelaxation::cables()
  std::string name;
  std::vector<MotionPoseSummary> poses;  ///< fewer than MotionSummary::q when it stopped
  int branch_lost_pose = -1;             ///< first pose where the followed branch ended, -1 = never
  bool completed = false;
  std::string message;  ///< why the sweep stopped early
  /// [m] largest distance between the first and the last pose's centreline; NaN unless the
  /// motion goes there and back and the sweep completed.
  double back_to_start = 0.0;
  double seconds = 0.0;
};

/// The harness.json motion run on the relaxed file, as `cablefit relax` runs it.
struct MotionSummary {
  std::string name;
  std::string kind;                   ///< "rotation" or "translation"
  std::string unit;                   ///< of q: "rad" (rotation), "m" (translation), "pose" (a list)
  std::vector<double> q;              ///< the poses' parameters, in `unit`
  std::vector<std::string> problems;  ///< moving supports that could not be swept, one line each
  std::vector<SweptCableSummary> cables;
  double seconds = 0.0;  ///< wall time of the sweep and its clearances
};

struct RelaxedFile;  // defined in cablefit_facade.cc

/// The relaxed harness of one input file, kept so it can be exported without solving again.
class HarnessRelaxation {
 public:
  /// Reads `input` (STEP/IGES/mesh, `mesh_unit` for meshes), reads `config_path`
  /// (harness.json, may be empty) and relaxes every cable like `cablefit relax --accuracy
  /// --timeout` (`accuracy` <= 0: the command line's default for the input, 1e-4 m for a KBL
  /// harness and 1e-6 m otherwise): a cable (or group) taking longer than `timeout` seconds (<= 0:
  /// no limit) fails with "timed out after N s". Then, as the command line, the clearances and,
  /// when harness.json has a "motion", its sweep (motion()). `progress` (may be empty) gets
  /// (fraction, stage); returning false cancels: the remaining cables fail with "cancelled". Throws
  /// FileError/InvalidInput for unreadable inputs.
  static HarnessRelaxation Run(const std::string& input, const std::string& config_path,
                               double accuracy, const std::string& mesh_unit, double timeout,
                               const ProgressCallback& progress);

  const std::vector<CableSummary>& cables() const { return cables_; }
  /// The harness.json motion, unset without one.
  const std::optional<MotionSummary>& motion() const { return motion_; }
  std::vector<std::string> solid_names() const;
  double read_seconds() const;

  /// The relaxed tubes (failed cables as drawn) as STEP AP242 in mm, with the input's other
  /// solids when `with_solids`: the file `cablefit relax` writes when `with_solids` and
  /// `cable` < 0, else only cable number `cable`; with `pose` >= 0 that cable as it is at pose
  /// `pose` of the motion (InvalidInput unless the motion swept it that far).
  void WriteStep(const std::string& path, bool with_solids, int cable, int pose = -1) const;
  /// What `cablefit relax` writes into `dir` for this input: <stem>.json, <stem>.step,
  /// <stem>-deviation.png (unless !pictures) and report.html. Returns the report's path.
  std::string WriteReport(const std::string& dir, bool pictures) const;

 private:
  std::shared_ptr<RelaxedFile> file_;
  std::vector<CableSummary> cables_;
  std::optional<MotionSummary> motion_;
};

/// The colour `value` gets on the scale [lo, hi] of the relax deviation pictures (viridis),
/// sRGB components in [0, 1]. Throws InvalidInput unless lo < hi, both finite.
std::array<double, 3> DeviationColour(double value, double lo, double hi);

/// A diagnosed recording case: what the workbench shows (points, curves, text).
struct DiagnosisSummary {
  std::string name;
  std::string kind;  ///< "shape" or "force"
  std::string effect;
  double confidence = 0.0;
  std::optional<std::pair<double, double>> interval;  // [m]
  std::map<std::string, double> parameters;
  std::vector<std::pair<std::string, double>> candidates;  ///< (effect, score), best first
  /// Every effect found (effect, share of the baseline mismatch), dominant first; empty: none.
  std::vector<std::pair<std::string, double>> effects;
  double baseline_max = 0.0, fitted_max = 0.0;  ///< in deviation_unit
  std::string deviation_unit;
  std::string explanation;
  std::string observation_source;
  Eigen::Matrix3Xd scan_points;  // 3 x k [m] sub-sampled scan (may be empty)
  Eigen::Matrix3Xd observation;  // 3 x n [m] centre points the fit saw (shape cases)
  Eigen::Matrix3Xd nominal;      // 3 x m [m] nominal centreline nodes (shape cases)
  Eigen::Matrix3Xd fitted;       // 3 x m [m] fitted centreline nodes (shape cases)
  std::vector<std::string> notes;
  double seconds = 0.0;
  std::string report;  ///< report.html written, or empty
};

/// Diagnoses `case_file` like `cablefit diagnose`; when `report_dir` is not empty also writes
/// diagnosis.json, the model curves, the pictures and report.html there (as the CLI does per
/// case). Throws FileError naming the file at fault.
DiagnosisSummary DiagnoseRecording(const std::string& case_file, const std::string& report_dir,
                                   const ProgressCallback& progress);

}  // namespace cablefit::freecad
