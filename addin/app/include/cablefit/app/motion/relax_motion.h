// The motion of harness.json ("motion") run on the relaxed cables of one input: every cable
// with a moving support is swept through the motion's poses (core/solver/motion_sweep.h), each
// pose measured like a relaxed cable (min bend radius, max tension, support reactions, stability,
// clearance to the solids and the other cables); over the motion, the worst pose of each and
// where the followed branch is lost (snap-through).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/motion/motion_results.h"
#include "cablefit/app/relax/relaxed_harness.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// Sweeps the cables `config.motion` moves; a cable solved as a network (junctions, contact) is
/// swept with its whole network, whose every cable then has a motion. Unset without a motion.
std::optional<FileMotion> SweepHarnessMotion(const HarnessConfig& config,
                                             const SimulationOptions& options,
                                             const RelaxedHarness& h);

/// The per-cable "motion" object of the relax JSON.
json::Json CableMotionToJson(const CableMotion& m, const MotionConfig& config);
/// The file-level "motion" object of the relax JSON (parameters, problems, meaning).
json::Json FileMotionToJson(const FileMotion& m);
/// Lines for stdout and the report: per swept cable its worst poses and stability.
std::vector<std::string> MotionLines(const FileMotion& m);

}  // namespace cablefit::addin
