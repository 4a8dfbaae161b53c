// `cablefit bench` figures of a motion sweep (core/solver/motion_sweep.h).
#pragma once

#include "cablefit/core/rod/rod_spec.h"

namespace cablefit::addin {

/// Sweeps `spec`'s last support about the vertical axis through a point 0.1 m beside it, 0 to 60
/// degrees in 50 steps and back (101 poses), `reps` times; prints the median wall time and the
/// sweep's figures.
void BenchMotionSweep(const RodSpec& spec, int reps);

/// The bench's synthetic branched harness (app/bench_harness.h) with the end clamp of its last
/// trunk segment swung the same way (101 poses), swept as one network at its first relax level;
/// prints the wall time and the sweep's figures.
void BenchNetworkMotionSweep();

}  // namespace cablefit::addin
