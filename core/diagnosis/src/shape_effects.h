// The catalogue's shape effects as parametrised changes of the nominal RodSpec
// (recording-v1.md, "The catalogue of effects"). The case's clamp frames are taken as given:
// a clamp's twist about the cable is the one its normal states unless twist_preload says
// otherwise. Every model maps its fit parameters both ways from one place: `apply` builds the
// changed spec, `describe` states the same change in the catalogue's terms, so a bound (where a
// contact may sit, how narrow a curved span may be) is written once.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cablefit/core/diagnosis/shape_effect.h"
#include "cablefit/core/rod/rod_spec.h"
#include "cablefit/core/solver/rod_solution.h"
#include "residual_bends.h"

namespace cablefit {

/// What `describe` needs besides the parameters.
struct EffectDescriptionContext {
  /// Where the nominal differs most from the recording [m]: the interval of an effect that acts
  /// on the whole cable or at a clamp.
  std::pair<double, double> mismatch{0.0, 0.0};
  /// The changed model's solution (reactions), when there is one.
  const RodSolution* solution = nullptr;
};

/// An effect in the catalogue's terms (diagnosis.json's parameters, interval).
struct EffectDescription {
  std::map<std::string, double> parameters;   // curvature, angle, ratio, force, ...
  std::map<std::string, std::string> units;   // unit of each parameter and vector ("-": none)
  std::map<std::string, Vec3> vectors;        // axis, force_vector (world)
  std::optional<std::pair<double, double>> interval;  // [m]
};

struct EffectModel {
  ShapeEffect effect = ShapeEffect::kNone;
  int physical_parameters = 0;          // counted by the selection criterion
  std::optional<int> clamp;             // clamp (support) index for clamp effects
  Eigen::VectorXd scale;                // typical size of every parameter
  std::vector<Eigen::VectorXd> starts;  // starting physical parameters
  /// More starts when the effect is added to another one's fit: what that fit leaves is
  /// smaller and more local than the whole mismatch, so a placed effect needs a finer grid.
  std::vector<Eigen::VectorXd> residual_starts;
  /// A placed effect's starts at the places where another fit's residual bends, at zero
  /// strength (residual_bends.h): where the effect belongs follows from what the other fit
  /// leaves, not from a grid laid out for some layouts. Null for effects without a place.
  std::function<std::vector<Eigen::VectorXd>(const std::vector<ResidualBend>&)> starts_at_bends;
  /// A placed effect's places at zero strength, spread finely over the cable in order of their
  /// first parameter (the place along it), for the first-order scan of where the effect removes
  /// most of another fit's residual (place_scan.h). Empty for effects without a place.
  std::vector<Eigen::VectorXd> scan_places;
  /// The parameters that set the effect's strength: where all of them are zero the model is
  /// the spec it changes, and the other parameters (where, how wide) do nothing. Empty when no
  /// parameter value is neutral.
  std::vector<int> amplitudes;
  /// Parameters -> the change made to a spec: the nominal, or, when effects act together, the
  /// spec another effect has changed already.
  std::function<void(const Eigen::VectorXd&, RodSpec*)> change;
  /// Parameters -> the change in the catalogue's terms.
  std::function<EffectDescription(const Eigen::VectorXd&, const EffectDescriptionContext&)>
      describe;
  /// The spec `change` is made to.
  std::shared_ptr<const RodSpec> base;
  /// A combination of effects (effect_combination.h): the single models it is made of (indices
  /// into the list of single models) and where each one's parameters start in x; empty for a
  /// single effect.
  std::vector<int> parts;
  std::vector<int> part_offsets;

  /// The changed spec.
  RodSpec apply(const Eigen::VectorXd& x) const;
  bool is_combination() const { return !parts.empty(); }
  /// x changes nothing (every amplitude zero).
  bool is_neutral(const Eigen::VectorXd& x) const;
};

/// Rotates support `clamp`'s normal by `angle` [rad] about its tangent (right-hand rule).
void RotateClampAboutTangent(int clamp, double angle, RodSpec* spec);

/// Every fittable model for `nominal`; "none" comes first. `reaction_moment[k]`
/// is the nominal moment magnitude at support k [N m] (scales the compliance
/// starts). `recorded` (3 x n [m]) at arc lengths `recorded_s` (n [m], n >= 2) is
/// the recorded cable: a contact pushes normal to it.
std::vector<EffectModel> BuildEffectModels(const RodSpec& nominal,
                                           const std::vector<double>& reaction_moment,
                                           const Eigen::Matrix3Xd& recorded,
                                           const Eigen::VectorXd& recorded_s);

}  // namespace cablefit
