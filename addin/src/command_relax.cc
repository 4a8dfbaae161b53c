// Placeholder until the relax issue lands: the sub-command exists so --help lists it, and it says
// plainly that it is not available rather than pretending to work.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "cablefit/addin/commands.h"

namespace cablefit::addin {

void RegisterRelaxCommand(CLI::App& app, int* exit_code) {
  auto* cmd = app.add_subcommand("relax", "(not available yet in this build)");
  cmd->allow_extras();
  cmd->callback([exit_code] {
    std::fprintf(stderr, "cablefit: relax: not available yet in this build\n");
    *exit_code = kExitUsage;
  });
}

}  // namespace cablefit::addin
