// Error tiers, so that a host process (the FreeCAD module) survives everything but a bug in
// cablefit itself:
//  - a broken internal invariant aborts (CABLEFIT_CHECK, always on): nothing can be trusted;
//  - caller misuse, a precondition of an API that the calling code violated, throws UsageError
//    (a std::logic_error; CABLEFIT_REQUIRE): the caller has a bug, the process may go on;
//  - bad data (a value, file or set-up from the user) throws InvalidInput;
//  - a stopped run (user cancel, time limit) throws Cancelled (cancellation.h);
//  - a solver that fails on valid input reports it in its Summary, it does not throw;
//  - invalid Options (Options::IsValid) are reported as Ceres reports them: a solver that
//    returns a Summary puts kInvalidOptions and the reason in it and solves nothing; an analysis
//    without a Summary (a diagnosis, a section, a render) throws UsageError, because options
//    come from code (the CLI checks the values a user gives before it builds them).
// Each is caught once at the top of the CLI and printed as one line.
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

/// Caller misuse: an API was called against its documented precondition (sizes that do not
/// match, a call out of order). A bug in the calling code, not in the data.
class UsageError : public std::logic_error {
 public:
  explicit UsageError(const std::string& what) : std::logic_error(OneLine(what)) {}
};

[[noreturn]] void AbortOnBrokenInvariant(const char* condition, const char* file, int line,
                                         const std::string& message);

}  // namespace cablefit

/// Internal invariant: aborts, because a state that "cannot happen" did.
#define CABLEFIT_CHECK(cond, msg)                                                   \
  do {                                                                              \
    if (!(cond)) ::cablefit::AbortOnBrokenInvariant(#cond, __FILE__, __LINE__, msg); \
  } while (0)

/// Precondition on the caller's arguments: throws cablefit::UsageError.
#define CABLEFIT_REQUIRE(cond, msg)                                       \
  do {                                                                    \
    if (!(cond)) throw ::cablefit::UsageError(std::string(msg));          \
  } while (0)
