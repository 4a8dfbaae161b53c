// The one exception for a failed solve. A solver that fails on valid input reports it in its
// summary (StaticsSummary, SimulationResult) and does not throw; only an analysis that cannot go
// on without that solve, and has no summary of its own to put it in, throws SolverFailure.
#pragma once

#include <stdexcept>
#include <string>

#include "cablefit/core/base/errors.h"

namespace cablefit {

/// A solve failed inside an analysis that needs it (no result can be given); the input may be
/// fine. Not InvalidInput, so that it is never reported as a problem of the user's data.
class SolverFailure : public std::runtime_error {
 public:
  explicit SolverFailure(const std::string& what) : std::runtime_error(OneLine(what)) {}
};

}  // namespace cablefit
