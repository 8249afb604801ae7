// The image tests render a solver's current state as the applications do: one field snapshot
// of what the view needs (sim/fields/frame_fields.hpp), then the const renderer calls.
#pragma once

#include <cstdint>
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

}  // namespace clothlab::test
