// The terminal side of a batch run (relax, diagnose): what the pipeline says, through one
// progress bar so that no line tears it. Results go to the standard output, notes, warnings and
// problems to the standard error (prefixed "cablefit: "); --quiet keeps only what a user must see.
#pragma once

#include <cstdio>
#include <optional>
#include <string>

#include "cablefit/app/pipeline/run_observer.h"
#include "progress_bar.h"

namespace cablefit::addin {

class RunPrinter : public RunObserver {
 public:
  explicit RunPrinter(bool quiet) : quiet_(quiet) {}
  void Started(int slots) override;
  void Progress(int slot, double fraction, const std::string& stage) override;
  void Finished(int slot) override;
  void Stopped() override;
  void Message(RunMessage kind, const std::string& text) override;

 private:
  void Print(std::FILE* out, const std::string& line);

  bool quiet_;
  std::optional<ProgressBar> bar_;  // from Started to Stopped
};

}  // namespace cablefit::addin
