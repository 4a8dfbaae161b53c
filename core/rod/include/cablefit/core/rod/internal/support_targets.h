// Support targets during continuation: the solver moves supports from the pose the starting shape
// has to the model's pose, and keeps the support frame items consistent with their targets.
#pragma once

#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit::internal {

/// Quaternion of a support's model target frame.
Eigen::Vector4d SupportTargetQuaternion(const RodSupport& support);

/// Targets at continuation parameter t in [0, 1]: from `start`'s support poses (t = 0) to the
/// model's (t = 1); positions linearly, frames by slerp.
void SetSupportTargets(const RodModel& model, double t, const RodState& start, RodState* state);

/// Rigid clamp items take their target frame; clip items keep their twist about the target
/// tangent; then neighbouring quaternions are put in one hemisphere.
void ApplySupportTargets(const RodModel& model, RodState* state);

/// Flips signs so that neighbouring quaternions have a non-negative dot product (q and -q are
/// one rotation, but the strain measure Im(conj(q_a) q_b) needs consistent signs).
void AlignQuaternionSigns(const RodModel& model, RodState* state);

}  // namespace cablefit::internal
