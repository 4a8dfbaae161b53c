// Placeholder until the diagnose issue lands: the sub-command exists so --help lists it, and it says
// plainly that it is not available rather than pretending to work.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cablefit/addin/commands.h"

namespace cablefit::addin {

void RegisterDiagnoseCommand(CLI::App& app, int* exit_code) {
  auto* cmd = app.add_subcommand("diagnose", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([exit_code] {
    std::fprintf(stderr, "cablefit: diagnose: not available yet in this build\n");
    *exit_code = kExitUsage;
  });
}

}  // namespace cablefit::addin
