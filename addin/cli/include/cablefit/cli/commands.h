// Sub-commands of the `cablefit` command line (contract: README, "Command line"). Each Register*
// adds one sub-command to the app; its callback stores the exit status in `*exit_code`.
#pragma once

#include <initializer_list>

namespace CLI {
class App;
}

namespace cablefit::addin {

/// Exit statuses of cli-v1: 0 all done, 1 some inputs failed (or were cancelled / timed out),
/// 2 usage error / nothing read. An internal error (cablefit broke a precondition of its own API,
/// a bug to report) is printed as such and exits 1: the work failed, the input was not at fault.
enum ExitCode { kExitOk = 0, kExitSomeFailed = 1, kExitUsage = 2 };

void RegisterSimulateCommand(CLI::App& app, int* exit_code);
void RegisterBenchCommand(CLI::App& app, int* exit_code);
void RegisterDiagnoseCommand(CLI::App& app, int* exit_code);
void RegisterRelaxCommand(CLI::App& app, int* exit_code);
void RegisterSectionCommand(CLI::App& app, int* exit_code);

/// Runs the whole command line (what cablefit-full's main() does), returning the exit status.
int RunCommandLine(int argc, char** argv);

using RegisterCommand = void (*)(CLI::App& app, int* exit_code);
/// The command line with only `commands`: RunCommandLine is this with all of them, and the
/// start-up executable `cablefit` with the ones that need no CAD, mesh or rendering library.
int RunCommandLineWith(int argc, char** argv, std::initializer_list<RegisterCommand> commands);

}  // namespace cablefit::addin
