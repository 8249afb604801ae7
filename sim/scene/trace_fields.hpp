// The fields a trace records, by name: the scene's [trace] fields and clothlab.trace's `fields`.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "sim/scene/name_list.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab {

inline constexpr std::array<std::string_view, 4> kTraceFields = {"position", "velocity", "force",
                                                                 "energy"};

// The flag of `spec` that field `name` sets; null for a name not in kTraceFields.
inline bool* trace_field(TraceSpec& spec, std::string_view name) {
  return name == kTraceFields[0]   ? &spec.position
         : name == kTraceFields[1] ? &spec.velocity
         : name == kTraceFields[2] ? &spec.force
         : name == kTraceFields[3] ? &spec.energy
                                   : nullptr;
}

// "position, velocity, force, energy", for messages.
inline std::string trace_field_list() {
  return comma_list(kTraceFields, [](std::string_view name) { return name; });
}

}  // namespace clothlab
