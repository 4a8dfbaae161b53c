#include "cablefit/core/base/deadline.h"

#include <chrono>
#include <cstdio>

namespace cablefit {
namespace {

thread_local double t_end = 0.0;      // [s] steady-clock seconds, 0 = no deadline
thread_local double t_seconds = 0.0;  // [s] the limit as given, for the message

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

ScopedDeadline::ScopedDeadline(double seconds) : previous_end_(t_end), previous_seconds_(t_seconds) {
  t_end = seconds > 0.0 ? Now() + seconds : 0.0;
  t_seconds = seconds > 0.0 ? seconds : 0.0;
}

ScopedDeadline::~ScopedDeadline() {
  t_end = previous_end_;
  t_seconds = previous_seconds_;
}

void CheckDeadline() {
  if (t_end <= 0.0 || Now() < t_end) return;
  char text[64];
  std::snprintf(text, sizeof text, "timed out after %g s", t_seconds);
  throw DeadlineExceeded(text);
}

}  // namespace cablefit
