// Names of enum values as they appear in scene files and messages.
#include <array>
#include <utility>

#include "sim/scene/scene.hpp"

namespace clothlab {

namespace {

constexpr std::array<std::pair<IntegratorKind, const char*>, 8> kIntegratorNames{{
    {IntegratorKind::explicit_euler, "explicit_euler"},
    {IntegratorKind::symplectic_euler, "symplectic_euler"},
    {IntegratorKind::seed_hack, "seed_hack"},
    {IntegratorKind::verlet, "verlet"},
    {IntegratorKind::rk4, "rk4"},
    {IntegratorKind::implicit_euler, "implicit_euler"},
    {IntegratorKind::xpbd, "xpbd"},
    {IntegratorKind::local_global, "local_global"},
}};

}  // namespace

const char* to_string(IntegratorKind kind) {
  for (const auto& [k, name] : kIntegratorNames)
    if (k == kind) return name;
  return "unknown";
}

std::optional<IntegratorKind> integrator_from_string(const std::string& name) {
  for (const auto& [k, text] : kIntegratorNames)
    if (name == text) return k;
  return std::nullopt;
}

}  // namespace clothlab
