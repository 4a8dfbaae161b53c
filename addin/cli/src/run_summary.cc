#include "run_summary.h"

#include <cstdio>
#include <filesystem>

#include "cablefit/core/base/errors.h"
#include "terminal_text.h"

namespace cablefit::addin {

void PrintFailureList(const std::string& command, const std::vector<std::string>& failures) {
  if (failures.empty()) return;
  std::fprintf(stderr, "cablefit: %s: %zu failure(s):\n", command.c_str(), failures.size());
  for (const std::string& f : failures) std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(f).c_str());
}

void CheckSummaryJsonPath(const std::string& path, const std::vector<std::string>& inputs) {
  if (path.empty()) throw InvalidInput("--summary-json: the file name is empty");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InvalidInput("--summary-json " + path + ": is a folder; name a file");
  for (const std::string& in : inputs) {
    if (std::filesystem::equivalent(in, path, ec) && !ec)
      throw InvalidInput("--summary-json " + path + ": is the input " + in +
                         "; write the summary to another file");
  }
}

}  // namespace cablefit::addin
