// The counts a `cablefit relax` run is judged by, said the same way in the report's verdict,
// the final line on the standard output and the --summary-json file.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cablefit/app/output/relax_file.h"

namespace cablefit::addin {

struct RelaxCounts {
  int inputs = 0;         ///< inputs the run was given (files, after expanding folders)
  int inputs_failed = 0;  ///< inputs with a problem of their own (unread, outputs not written)
  int cables = 0;         ///< cables found in the inputs that were read
  int relaxed = 0;        ///< cables whose solve converged
  int failed = 0;         ///< cables that did not
  int unstable = 0;       ///< relaxed, but the equilibrium found is unstable
  int bend = 0;           ///< relaxed with a bend radius below its limit
  int taut = 0;           ///< relaxed with a stretch between supports without slack
  double worst = -1.0;    ///< [m] largest max deviation of a relaxed cable, -1 if none
  std::string worst_cable;  ///< "<cable> (<stem>)" of `worst`
  double worst_s = 0.0;     ///< [m] where along that cable
};

/// Counts over every input of the run.
RelaxCounts CountRelaxation(const std::vector<RelaxedFile>& files);

/// "relax: 5 cables from 1 input: 5 relaxed, 0 failed, 1 below the bend-radius limit, 0 taut,
/// 0 unstable; largest deviation 26.3 mm (hose (legacy_harness) at s = 412 mm); 1.4 s".
std::string RelaxSummaryLine(const RelaxCounts& counts, double seconds);

/// The `cablefit-relax-summary/1` object of --summary-json: counts, per input its status,
/// outputs and cables (name, status, error), every failure line, seconds, provenance.
/// `failures` are the run's "<file>: <problem>" lines.
nlohmann::json RelaxSummaryJson(const std::vector<RelaxedFile>& files,
                                const std::vector<std::string>& failures,
                                const std::string& config_path, double seconds);

}  // namespace cablefit::addin
