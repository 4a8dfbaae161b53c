// Cooperative time limit for one batch item (`--timeout` of the batch commands): the caller
// sets a deadline for the current thread, and the long loops of the solvers (Newton iterations,
// Levenberg-Marquardt steps) call CheckDeadline(), which throws once it has passed. Per thread,
// because a batch runs one item per worker thread and the solvers are called deep inside the
// item, where threading an option through every layer would touch every options struct.
#pragma once

#include <stdexcept>
#include <string>

namespace cablefit {

/// Thrown by CheckDeadline(): the item ran out of its time. what() is one line,
/// "timed out after N s".
class DeadlineExceeded : public std::runtime_error {
 public:
  explicit DeadlineExceeded(const std::string& what) : std::runtime_error(what) {}
};

/// Sets a deadline `seconds` from now for the calling thread while in scope (<= 0: none);
/// restores the previous one on exit.
class ScopedDeadline {
 public:
  explicit ScopedDeadline(double seconds);
  ~ScopedDeadline();
  ScopedDeadline(const ScopedDeadline&) = delete;
  ScopedDeadline& operator=(const ScopedDeadline&) = delete;

 private:
  double previous_end_;      // [s] steady-clock time, or 0 for none
  double previous_seconds_;  // [s] the limit as given
};

/// Throws DeadlineExceeded when the calling thread's deadline has passed; cheap otherwise.
void CheckDeadline();

}  // namespace cablefit
