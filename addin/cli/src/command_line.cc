#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "cablefit/cli/commands.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/core/base/solver_failure.h"
#include "terminal_text.h"

namespace cablefit::addin {

int RunCommandLine(int argc, char** argv) {
  CLI::App app{"cablefit: wiring-harness and hose CAD to physics, and why a simulated cable "
               "does not look like the real one"};
  app.require_subcommand(1);
  int exit_code = kExitOk;
  RegisterSimulateCommand(app, &exit_code);
  RegisterDiagnoseCommand(app, &exit_code);
  RegisterRelaxCommand(app, &exit_code);
  RegisterSectionCommand(app, &exit_code);
  RegisterBenchCommand(app, &exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
    std::fprintf(stderr, "run 'cablefit --help' for usage\n");
    return kExitUsage;
  } catch (const InvalidInput& e) {
    // Typed user-input errors arrive here as one line "<file>: <problem>".
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
    return kExitUsage;
  } catch (const Cancelled& e) {
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
    return kExitSomeFailed;
  } catch (const SolverFailure& e) {
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
    return kExitSomeFailed;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "cablefit: internal error: %s\n", TerminalSafe(e.what()).c_str());
    return kExitInternal;
  } catch (const std::exception& e) {
    // Anything else (an unreadable output folder, out of memory) is still one line.
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(OneLine(e.what())).c_str());
    return kExitUsage;
  }
  return exit_code;
}

}  // namespace cablefit::addin
