// The harness catalogue (harness_diagnosis.h) as models: each a change of the nominal NetworkSpec
// driven by a few parameters x, at one place (a junction, a clip, a branch), with the neutral
// start (x0: the nominal itself, its place parameters where the nominal mismatch points) and the
// description of a fitted x in the catalogue's terms.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "cablefit/core/diagnosis/harness_diagnosis.h"
#include "cablefit/core/network/network_simulation.h"

namespace cablefit::internal {

struct HarnessEffectModel {
  HarnessEffect effect = HarnessEffect::kNone;
  int branch = -1, junction = -1, support = -1;
  Eigen::VectorXd x0;     // the start: no change, place parameters from the mismatch
  Eigen::VectorXd scale;  // typical size of each parameter (differences, damping)
  /// Parameters whose size is the effect's (zero at x0); the others place it. A linearised
  /// screening moves only these.
  std::vector<int> amplitudes;
  std::function<void(const Eigen::VectorXd& x, NetworkSpec* spec)> change;
  std::function<HarnessFoundEffect(const Eigen::VectorXd& x)> describe;
  std::string label;  // "branch_stiffness at <branch>", for notes and tests
  /// A model of two (CombineHarnessModels): its parts, part k's parameters from offsets[k].
  std::vector<HarnessEffectModel> parts;
  std::vector<int> offsets;
};

/// The effects a fitted model states: its own, or each part's of a pair.
std::vector<HarnessFoundEffect> DescribeEffects(const HarnessEffectModel& model,
                                                const Eigen::VectorXd& x);

/// Where the nominal mismatch is on each branch (from the observed points against the nominal).
struct MismatchHints {
  std::vector<double> max_s;  // per branch [m], arc length of its largest offset
  std::vector<double> rms;    // per branch [m]
};

/// Every model of the catalogue at every place the nominal harness has for it: each junction
/// (position along its trunk, compliance), each support inside a branch (clip position and
/// angle) and each clamp or clip with a frame (angle), each branch (stiffness, density,
/// curvature set, support contact). `solution` is the nominal's (junction moments, tangents).
std::vector<HarnessEffectModel> BuildHarnessEffectModels(const NetworkSpec& nominal,
                                                         const NetworkSolution& solution,
                                                         const MismatchHints& hints);

/// A model of two: x = (x_a, x_b), each part applied to the spec in turn.
HarnessEffectModel CombineHarnessModels(const HarnessEffectModel& a, const HarnessEffectModel& b);

}  // namespace cablefit::internal
