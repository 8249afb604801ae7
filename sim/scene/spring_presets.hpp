// Material presets for the seed springs: `springs.preset = "cotton"` sets the specific stiffness
// of each spring class and the along-spring damping at once; keys written beside it (in the
// file or with --set) override single values. docs/materials.md gives each preset's measured
// behaviour on the shipped scenes.
//
// Why bend is so much softer than stretch: a woven fabric stretches little but bends under its
// own weight (Kawabata's KES-F measurements, 1980; Provot 1995 and Baraff & Witkin 1998 give
// bending its own, much smaller constant). With bend = stretch the seed rule's two-step and
// knight's-move springs hold the sheet flat like card.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "sim/scene/scene.hpp"

namespace clothlab {

struct SpringPreset {
  std::string_view name;
  double stretch = 0.0;  // N/m for a spring one edge long (springs.stiffness)
  double shear = 0.0;    // N/m, grid diagonals
  double bend = 0.0;     // N/m, two-step and knight's-move springs
  double damping = 0.0;  // N s/m, along each spring
};

// Every preset, in the order `clothlab params` lists them.
std::span<const SpringPreset> spring_presets();

// The preset called `name`, or none.
std::optional<SpringPreset> find_spring_preset(std::string_view name);

// Sets the preset's name, stiffnesses and damping on `springs`; a stretch written before is
// dropped (it follows `stiffness` again).
void apply_spring_preset(const SpringPreset& preset, SpringSpec& springs);

}  // namespace clothlab
