// The `clothlab bench` suites. Each runs its measurements, prints progress to `log`, and returns
// its tables: the first is the data table written as the suite's CSV, the others are summaries
// (printed, and written beside it as <out>_<n>.csv).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "bench/suites/report.hpp"

namespace clothlab::bench {

struct SuiteOptions {
  bool quick = false;  // a reduced sweep that runs in seconds (the test suite uses it)
  int threads = 1;     // solver threads for accuracy and stability (scaling measures 1 and 2)
  std::ostream* log = nullptr;  // progress lines; null for none
};

std::vector<Table> accuracy_suite(const SuiteOptions& options);
std::vector<Table> stability_suite(const SuiteOptions& options);
// The large-step methods at 1/60 s against RK4 over a stiffness sweep, and a 256 x 256 frame.
std::vector<Table> large_step_suite(const SuiteOptions& options);
std::vector<Table> scaling_suite(const SuiteOptions& options);
std::vector<Table> features_suite(const SuiteOptions& options);
// Cloth against cloth: crossing pairs and the cost of triangle contact on the stress scenes.
std::vector<Table> contact_suite(const SuiteOptions& options);
// Real time against accuracy at 256x256, xpbd's defaults up to 512x512, and the large sheet in
// the window (issue 54).
std::vector<Table> realtime_suite(const SuiteOptions& options);
// Needs EGL / OpenGL 4.5 (throws vis::GlUnavailable without): headless rendering.
std::vector<Table> views_suite(const SuiteOptions& options);
std::vector<Table> rendering_suite(const SuiteOptions& options);
// Needs EGL / OpenGL 4.3 compute: the CPU solver against the GPU compute backend.
std::vector<Table> backends_suite(const SuiteOptions& options);

inline constexpr const char* kSuiteNames[] = {"accuracy",  "largestep", "stability", "scaling",
                                              "features",  "contact",   "realtime",  "views",
                                              "rendering", "backends"};

}  // namespace clothlab::bench
