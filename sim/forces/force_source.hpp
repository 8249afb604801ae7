// Which part of the force field a force evaluation fills: the total, or one source alone.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace clothlab {

// total = springs + gravity + drag + wind (the force the integrators see).
enum class ForceSource { total, springs, gravity, drag, wind };

inline constexpr std::array<ForceSource, 5> kAllForceSources = {
    ForceSource::total, ForceSource::springs, ForceSource::gravity, ForceSource::drag,
    ForceSource::wind};

// "total", "springs", "gravity", "drag", "wind".
std::string_view force_source_name(ForceSource source);
// The inverse of force_source_name (exact, lower case); nullopt for anything else.
std::optional<ForceSource> parse_force_source(std::string_view name);

}  // namespace clothlab
