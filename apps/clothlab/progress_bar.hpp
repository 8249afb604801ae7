// A one-line progress bar on stderr: frames (or steps) done, elapsed and estimated time left.
// Redraws in place on a terminal; elsewhere (logs, CI) prints a line every 10 %.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace clothlab::app {

class ProgressBar {
 public:
  ProgressBar(long total, bool enabled, const char* unit = "frames")
      : total_(total), enabled_(enabled), tty_(::isatty(2)), unit_(unit), start_(Clock::now()) {}

  // Turns the bar on after it was made off (a trace found long once under way); the elapsed
  // time still counts from construction.
  void enable() { enabled_ = true; }

  void update(long done) {
    if (!enabled_ || total_ <= 0) return;
    const int percent = static_cast<int>(100 * done / total_);
    const auto now = Clock::now();
    // Off a terminal: a line every 10 %, and at least every kLogSeconds on a long run.
    const bool due = percent / 10 != last_decile_ || done == total_ ||
                     now - last_line_ >= std::chrono::seconds(kLogSeconds);
    if (!tty_ && !due) return;
    last_decile_ = percent / 10;
    last_line_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = done > 0 ? elapsed * static_cast<double>(total_ - done) / done : 0.0;
    char bar[31];
    const int filled = static_cast<int>(30 * done / total_);
    for (int k = 0; k < 30; ++k) bar[k] = k < filled ? '#' : '.';
    bar[30] = '\0';
    std::fprintf(stderr, "%s[%s] %ld/%ld %s, %.1f s elapsed, %.1f s left%s", tty_ ? "\r" : "", bar,
                 done, total_, unit_, elapsed, left, tty_ ? "" : "\n");
    if (tty_ && done == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr int kLogSeconds = 30;
  long total_;
  bool enabled_, tty_;
  const char* unit_;
  int last_decile_ = -1;
  Clock::time_point start_, last_line_;
};

}  // namespace clothlab::app
