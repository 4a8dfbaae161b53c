// Text from inputs (case, cable and file names, messages quoting them) is printed on a terminal:
// a control character in it could forge a result line ("\nFAKE: none, confidence 1.00"), move
// the cursor or change colours. Everything the command line prints goes through TerminalSafe.
#pragma once

#include <string>
#include <string_view>

namespace cablefit::addin {

/// `text` with every control character (bytes 0x00-0x1f and 0x7f: newline, CR, ESC, BEL, ...)
/// written as \xNN; other bytes, UTF-8 included, unchanged.
std::string TerminalSafe(std::string_view text);

}  // namespace cablefit::addin
