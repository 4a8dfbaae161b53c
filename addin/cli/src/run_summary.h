// What the batch commands (relax, diagnose) say at the end of a run, the same way for both:
// the failures again, one `cablefit: <file>: <problem>` line each, and the --summary-json file.
#pragma once

#include <string>
#include <vector>

namespace cablefit::addin {

/// Prints "cablefit: <command>: N failure(s):" and then each failure as
/// "cablefit: <file>: <problem>" on the standard error; nothing when `failures` is empty.
/// `failures` are "<file>: <problem>" lines.
void PrintFailureList(const std::string& command, const std::vector<std::string>& failures);

/// Throws InvalidInput before any work when --summary-json `path` cannot be the run summary:
/// empty, an existing folder, or one of `inputs`.
void CheckSummaryJsonPath(const std::string& path, const std::vector<std::string>& inputs);

}  // namespace cablefit::addin
