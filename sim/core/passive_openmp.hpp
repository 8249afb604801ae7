// Every ClothLab program waits passively at OpenMP barriers, after a short spin, unless the user
// chose otherwise. OpenMP's default lets waiting threads spin for milliseconds, which is fastest
// on an idle machine and a disaster on a busy one: with other jobs on both cores, `clothlab trace
// scenes/default.toml --duration 0.5` took 23 s instead of 0.41 s (issue 23), and `render` once
// spent 970 ms instead of 1 ms per frame beside llvmpipe's threads. A purely passive wait goes to
// sleep at every barrier, and waking a thread cost more than a small step: the 128^2 sheet took
// 351 us a step on 2 threads against 200 us on 1. Spinning kOpenMPSpinCount times first (about
// 10 us; libgomp's GOMP_SPINCOUNT) covers the gaps between one step's parallel loops: 100 us on
// 2 threads, while a thread whose partner lost its core still sleeps within microseconds.
// libgomp reads both variables when it loads, before main(), so a program that wants them
// re-executes itself once with them set. A policy or spin count already set is kept.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace clothlab {

// Measured on the scaling sheet, 2 threads, idle host (docs/results.md "Threads"): 100 spins were
// no better than none, 1000 and 3000 alike fast; beside a busy process 1000 lost less.
inline constexpr const char* kOpenMPSpinCount = "1000";

// Re-executes the program with OMP_WAIT_POLICY=passive and GOMP_SPINCOUNT=kOpenMPSpinCount
// unless a policy is set; returns only when it is set (or when re-executing failed: then the
// program runs with OpenMP's default).
inline void prefer_passive_openmp(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY")) return;
  ::setenv("OMP_WAIT_POLICY", "passive", 1);
  ::setenv("GOMP_SPINCOUNT", kOpenMPSpinCount, 0);
  ::execv("/proc/self/exe", argv);
}

// "passive wait", "passive wait after N spins", "active wait" or, with the policy unset, "active
// wait (OpenMP's default)": for summaries.
inline std::string openmp_wait_policy() {
  const char* p = std::getenv("OMP_WAIT_POLICY");
  if (p == nullptr) return "active wait (OpenMP's default)";
  if (strcasecmp(p, "passive") != 0) return "active wait";
  const char* spins = std::getenv("GOMP_SPINCOUNT");
  return spins == nullptr ? "passive wait" : std::string("passive wait after ") + spins + " spins";
}

}  // namespace clothlab
