// Runs the built `cablefit` binary for end-to-end tests.
#pragma once

#include <string>

namespace cablefit::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

/// Path of the built cablefit binary.
std::string CablefitBinary();
/// Runs `cablefit <args>` (args are passed to the shell as written: quote paths yourself).
CliRun RunCablefit(const std::string& args);

}  // namespace cablefit::testing
