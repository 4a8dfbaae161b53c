// The catalogue's shape effects as parametrised changes of the nominal RodSpec
// (recording-v1.md, "The catalogue of effects"). The case's clamp frames are taken as given:
// a clamp's twist about the cable is the one its normal states unless twist_preload says
// otherwise.
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
  Eigen::VectorXd scale;                // typical size of every parameter
  std::vector<Eigen::VectorXd> starts;  // starting physical parameters
  /// Parameters -> the changed spec.
  std::function<RodSpec(const Eigen::VectorXd&)> apply;
};

/// Rotates support `clamp`'s normal by `angle` [rad] about its tangent (right-hand rule).
void RotateClampAboutTangent(int clamp, double angle, RodSpec* spec);

/// Every fittable model for `nominal`; "none" comes first. `reaction_moment[k]`
/// is the nominal moment magnitude at support k [N m] (scales the compliance
/// starts).
std::vector<EffectModel> BuildEffectModels(const RodSpec& nominal,
                                           const std::vector<double>& reaction_moment);

}  // namespace cablefit
