// Error tiers (see docs): CABLEFIT_CHECK aborts on broken invariants (always on); bad user
// input is a typed exception, caught once at the top of the CLI and printed as one line.
#pragma once

#include <stdexcept>
#include <string>

namespace cablefit {

/// `text` with line breaks and other control characters shown as escapes ("\\n"), so that a file
/// name or a quoted value from a file cannot split an error message over several lines.
std::string OneLine(const std::string& text);

/// A number for an error message: 4 significant digits ("0.3118", "1e-05").
std::string MessageNumber(double value);

/// Bad user input: a value, file or set-up that cannot be used. `what()` is one line, without
/// the file name; the layer that knows the file (formats/, addin/) adds it.
class InvalidInput : public std::runtime_error {
 public:
  explicit InvalidInput(const std::string& what) : std::runtime_error(OneLine(what)) {}
};

/// Bad input located in a file: what() is "<file>: <problem>".
class FileError : public InvalidInput {
 public:
  FileError(std::string file, const std::string& problem)
      : InvalidInput(file + ": " + problem), file_(std::move(file)), problem_(problem) {}
  const std::string& file() const { return file_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  std::string problem_;
};

[[noreturn]] void AbortOnBrokenInvariant(const char* condition, const char* file, int line,
                                         const std::string& message);

}  // namespace cablefit

#define CABLEFIT_CHECK(cond, msg)                                                   \
  do {                                                                              \
    if (!(cond)) ::cablefit::AbortOnBrokenInvariant(#cond, __FILE__, __LINE__, msg); \
  } while (0)
