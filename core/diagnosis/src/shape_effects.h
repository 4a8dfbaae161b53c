// The catalogue's shape effects as parametrised changes of the nominal RodSpec
// (recording-v1.md, "The catalogue of effects"). Every model but twist_preload
// also carries, as its last parameter, the far clamp's rotation about its own
// tangent (from the case's normal): the twist a clamp imposes is uncertain (see
// DiagnoseShape), so it is fitted in every model alike under a prior;
// twist_preload is that rotation without the prior.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

struct EffectModel {
  std::string effect;                   // catalogue name
  int physical_parameters = 0;          // counted by the selection criterion
  std::optional<int> clamp;             // clamp (support) index for clamp effects
  std::vector<std::string> names;       // physical parameter names (for reports)
  Eigen::VectorXd scale;                // typical size of every parameter (incl. the nuisance)
  std::vector<Eigen::VectorXd> starts;  // starting physical parameters
  /// Carries the nuisance twist as its last parameter (all but twist_preload).
  bool has_nuisance = true;
  /// Parameters (physical..., nuisance twist) -> the changed spec.
  std::function<RodSpec(const Eigen::VectorXd&)> apply;
};

/// Index of the support whose twist is the nuisance parameter (last clamp), or
/// -1.
int NuisanceClampIndex(const RodSpec& nominal);

/// Applies the nuisance rotation (radians about the clamp tangent) to `spec`.
void ApplyNuisanceTwist(int clamp, double angle, RodSpec* spec);

/// Every fittable model for `nominal`; "none" comes first. `reaction_moment[k]`
/// is the nominal moment magnitude at support k [N m] (scales the compliance
/// starts).
std::vector<EffectModel> BuildEffectModels(const RodSpec& nominal,
                                           const std::vector<double>& reaction_moment);

}  // namespace cablefit
