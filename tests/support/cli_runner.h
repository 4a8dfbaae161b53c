// Runs the built `cablefit` binary for end-to-end tests.
#pragma once

#include <filesystem>
#include <string>

namespace cablefit::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

/// Shell-quoted path. Built with append: GCC 12 warns (-Wrestrict, a false positive) on
/// "'" + std::string.
inline std::string Q(const std::filesystem::path& p) {
  std::string q(1, '\'');
  q.append(p.string()).push_back('\'');
  return q;
}

/// Path of the built cablefit binary.
std::string CablefitBinary();
/// Runs `cablefit <args>` (args are passed to the shell as written: quote paths yourself).
CliRun RunCablefit(const std::string& args);

}  // namespace cablefit::testing
