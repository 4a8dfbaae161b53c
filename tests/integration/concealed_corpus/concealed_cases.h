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
  /// The range the gravity number w L^3 / EI is drawn from.
  double min_gravity = 2.0, max_gravity = 35.0;
  /// The far clamp's twist away from the cable's torque-free twist [rad] (before the bench's
  /// own scatter): a route set up twisted.
  double far_twist = 0.0;
};

/// Sagging, 3-D bend, drop, loop.
std::vector<Layout> CorpusLayouts();

/// Layouts the diagnosis was not developed on, the measure of whether it depends on its
/// corpus: a steep hang between clamps at different heights, an S between two parallel clamps
/// set side by side, a long sag of a limp cable, a 3-D route whose far clamp is set twisted.
std::vector<Layout> NewLayouts();

/// The layout of that name among both lists; null when there is none.
const Layout* FindLayout(const std::string& name);

/// A nominal cable on `lay`, its far clamp set near the cable's torque-free twist as a bench
/// does (plus the layout's own far twist). `gravity_number` > 0 sets w L^3 / EI instead of
/// drawing it from the layout's range.
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

/// How hard a scan is to read: fewer points, a longer unseen stretch, more noise. The draws
/// are the same whatever the quality, so that it changes nothing else of a case.
struct ScanQuality {
  double point_factor = 1.0;  // times the drawn number of surface points
  double gap_fraction = 0.0;  // the unseen stretch as a fraction of the cable; 0: 4 cm
  double noise_factor = 1.0;  // times the drawn surface noise
};

/// Half the points, a tenth of the cable unseen, twice the noise.
ScanQuality SparseNoisyScan();

/// Where `with` hangs apart from `without` (each solved as it is): the span of arc length where
/// their distance exceeds half its largest value, as the catalogue states where an effect that
/// acts everywhere shows. nullopt when either cannot be solved.
std::optional<std::pair<double, double>> ContributionSpan(const RodSpec& with,
                                                          const RodSpec& without);

struct ScannedTruth {
  bool solved = false;  // false: the hidden truth itself could not be solved
  std::string failure;  // why not
  ShapeObservation observation;
  PointCloud cloud;  // the synthetic scan itself
  double extraction_seconds = 0.0;
};

/// Solves `truth` (its point loads, the hidden contacts, turned normal to the cable as it finally
/// hangs, as a frictionless support pushes), takes a synthetic hand-held scan of it (its parameters
/// drawn from `rng` whether or not `run`) and extracts the centre line guided by `told` (by `truth`
/// when `told` lists fewer than two supports). Nothing but the draws happens unless `run`.
ScannedTruth ScanTruth(const RodSpec& truth, const RodSpec& told, std::mt19937& rng, bool run,
                       const ScanQuality& quality = {});

/// ScanTruth, printing a hidden truth that could not be solved (not a diagnosis result, but
/// reported so that a regression in the solver shows): nullopt then.
std::optional<ScannedTruth> ScanOrReport(const char* layout, const std::string& label,
                                         const RodSpec& truth, const RodSpec& told,
                                         std::mt19937& rng, bool run,
                                         const ScanQuality& quality = {});

/// DiagnoseShape of a scanned truth as `cablefit diagnose` runs one case (its fits on every
/// core); `seconds` receives the extraction's and the diagnosis's time.
ShapeDiagnosis DiagnoseAsCommand(const RodSpec& told, const ScannedTruth& scanned, double* seconds);

}  // namespace cablefit::testing
