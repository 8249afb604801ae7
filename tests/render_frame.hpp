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
// whether their sizes agree, the largest channel difference between them, and the channels
// more than 16/255 from `rest`.
struct FrameComparison {
  bool same_size = false;
  int worst = 0;
  long moved = 0;
};
inline FrameComparison compare_frames(const std::vector<std::uint8_t>& a,
                                      const std::vector<std::uint8_t>& b,
                                      const std::vector<std::uint8_t>& rest) {
  FrameComparison c;
  c.same_size = a.size() == b.size();
  for (std::size_t k = 0; k < a.size() && k < b.size() && k < rest.size(); ++k) {
    c.worst = std::max(c.worst, std::abs(int(a[k]) - int(b[k])));
    c.moved += std::abs(int(a[k]) - int(rest[k])) > 16;
  }
  return c;
}

// The renderer's current cloth `device` (a GPU solver) drawn, then the renderer switched to
// `cpu` (holding the same state) and that drawn: the two frames compared, as above.
inline FrameComparison compare_with_cpu(vis::HeadlessRenderer& renderer, Solver& device,
                                        Solver& cpu, const vis::ViewSettings& view,
                                        const std::vector<std::uint8_t>& rest) {
  const std::vector<std::uint8_t> from_device = render_frame(renderer, device, view);
  renderer.set_cloth(cpu);
  return compare_frames(from_device, render_frame(renderer, cpu, view), rest);
}

}  // namespace clothlab::test
