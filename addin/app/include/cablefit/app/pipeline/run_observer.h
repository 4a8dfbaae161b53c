// What a batch run (relax, diagnose) says while it works. The pipelines print nothing
// themselves: the command line shows it through its progress bar, the FreeCAD module ignores it.
#pragma once

#include <string>

namespace cablefit::addin {

enum class RunMessage {
  kDetail,   ///< a result line per item (a relaxed cable, a written input, a diagnosed case)
  kResult,   ///< a finding the user must see (clearance violations, motion, tolerance lines)
  kNote,     ///< what reading found or assumed
  kWarning,  ///< a likely mistake that does not stop the run
  kProblem,  ///< "<file>: <problem>": a failure of one input, cable or case
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  /// The run's items are known: `slots` progress slots follow (before any Progress).
  virtual void Started(int slots) { (void)slots; }
  /// Slot `slot` is `fraction` done, now at `stage`. Called from worker threads.
  virtual void Progress(int slot, double fraction, const std::string& stage) {
    (void)slot, (void)fraction, (void)stage;
  }
  virtual void Finished(int slot) { (void)slot; }
  /// No more progress follows (only the end of the run's messages).
  virtual void Stopped() {}
  /// One line; called from worker threads: the observer serialises its output.
  virtual void Message(RunMessage kind, const std::string& text) { (void)kind, (void)text; }
};

}  // namespace cablefit::addin
