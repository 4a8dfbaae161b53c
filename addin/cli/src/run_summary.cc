#include "run_summary.h"

#include <cstdio>

#include "terminal_text.h"

namespace cablefit::addin {

void PrintFailureList(const std::string& command, const std::vector<std::string>& failures) {
  if (failures.empty()) return;
  std::fprintf(stderr, "cablefit: %s: %zu failure(s):\n", command.c_str(), failures.size());
  for (const std::string& f : failures) std::fprintf(stderr, "cablefit: %s\n", TerminalSafe(f).c_str());
}

}  // namespace cablefit::addin
