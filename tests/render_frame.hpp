// The image tests render a solver's current state as the applications do: one field snapshot
// of what the view needs (sim/fields/frame_fields.hpp), then the const renderer calls.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <vector>

#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "vis/render/headless_renderer.hpp"

namespace clothlab::test {

inline std::vector<std::uint8_t> render_frame(vis::HeadlessRenderer& renderer, Solver& solver,
                                              const vis::ViewSettings& view) {
  FieldSnapshot snapshot;
  return renderer.render(solver, snapshot.take(solver, renderer.request(view)), view);
}

inline std::optional<vis::ProbeSample> probe_frame(vis::HeadlessRenderer& renderer, Solver& solver,
                                                   const vis::ViewSettings& view, int px, int py) {
  FieldSnapshot snapshot;
  return renderer.probe(solver, snapshot.take(solver, renderer.request(view, true)), view, px, py);
}

// Two frames of the same state drawn two ways, and how far the first moved from a rest frame:
// the largest channel difference between them, and the channels more than 16/255 from `rest`.
struct FrameComparison {
  int worst = 0;
  long moved = 0;
};
inline FrameComparison compare_frames(const std::vector<std::uint8_t>& a,
                                      const std::vector<std::uint8_t>& b,
                                      const std::vector<std::uint8_t>& rest) {
  FrameComparison c;
  for (std::size_t k = 0; k < a.size() && k < b.size() && k < rest.size(); ++k) {
    c.worst = std::max(c.worst, std::abs(int(a[k]) - int(b[k])));
    c.moved += std::abs(int(a[k]) - int(rest[k])) > 16;
  }
  return c;
}

}  // namespace clothlab::test
