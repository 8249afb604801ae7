#include "sim/scene/spring_presets.hpp"

#include <array>

namespace clothlab {
namespace {

// Chosen on the shipped 32 x 32 scenes (edge 3.75-6.5 cm); docs/materials.md has the measured
// folds, drape and drop of each. cotton: soft folds, slides off a ball; silk: light, many small
// folds; denim: heavy, few broad folds; card: the assignment's uniform stiffness, no folds.
constexpr std::array<SpringPreset, 4> kPresets{{
    {"cotton", 800.0, 400.0, 8.0, 0.05},
    {"silk", 400.0, 100.0, 1.0, 0.02},
    {"denim", 2500.0, 1500.0, 60.0, 0.1},
    {"card", 800.0, 800.0, 800.0, 0.05},
}};

}  // namespace

std::span<const SpringPreset> spring_presets() {
  return kPresets;
}

std::optional<SpringPreset> find_spring_preset(std::string_view name) {
  for (const SpringPreset& p : kPresets)
    if (p.name == name) return p;
  return std::nullopt;
}

void apply_spring_preset(const SpringPreset& preset, SpringSpec& springs) {
  springs.preset = std::string(preset.name);
  springs.stiffness = preset.stretch;
  springs.stretch.reset();
  springs.shear = preset.shear;
  springs.bend = preset.bend;
  springs.damping = preset.damping;
}

}  // namespace clothlab
