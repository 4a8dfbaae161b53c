// The concealed corpora's set-ups: bench layouts, a nominal cable drawn at random for one, the
// catalogue's effects hidden in it, and a synthetic hand-held scan of the hidden truth turned into
// the observation the diagnosis is given. Shared by the single-effect and the two-effect corpus.
#pragma once

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cablefit/core/diagnosis/shape_diagnosis.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit::testing {

struct Layout {
  const char* name;
  double span;  // clamp distance / length
  double drop;  // vertical offset of the far clamp / length
  double yaw;   // far clamp's lateral offset angle
  Vec3 t0, t1;  // clamp tangents
};

/// Sagging, 3-D bend, drop, loop.
std::vector<Layout> CorpusLayouts();

/// A nominal cable on `lay`, its far clamp set near the cable's torque-free twist as a bench
/// does. `gravity_number` > 0 sets w L^3 / EI instead of drawing it (2-35).
RodSpec MakeNominal(const Layout& lay, std::mt19937& rng, double gravity_number = 0.0);

/// A support's push of `magnitude` [N] at arc length `sc` of the cable `nominal` describes,
/// normal to it there, at `angle` [rad] about the cable from the direction against gravity.
Vec3 NormalPush(const RodSpec& nominal, double sc, double magnitude, double angle);

/// Where a hidden effect goes: a clamp (clamp effects; < 0 = either, at random) and, for a
/// curvature span or a contact, the place along the cable as a fraction of its length (< 0 = the
/// usual random middle part).
struct Placement {
  int clamp = -1;
  double where = -1.0;
};

/// Hides `effect` (a catalogue name) in `truth`, which starts as `nominal` or with another effect
/// hidden already; `subtle` halves its strength. Returns the clamp it went to, if a clamp effect.
std::optional<int> HideEffect(const std::string& effect, const RodSpec& nominal, bool subtle,
                              std::mt19937& rng, RodSpec* truth, Placement place = {});

/// The true span of a hidden natural curvature or contact [m], for checking where the diagnosis
/// put it: the last one `HideEffect` added of that kind.
std::optional<std::pair<double, double>> HiddenSpan(const std::string& effect,
                                                    const RodSpec& truth);

struct ScannedTruth {
  bool solved = false;          // false: the hidden truth itself could not be solved
  std::string failure;          // why not
  ShapeObservation observation;
  PointCloud cloud;  // the synthetic scan itself
  double extraction_seconds = 0.0;
};

/// Solves `truth` (its point loads, the hidden contacts, turned normal to the cable as it finally
/// hangs, as a frictionless support pushes), takes a synthetic hand-held scan of it (its parameters drawn from `rng`
/// whether or not `run`) and extracts the centre line guided by `told` (by `truth` when `told`
/// lists fewer than two supports). Nothing but the draws happens unless `run`.
ScannedTruth ScanTruth(const RodSpec& truth, const RodSpec& told, std::mt19937& rng, bool run);

/// ScanTruth, printing a hidden truth that could not be solved (not a diagnosis result, but
/// reported so that a regression in the solver shows): nullopt then.
std::optional<ScannedTruth> ScanOrReport(const char* layout, const std::string& label,
                                         const RodSpec& truth, const RodSpec& told,
                                         std::mt19937& rng, bool run);

/// DiagnoseShape of a scanned truth as `cablefit diagnose` runs one case (its fits on every
/// core); `seconds` receives the extraction's and the diagnosis's time.
ShapeDiagnosis DiagnoseAsCommand(const RodSpec& told, const ScannedTruth& scanned,
                                 double* seconds);

}  // namespace cablefit::testing
