// One input of `cablefit relax`: reading a CAD file or mesh into a HarnessDrawing, the relaxed
// cables, and the per-input outputs <stem>.step and <stem>.json.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cablefit/formats/harness_drawing.h"
#include "cablefit/formats/json_util.h"
#include "cablefit/app/relax/relax_cable.h"
#include "cablefit/app/relax/relaxed_harness.h"
#include "cablefit/app/clearance/relax_clearance.h"
#include "cablefit/app/output/output_files.h"
#include "cablefit/app/motion/relax_motion.h"
#include "cablefit/app/tolerance/relax_tolerance.h"

namespace cablefit::addin {

/// Per-stage wall times of one input [s].
struct StageTimes {
  double read = 0, relax = 0, step = 0, json = 0, picture = 0;
};

/// Everything known about one input after the run: its relaxed cables (RelaxedHarness) and
/// what was measured on them and written.
struct RelaxedFile : RelaxedHarness {
  std::string input;  ///< path as found
  std::string stem;   ///< output file stem (unique in the run)
  std::string error;  ///< the file's one-line problem (without the path); empty if none
  bool read_ok = false;
  StageTimes times;
  std::string picture;                 ///< PNG file name next to the outputs, empty if none
  std::vector<std::string> close_ups;  ///< per cable PNG names (--close-ups), else empty
  MotionPictures motion_pictures;      ///< the motion's animation and still frames, if any
  std::vector<json::Json> networks;    ///< per network group: junction loads, contacts
  /// The settings this input is relaxed with when the input itself carries some (a KBL file:
  /// the run's harness.json layered over them); null = the run's. See ConfigOf.
  std::shared_ptr<const HarnessConfig> own_config;
  /// By cable name, what the input itself says about the cable (KBL: the "kbl" object).
  std::map<std::string, json::Json> cable_json;
  std::vector<std::string> notes;      ///< what reading the input found or assumed
  /// Relaxed cables against the solids and each other (MeasureHarnessClearances).
  std::vector<ClearancePair> clearances;
  /// The harness.json motion run on this input (SweepHarnessMotion); unset without one.
  std::optional<FileMotion> motion;
  /// The harness.json tolerance envelope run on this input (VaryHarnessTolerances); unset without one.
  std::optional<FileTolerance> tolerance;
  /// Envelope files written next to the outputs (WriteEnvelopeFiles), empty when none.
  std::vector<EnvelopeFiles> envelopes;
};

/// The settings `f` is relaxed with: its own, else the run's `config`.
const HarnessConfig& ConfigOf(const RelaxedFile& f, const HarnessConfig& config);

/// The diameter `cable` is drawn with in the output: relaxed set-up's, else harness.json's or
/// the drawn one, else the default.
double OutputDiameter(const RelaxedFile& f, int cable, const HarnessConfig& config);

/// Writes DIR/<stem>.step: relaxed cables resampled to about two points per diameter (retried
/// sparser if the sweep fails), failed ones as drawn so names and count are kept,
/// and the drawing's solids. Returns one line per cable that could not be made into a tube and
/// was left out (the others are written all the same).
std::vector<std::string> WriteRelaxedStepFile(const std::string& path, const RelaxedFile& f,
                                              const HarnessConfig& config);

/// The `cablefit-relax/1` object of DIR/<stem>.json.
json::Json RelaxedFileToJson(const RelaxedFile& f, const HarnessConfig& config);

}  // namespace cablefit::addin
