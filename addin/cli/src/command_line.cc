#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "cablefit/app/base/provenance.h"
#include "cablefit/cli/commands.h"
#include "cablefit/core/base/cancellation.h"
#include "cablefit/core/base/errors.h"
#include "cablefit/formats/allocator_tuning.h"
#include "cablefit/core/base/solver_failure.h"
#include "terminal_text.h"

namespace cablefit::addin {

namespace {

// Result lines that never reached their reader (a full disk, a closed pipe, /dev/full) are a
// failure, not success: for `section` and `bench` the standard output is the whole result.
int CheckStandardOutput(const CLI::App& app, int exit_code) {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout)) return exit_code;
  std::fprintf(stderr, "cablefit: cannot write the standard output: %s\n",
               error != 0 ? std::strerror(error) : "write error");
  for (const CLI::App* sub : app.get_subcommands())
    if (sub->get_name() == "section" || sub->get_name() == "bench") return kExitUsage;
  return exit_code == kExitOk ? kExitSomeFailed : exit_code;
}

std::string CommandNames(CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

bool IsCommand(CLI::App& app, const std::string& word) {
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    if (sub->check_name(word)) return true;
  return false;
}

// The help to point at after a usage error: the sub-command's when one was named.
std::string HelpCommand(CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) return "cablefit " + sub->get_name() + " --help";
  return "cablefit --help";
}

}  // namespace

int RunCommandLineWith(int argc, char** argv, std::initializer_list<RegisterCommand> commands) {
  SetCommandLine(argc, argv);  // for the provenance of every output
  TuneAllocatorForSolves();
  // Named here, not from argv[0], so that usage lines read "cablefit relax", wherever it lives.
  CLI::App app{"cablefit: wiring-harness and hose CAD to physics, and why a simulated cable "
               "does not look like the real one",
               "cablefit"};
  app.set_version_flag("--version", ToolVersion());
  app.require_subcommand(1);
  int exit_code = kExitOk;
  for (RegisterCommand add : commands) add(app, &exit_code);
  // A first word that is no option and no command: say so, instead of CLI11's "a subcommand is
  // required"; "help" is what people type.
  if (argc > 1 && argv[1][0] != '-' && !IsCommand(app, argv[1])) {
    if (std::string(argv[1]) == "help") {
      std::fputs(app.help().c_str(), stdout);
      return kExitOk;
    }
    std::fprintf(stderr, "cablefit: unknown command '%s' (the commands are %s)\n",
                 TerminalSafe(argv[1]).c_str(), CommandNames(app).c_str());
    std::fprintf(stderr, "run 'cablefit --help' for usage\n");
    return kExitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(e.what()).c_str());
    std::fprintf(stderr, "run '%s' for usage\n", HelpCommand(app).c_str());
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
    // cli-v1 has no code of its own for our bugs: the work failed (1), the input was not at fault.
    std::fprintf(stderr, "cablefit: internal error: %s\n", TerminalSafe(e.what()).c_str());
    return kExitSomeFailed;
  } catch (const std::exception& e) {
    // Anything else (an unreadable output folder, out of memory) is still one line.
    std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(OneLine(e.what())).c_str());
    return kExitUsage;
  }
  return CheckStandardOutput(app, exit_code);
}

}  // namespace cablefit::addin
