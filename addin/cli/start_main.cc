// `cablefit`: what users run. `simulate`, `section` and `diagnose` need only the physics core,
// the case, JSON, PLY and CSV readers and the pictures (OSMesa is opened by the first 3-D
// picture, not linked), so they run here, in an executable that loads none of the CAD, mesh and
// XML libraries (a script calling `simulate` a thousand times should not spend its time in the
// dynamic loader: ~0.1 s and 80 libraries each otherwise; a force case's diagnosis is done in
// less). Every other command
// line is handed, unchanged, to cablefit-full beside this executable (exec: same process, same
// exit status, signals and time limits).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "cablefit/app/base/provenance.h"
#include "cablefit/cli/commands.h"

namespace {

std::filesystem::path FullExecutable() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (ec ? std::filesystem::path(".") : self.parent_path()) / "cablefit-full";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) {
    const std::string command = argv[1];
    // Scripts ask for the version to check what they run: answered without the full tool.
    if (command == "--version" && argc == 2) {
      std::printf("%s\n", cablefit::addin::ToolVersion().c_str());
      return 0;
    }
    if (command == "simulate" || command == "section" || command == "diagnose") {
      return cablefit::addin::RunCommandLineWith(
          argc, argv,
          {cablefit::addin::RegisterSimulateCommand, cablefit::addin::RegisterSectionCommand,
           cablefit::addin::RegisterDiagnoseCommand});
    }
  }
  const std::string full = FullExecutable().string();
  std::vector<char*> args(argv, argv + argc);
  args.push_back(nullptr);
  args[0] = const_cast<char*>(full.c_str());
  ::execv(full.c_str(), args.data());
  std::fprintf(stderr, "cablefit: cannot run %s: %s\n", full.c_str(), std::strerror(errno));
  return cablefit::addin::kExitUsage;
}
