// Every sub-command: kept apart from command_line.cc so that an executable with only some of
// them (the start-up `cablefit`) does not link the others and the libraries they need.
#include "cablefit/cli/commands.h"

namespace cablefit::addin {

int RunCommandLine(int argc, char** argv) {
  return RunCommandLineWith(argc, argv,
                            {RegisterSimulateCommand, RegisterDiagnoseCommand, RegisterRelaxCommand,
                             RegisterSectionCommand, RegisterBenchCommand});
}

}  // namespace cablefit::addin
