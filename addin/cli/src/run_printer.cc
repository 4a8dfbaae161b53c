#include "run_printer.h"

#include "terminal_text.h"

namespace cablefit::addin {

void RunPrinter::Started(int slots) { bar_.emplace(slots, quiet_ ? nullptr : stderr); }

void RunPrinter::Progress(int slot, double fraction, const std::string& stage) {
  if (bar_) bar_->Update(slot, fraction, stage);
}

void RunPrinter::Finished(int slot) {
  if (bar_) bar_->Finish(slot);
}

void RunPrinter::Stopped() { bar_.reset(); }

void RunPrinter::Message(RunMessage kind, const std::string& text) {
  switch (kind) {
    case RunMessage::kDetail:
      if (!quiet_) Print(stdout, text);
      break;
    case RunMessage::kResult: Print(stdout, text); break;
    case RunMessage::kNote:
      if (!quiet_) Print(stderr, "cablefit: note: " + text);
      break;
    case RunMessage::kWarning: Print(stderr, "cablefit: warning: " + text); break;
    case RunMessage::kProblem: Print(stderr, "cablefit: " + text); break;
  }
}

void RunPrinter::Print(std::FILE* out, const std::string& line) {
  if (bar_) {
    bar_->PrintLine(out, line);
  } else {  // before the items are known or after the bar is gone
    std::fprintf(out, "%s\n", TerminalSafe(line).c_str());
  }
}

}  // namespace cablefit::addin
