// A one-line progress bar on stderr: frames done, elapsed and estimated time left. Redraws in
// place on a terminal; elsewhere (logs, CI) prints a line every 10 %.
#pragma once

#include <unistd.h>

#include <chrono>
#include <cstdio>

namespace clothlab::app {

class ProgressBar {
 public:
  ProgressBar(long total, bool enabled)
      : total_(total), enabled_(enabled), tty_(::isatty(2)), start_(Clock::now()) {}

  void update(long done) {
    if (!enabled_ || total_ <= 0) return;
    const int percent = static_cast<int>(100 * done / total_);
    if (!tty_ && percent / 10 == last_decile_ && done != total_) return;
    last_decile_ = percent / 10;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double left = done > 0 ? elapsed * static_cast<double>(total_ - done) / done : 0.0;
    char bar[31];
    const int filled = static_cast<int>(30 * done / total_);
    for (int k = 0; k < 30; ++k) bar[k] = k < filled ? '#' : '.';
    bar[30] = '\0';
    std::fprintf(stderr, "%s[%s] %ld/%ld frames, %.1f s elapsed, %.1f s left%s", tty_ ? "\r" : "",
                 bar, done, total_, elapsed, left, tty_ ? "" : "\n");
    if (tty_ && done == total_) std::fputc('\n', stderr);
    std::fflush(stderr);
  }

 private:
  using Clock = std::chrono::steady_clock;
  long total_;
  bool enabled_, tty_;
  int last_decile_ = -1;
  Clock::time_point start_;
};

}  // namespace clothlab::app
