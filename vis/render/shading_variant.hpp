// What the lit shaders (shaders/lighting.glsl and the passes that include it) are compiled for:
// the shadow filter, coloured shadows and the PCF kernel's size are #defines, not uniforms, so
// llvmpipe does not pay for the filters a frame does not use (gl/program_variants.hpp).
#pragma once

#include <string>

#include "sim/scene/render_spec.hpp"

namespace clothlab::vis {

struct ShadingVariant {
  ShadowFilter filter = ShadowFilter::pcf;  // none: no shadow map is read
  bool coloured = false;  // mode 5: a translucent cloth tints the shadows it casts
  bool fast = false;  // render.quality fast: PCF in 2 taps, PCSS in 4 (search and filter), not 16

  // "#define SHADOW_FILTER 1\n#define SHADOW_COLOURED 0\n#define SHADOW_TAPS 16\n"
  std::string defines() const;
};

}  // namespace clothlab::vis
