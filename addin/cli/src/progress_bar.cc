#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "terminal_text.h"

namespace cablefit::addin {

namespace {
constexpr int kBarWidth = 28;
constexpr int kMaxLine = 100;  // stay within one line of a normal terminal
}  // namespace

ProgressBar::ProgressBar(int items, std::FILE* stream)
    : stream_(stream),
      drawing_(stream != nullptr && ::isatty(::fileno(stream)) == 1),
      fraction_(static_cast<std::size_t>(std::max(items, 0)), 0.0),
      finished_(static_cast<std::size_t>(std::max(items, 0)), false),
      start_(std::chrono::steady_clock::now()) {
  std::lock_guard lock(mutex_);
  DrawLocked(true);
}

ProgressBar::~ProgressBar() {
  std::lock_guard lock(mutex_);
  EraseLocked();
}

void ProgressBar::Update(int item, double fraction, const std::string& stage) {
  std::lock_guard lock(mutex_);
  if (item < 0 || item >= static_cast<int>(fraction_.size())) return;
  fraction_[static_cast<std::size_t>(item)] = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
  if (!stage.empty()) stage_ = TerminalSafe(stage);
  DrawLocked(false);
}

void ProgressBar::Finish(int item) {
  std::lock_guard lock(mutex_);
  if (item < 0 || item >= static_cast<int>(fraction_.size())) return;
  fraction_[static_cast<std::size_t>(item)] = 1.0;
  finished_[static_cast<std::size_t>(item)] = true;
  DrawLocked(true);
}

void ProgressBar::PrintLine(std::FILE* out, const std::string& line) {
  std::lock_guard lock(mutex_);
  EraseLocked();
  std::fprintf(out, "%s\n", TerminalSafe(line).c_str());
  std::fflush(out);
  DrawLocked(true);
}

void ProgressBar::EraseLocked() {
  if (!drawing_) return;
  std::fprintf(stream_, "\r\033[K");
  std::fflush(stream_);
}

void ProgressBar::DrawLocked(bool force) {
  if (!drawing_ || fraction_.empty()) return;
  const auto now = std::chrono::steady_clock::now();
  // Redrawing on every solver iteration would cost more than the solve on a slow terminal.
  if (!force && now - last_draw_ < std::chrono::milliseconds(100)) return;
  last_draw_ = now;
  double done = 0.0;
  int finished = 0;
  for (std::size_t i = 0; i < fraction_.size(); ++i) {
    done += fraction_[i];
    finished += finished_[i] ? 1 : 0;
  }
  const double f = done / static_cast<double>(fraction_.size());
  const int filled = static_cast<int>(std::lround(f * kBarWidth));
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  char head[160];
  std::snprintf(head, sizeof head, "[%s%s] %3d%% %d/%zu %.0fs ",
                std::string(static_cast<std::size_t>(filled), '#').c_str(),
                std::string(static_cast<std::size_t>(kBarWidth - filled), '.').c_str(),
                static_cast<int>(f * 100.0), finished, fraction_.size(), elapsed);
  std::string line = head + stage_;
  if (line.size() > static_cast<std::size_t>(kMaxLine)) line.resize(kMaxLine);
  std::fprintf(stream_, "\r\033[K%s", line.c_str());
  std::fflush(stream_);
}

}  // namespace cablefit::addin
