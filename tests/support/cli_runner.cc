#include "cli_runner.h"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "test_support.h"

namespace cablefit::testing {

std::string CablefitBinary() {
  if (const char* env = std::getenv("CABLEFIT_BINARY_DIR"))
    return (std::filesystem::path(env) / "addin" / "cablefit").string();
  return (SourceDir() / "build" / "addin" / "cablefit").string();
}

CliRun RunCablefit(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("cablefit-cli-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "out").string(), err = (dir / "err").string();
  const std::string cmd = "'" + CablefitBinary() + "' " + args + " > '" + out + "' 2> '" + err + "'";
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  auto slurp = [](const std::string& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
  };
  r.out = slurp(out);
  r.err = slurp(err);
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace cablefit::testing
