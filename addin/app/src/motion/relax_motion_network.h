// The motion of a network group (cables joined at breakouts, or in contact with solids): the
// group is swept as one network (SweepNetwork), and every cable of it gets its motion, whether
// one of its own supports moves or it is pulled along by the others. Internal to relax_motion.
#pragma once

#include <map>
#include <vector>

#include "cablefit/app/relax/relaxed_harness.h"
#include "cablefit/app/motion/motion_results.h"
#include "cablefit/app/relax/relax_network.h"
#include "cablefit/core/solver/motion_sweep.h"

namespace cablefit::addin {

/// Sweeps `group` of `f` through the poses `q` of `config.motion`; `moving` maps a group cable
/// (drawing index) to the indices of its set-up's supports that move, `moving_solids` lists the
/// drawing solids that move (those among the group's obstacles move in its contact). One
/// CableMotion per group cable, in group order; a sweep that fails says why in each of them.
std::vector<CableMotion> SweepNetworkGroupMotion(const RelaxedHarness& f, const RelaxGroup& group,
                                                 const std::map<int, std::vector<int>>& moving,
                                                 const std::vector<OrientedBox>& boxes,
                                                 const HarnessConfig& config,
                                                 const SimulationOptions& options,
                                                 const std::vector<double>& q,
                                                 const std::vector<int>& moving_solids);

}  // namespace cablefit::addin
