// The work-precision diagram of a tune (docs/tuning.md), drawn on the CPU into a PNG: wall time
// per simulated second across, the worst RMS distance from the reference up, both logarithmic;
// one dot per finished candidate coloured by family, the frontier as a line, the recommendation
// ringed, and the tolerance, the reference's own error and real time (1 s per s) as guides.
// Text comes from stb_easy_font (Debian libstb), so no GL context or font file is needed.
#pragma once

#include <optional>
#include <string>

#include "tune/tune.hpp"

namespace clothlab::tune {

struct PlotLabels {
  std::string title;                  // e.g. "pile.toml to T = 1 s, 2 threads"
  std::optional<double> tolerance;    // m: drawn when given
  std::optional<std::size_t> chosen;  // the row ringed
};

// Writes the diagram to `path` (complete or absent); throws std::runtime_error on failure.
void write_work_precision_plot(const Result& result, const PlotLabels& labels,
                               const std::string& path);

}  // namespace clothlab::tune
