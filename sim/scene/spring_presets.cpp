#include "sim/scene/spring_presets.hpp"

#include <array>

namespace clothlab {
namespace {

// Chosen on the shipped 32 x 32 scenes (edge 3.75-6.5 cm); docs/materials.md has the measured
// folds, drape and drop of each. `card` is the assignment's uniform stiffness.
constexpr std::array<SpringPreset, 4> kPresets{{
    {"cotton", 800.0, 400.0, 8.0, 0.05, "soft folds, slides off a ball"},
    {"silk", 400.0, 100.0, 1.0, 0.02, "light, many small folds"},
    {"denim", 2500.0, 1500.0, 60.0, 0.1, "heavy, few broad folds"},
    {"card", 800.0, 800.0, 800.0, 0.05, "bends as stiffly as it stretches: no folds"},
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
