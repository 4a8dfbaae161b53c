// A one-line terminal progress bar for batch commands (diagnose, relax). It draws on its stream
// only when that stream is a terminal, so logs and pipes stay clean; result lines printed through
// PrintLine never tear the bar. Thread-safe: workers of a batch_pool report concurrently.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

namespace cablefit::addin {

class ProgressBar {
 public:
  /// `items` units of work (e.g. cases). Draws on `stream` only if it is a terminal.
  explicit ProgressBar(int items, std::FILE* stream = stderr);
  /// Erases the bar.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Item `item` is `fraction` (clamped to [0, 1]) done, now in `stage` (may be empty).
  /// Matches ProgressCallback's (fraction, stage) so it can be forwarded directly.
  void Update(int item, double fraction, const std::string& stage);
  /// Item `item` is finished (fraction 1).
  void Finish(int item);
  /// Writes `line` (a newline is added) to `out` without tearing the bar.
  void PrintLine(std::FILE* out, const std::string& line);

  bool drawing() const { return drawing_; }

 private:
  void DrawLocked(bool force);
  void EraseLocked();

  std::mutex mutex_;
  std::FILE* stream_;
  bool drawing_ = false;
  std::vector<double> fraction_;  // per item, in [0, 1]
  std::vector<bool> finished_;
  std::string stage_;             // last reported stage, e.g. "sample-none: fit"
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace cablefit::addin
