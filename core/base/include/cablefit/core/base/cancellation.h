// The one way a long run is stopped before it ends: a cancellation scope per thread. The caller
// opens a CancellationScope around one work item (optionally with a time limit, the `--timeout`
// of the batch commands), the long loops of the solvers and readers (Newton iterations,
// Levenberg-Marquardt steps, scan slices, PLY records) call CheckCancelled(), and a progress
// callback returning false trips the scope (ReportProgress). Either way the run ends with a
// Cancelled exception, which is neither bad input nor a solver failure. Per thread, because a
// batch runs one item per worker thread and the checks sit deep inside the item, where threading
// a token through every layer would touch every options struct.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace cablefit {

/// Progress and cancel hook shared by the CLI and the CAD add-in: gets (fraction in [0, 1],
/// stage); returning false cancels the run (see ReportProgress).
using ProgressCallback = std::function<bool(double fraction, const std::string& stage)>;

/// The run was stopped: what() is one line, "cancelled" or "timed out after N s".
class Cancelled : public std::runtime_error {
 public:
  explicit Cancelled(const std::string& what) : std::runtime_error(what) {}
};

/// Cancelled because the scope's time limit passed.
class DeadlineExceeded : public Cancelled {
 public:
  using Cancelled::Cancelled;
};

/// Opens a cancellation scope on the calling thread while in scope: a time limit `seconds` from
/// now (<= 0: none) that replaces the enclosing one until exit. A cancel request inside the scope
/// also cancels the enclosing scopes (the user stopped the whole run, not one item).
/// The calling thread's scope as a worker thread needs it to do part of the same work item.
struct CancellationState {
  double end = 0.0;      // [s] steady-clock seconds, 0 = no deadline
  double seconds = 0.0;  // [s] the limit as given
  bool cancelled = false;
};
CancellationState CurrentCancellation();

class CancellationScope {
 public:
  explicit CancellationScope(double seconds = 0.0);
  /// A scope on a worker thread that continues `parent`'s (from CurrentCancellation() on the
  /// thread that started the worker): the same deadline, already cancelled if it was.
  explicit CancellationScope(const CancellationState& parent);
  ~CancellationScope();
  CancellationScope(const CancellationScope&) = delete;
  CancellationScope& operator=(const CancellationScope&) = delete;

 private:
  double previous_end_;      // [s] steady-clock time, or 0 for none
  double previous_seconds_;  // [s] the limit as given
  bool previous_cancelled_;
};

/// Trips the calling thread's scope: the next CheckCancelled() throws Cancelled, until the
/// outermost scope closes. Outside any scope it does nothing.
void RequestCancellation();

/// True once the calling thread's scope was cancelled or its time limit passed.
bool CancellationRequested();

/// Throws Cancelled (DeadlineExceeded for the time limit) when the calling thread's scope was
/// cancelled or timed out; cheap otherwise.
void CheckCancelled();

/// Calls `progress` (if any); when it returns false, trips the scope and throws Cancelled.
void ReportProgress(const ProgressCallback& progress, double fraction, const std::string& stage);

}  // namespace cablefit
