// The tolerance envelope of harness.json "tolerances": every relaxed cable solved with its
// length, bending stiffness and density varied, and with the place on it of every fixing between
// its ends shifted, at the corners of that box; its largest excursion from the nominal shape.
// Cables solved alone vary alone; a network (breakouts, contact) varies as one: length,
// stiffness and density of all its cables together (one batch of material), each fixing on its
// own. Up to kExhaustiveQuantities varied quantities every corner is solved; with more, the
// corners that the linearised shape says are worst (core/solver/tolerance_corners). Either way
// corners bound the envelope only when the shape moves monotonically; that is checked, not
// assumed: a few interior points of the box (fixed pseudo-random) are solved too, and the output
// says whether any went further than the corners.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cablefit/app/config/harness_config.h"
#include "cablefit/app/relax/relax_cable.h"
#include "cablefit/app/relax/relaxed_harness.h"
#include "cablefit/app/tolerance/tolerance_cases.h"
#include "cablefit/core/network/network_spec.h"
#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// `spec` with its length changed by the fraction `length` (support, sleeve, load and curvature
/// arc lengths scaled with it, positions kept), EI and GJ by `stiffness`, mass by `density`.
RodSpec VariedSpec(const RodSpec& spec, double length, double stiffness, double density);
/// The same for every branch of a network (junctions, obstacles and routes kept).
NetworkSpec VariedNetworkSpec(const NetworkSpec& spec, double length, double stiffness,
                              double density);

/// The tolerance envelope of one cable solved alone, from its nominal relaxation; its set-ups
/// on up to `threads` threads (the result does not depend on how many).
CableTolerance SingleCableTolerance(const CableRelaxation& nominal, const ToleranceConfig& config,
                                    const SimulationOptions& options,
                                    std::vector<std::string>* problems, int threads = 1);

/// Runs the envelope on every relaxed cable of `h`, alone or with its network, each one's
/// set-ups on up to `threads` threads. Unset without harness.json tolerances.
std::optional<FileTolerance> VaryHarnessTolerances(const HarnessConfig& config,
                                                   const SimulationOptions& options,
                                                   const RelaxedHarness& h, int threads);

json::Json CableToleranceToJson(const CableTolerance& t);
/// One line per varied cable (and per problem) for stdout and the report.
std::vector<std::string> ToleranceLines(const FileTolerance& t);

}  // namespace cablefit::addin
