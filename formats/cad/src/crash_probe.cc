#include "crash_probe.h"

#include <cstring>

#include "cablefit/core/base/errors.h"

namespace cablefit {

void ProbeFileInChild(const std::string& path, const std::string& what,
                      const std::vector<std::string>& args, double max_seconds) {
  const std::optional<ChildOutcome> outcome = RunOcctChild(args, max_seconds);
  if (!outcome) return;  // the real read decides
  if (outcome->timed_out) {
    throw FileError(path, what + " did not finish within " +
                              std::to_string(static_cast<int>(max_seconds)) +
                              " s (the limit for a file of this size); the file is corrupt or "
                              "sends OpenCASCADE's shape healing into a loop");
  }
  if (outcome->signal != 0) {
    throw FileError(path, what + " crashed on this file (signal " +
                              std::to_string(outcome->signal) + ": " +
                              ::strsignal(outcome->signal) + "); the file is corrupt");
  }
  if (outcome->exit_code != 0) {
    throw FileError(path, what + " failed on this file (exit status " +
                              std::to_string(outcome->exit_code) + "); the file is corrupt");
  }
}

}  // namespace cablefit
