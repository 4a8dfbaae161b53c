// solution.json of `cablefit simulate`: reactions at every support, solver summary, profiles.
#pragma once

#include <string>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/json_util.h"

namespace cablefit::addin {

/// The `cablefit-solution/1` text for a simulated case, with `provenance` as its last field.
/// Written straight to text: the profiles hold thousands of numbers and a simulate is meant to
/// take milliseconds as a whole process.
std::string SolutionJsonText(const std::string& case_name, const RodSpec& spec,
                             const SimulationResult& r, const json::Json& provenance);

}  // namespace cablefit::addin
