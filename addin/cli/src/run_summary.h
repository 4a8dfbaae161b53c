// What the batch commands (relax, diagnose) say at the end of a run, the same way for both:
// the failures again, one `cablefit: <file>: <problem>` line each.
#pragma once

#include <string>
#include <vector>

namespace cablefit::addin {

/// Prints "cablefit: <command>: N failure(s):" and then each failure as
/// "cablefit: <file>: <problem>" on the standard error; nothing when `failures` is empty.
/// `failures` are "<file>: <problem>" lines.
void PrintFailureList(const std::string& command, const std::vector<std::string>& failures);

}  // namespace cablefit::addin
