#include "cablefit/core/base/cancellation.h"

#include <chrono>
#include <cstdio>

namespace cablefit {
namespace {

thread_local double t_end = 0.0;      // [s] steady-clock seconds, 0 = no deadline
thread_local double t_seconds = 0.0;  // [s] the limit as given, for the message
thread_local bool t_cancelled = false;
thread_local int t_depth = 0;  // open scopes: outside any, a cancel request has nothing to stop

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

bool TimedOut() { return t_end > 0.0 && Now() >= t_end; }

}  // namespace

CancellationScope::CancellationScope(double seconds)
    : previous_end_(t_end), previous_seconds_(t_seconds), previous_cancelled_(t_cancelled) {
  t_end = seconds > 0.0 ? Now() + seconds : 0.0;
  t_seconds = seconds > 0.0 ? seconds : 0.0;
  ++t_depth;
}

CancellationState CurrentCancellation() { return {t_end, t_seconds, t_cancelled}; }

CancellationScope::CancellationScope(const CancellationState& parent)
    : previous_end_(t_end), previous_seconds_(t_seconds), previous_cancelled_(t_cancelled) {
  t_end = parent.end;
  t_seconds = parent.seconds;
  t_cancelled = t_cancelled || parent.cancelled;
  ++t_depth;
}

CancellationScope::~CancellationScope() {
  t_end = previous_end_;
  t_seconds = previous_seconds_;
  --t_depth;
  t_cancelled = t_depth > 0 && (previous_cancelled_ || t_cancelled);
}

void RequestCancellation() {
  if (t_depth > 0) t_cancelled = true;
}

bool CancellationRequested() { return t_cancelled || TimedOut(); }

void CheckCancelled() {
  if (t_cancelled) throw Cancelled("cancelled");
  if (!TimedOut()) return;
  char text[64];
  std::snprintf(text, sizeof text, "timed out after %g s", t_seconds);
  throw DeadlineExceeded(text);
}

void ReportProgress(const ProgressCallback& progress, double fraction, const std::string& stage) {
  if (!progress || progress(fraction, stage)) return;
  RequestCancellation();
  throw Cancelled("cancelled");
}

}  // namespace cablefit
