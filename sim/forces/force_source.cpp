#include "sim/forces/force_source.hpp"

namespace clothlab {

std::string_view force_source_name(ForceSource source) {
  switch (source) {
    case ForceSource::total:
      return "total";
    case ForceSource::springs:
      return "springs";
    case ForceSource::gravity:
      return "gravity";
    case ForceSource::drag:
      return "drag";
    case ForceSource::wind:
      return "wind";
  }
  return "total";
}

std::optional<ForceSource> parse_force_source(std::string_view name) {
  for (ForceSource s : kAllForceSources)
    if (force_source_name(s) == name) return s;
  return std::nullopt;
}

}  // namespace clothlab
