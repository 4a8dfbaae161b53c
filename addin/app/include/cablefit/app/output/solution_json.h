// solution.json of `cablefit simulate`: reactions at every support, solver summary, profiles.
#pragma once

#include <string>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// The `cablefit-solution/1` object for a simulated case.
json::Json SolutionToJson(const std::string& case_name, const RodSpec& spec, const SimulationResult& r);

}  // namespace cablefit::addin
