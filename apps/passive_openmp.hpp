// Every ClothLab program waits passively at OpenMP barriers unless the user chose otherwise.
// OpenMP's default lets waiting threads spin, which is fastest on an idle machine and a disaster
// on a busy one: with other jobs on both cores, `clothlab trace scenes/default.toml --duration
// 0.5` took 23 s instead of 0.41 s (issue 23), and `render` once spent 970 ms instead of 1 ms per
// frame beside llvmpipe's threads. libgomp reads OMP_WAIT_POLICY when it loads, before main(), so
// a program that wants it re-executes itself once with it set. A policy already set is kept.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <cstring>

namespace clothlab::app {

// Re-executes the program with OMP_WAIT_POLICY=passive unless it is set; returns only when it is
// set (or when re-executing failed: then the program runs with OpenMP's default).
inline void prefer_passive_openmp(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY")) return;
  ::setenv("OMP_WAIT_POLICY", "passive", 1);
  ::execv("/proc/self/exe", argv);
}

// "passive", "active" or, with the variable unset, "active (OpenMP's default)": for summaries.
inline const char* openmp_wait_policy() {
  const char* p = std::getenv("OMP_WAIT_POLICY");
  if (p == nullptr) return "active (OpenMP's default)";
  return strcasecmp(p, "passive") == 0 ? "passive" : "active";
}

}  // namespace clothlab::app
