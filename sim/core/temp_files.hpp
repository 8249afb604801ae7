// Temporary files removed when the process is stopped by SIGINT, SIGTERM or SIGHUP. Every file
// ClothLab writes goes to a temporary path first and is renamed when complete (complete or
// absent); a guard registers that path for its lifetime, and the handler installed by
// install_temp_file_cleanup() unlinks every registered path and then lets the signal end the
// process as it would have. SIGKILL cannot be caught: it leaves `NAME.tmp.PID` files
// (docs/inputs.md, "Temporary files and signals").
//
// The registry is the one piece of process-wide mutable state in ClothLab: a signal handler can
// reach nothing else. It is a fixed table of atomic pointers, so registering allocates nothing
// and the handler only reads pointers and calls unlink(2), which is async-signal-safe. Header
// only, so that every library that writes files (sim, music, vis) shares it without linking.
#pragma once

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <string>
#include <utility>

namespace clothlab {

namespace temp_files {

// At most this many temporary files at once (a trace; a video, its sound and a PNG).
inline constexpr int kSlots = 16;
inline std::atomic<const char*> slots[kSlots];

inline void remove_all(int signal) {
  for (auto& slot : slots)
    if (const char* path = slot.load()) ::unlink(path);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace temp_files

class TempFileGuard {
 public:
  explicit TempFileGuard(std::string path) : path_(std::move(path)) {
    for (int s = 0; s < temp_files::kSlots; ++s) {
      const char* empty = nullptr;
      if (temp_files::slots[s].compare_exchange_strong(empty, path_.c_str())) {
        slot_ = s;
        return;
      }
    }
  }
  ~TempFileGuard() {
    if (slot_ >= 0) temp_files::slots[slot_].store(nullptr);
  }
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int slot_ = -1;  // -1: not registered (the table was full)
};

// Installs the handler (once, from main; harmless to call again).
inline void install_temp_file_cleanup() {
  struct sigaction action {};
  action.sa_handler = temp_files::remove_all;
  sigemptyset(&action.sa_mask);
  // A signal the parent set to be ignored (nohup's SIGHUP, SIGINT for a background job) stays
  // ignored.
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(signal, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

}  // namespace clothlab
