// Two effects of the catalogue acting together, as one model with x = (x_a, x_b): b's change is
// made to the spec that a has changed. Real recordings rarely have one cause (a plastic set and a
// clamp that could not be set exactly; a heavier cable with a coil set), so the diagnosis weighs
// such pairs against the single effects.
#pragma once

#include <vector>

#include "cablefit/core/rod/rod_spec.h"
#include "shape_effects.h"

namespace cablefit {

/// Whether `a` and `b` make a pair that the shape can tell from either alone: two different
/// pieces of physics, or one that can act at two places (a curvature span or a support at two
/// places, a clamp effect at both clamps). Not: an effect that is one number of the whole cable
/// twice (weight/stiffness, anisotropy), a clamp effect twice at the same clamp, nor a twist
/// preload at both clamps of a cable whose shape sees only the twist between them (isotropic,
/// no natural curvature, two clamps that hold the twist).
bool CanCombine(const EffectModel& a, const EffectModel& b, const RodSpec& nominal);

/// The model of singles[a] and singles[b] acting together (parts {a, b}); no starts (the caller
/// starts it from the single fits).
EffectModel CombineEffects(const std::vector<EffectModel>& singles, int a, int b);

/// The model of the parts of `combined` other than part `part` (an index into its parts) acting
/// alone, with x laid out as `combined`'s: what a part adds is measured by leaving it out.
EffectModel WithoutPart(const EffectModel& combined, const std::vector<EffectModel>& singles,
                        int part);

/// Part `part`'s parameters out of a combined model's x.
Eigen::VectorXd PartParameters(const EffectModel& combined, const std::vector<EffectModel>& singles,
                               int part, const Eigen::VectorXd& x);

}  // namespace cablefit
