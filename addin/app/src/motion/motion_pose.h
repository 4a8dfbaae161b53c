// One pose of a swept cable measured the way a relaxed cable is. Internal to the motion sweeps
// (cables alone and networks).
#pragma once

#include "cablefit/app/motion/motion_results.h"
#include "cablefit/app/relax/relax_cable.h"
#include "cablefit/core/solver/motion_sweep.h"

namespace cablefit::addin {

/// One pose of a swept cable measured as a relaxed cable is: bend radius, tension, reactions,
/// the centreline resampled for output.
MotionPose MeasurePose(const CableRelaxation& relaxed, const SweepPose& p, double factor);

/// [m] Largest distance between the first and the last pose's centrelines of a completed
/// there-and-back sweep; NaN otherwise.
double BackToStart(const CableMotion& cm, bool there_and_back);

}  // namespace cablefit::addin
