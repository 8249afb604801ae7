#include "vis/render/shading_variant.hpp"

namespace clothlab::vis {

std::string ShadingVariant::defines() const {
  const int f = filter == ShadowFilter::pcss ? 2 : filter == ShadowFilter::pcf ? 1 : 0;
  // Fast: PCF in two taps (a diagonal pair), PCSS's blocker search and filter in four.
  const int taps = !fast ? 16 : f == 2 ? 4 : 2;
  return "#define SHADOW_FILTER " + std::to_string(f) + "\n#define SHADOW_COLOURED " +
         std::to_string(coloured ? 1 : 0) + "\n#define SHADOW_TAPS " + std::to_string(taps) + "\n";
}

}  // namespace clothlab::vis
