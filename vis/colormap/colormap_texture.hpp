// The colour map as the 256x1 lookup texture the field shaders sample (docs/rendering.md section
// 8).
#pragma once

#include "gl/objects.hpp"
#include "vis/colormap/colormap.hpp"

namespace clothlab::vis {

// A 256x1 GL_TEXTURE_2D holding colormap_table(map) as GL_SRGB8 (the entries are sRGB, so GL
// decodes them to linear light before filtering), GL_LINEAR, clamped to the edge. Sample it at
// u = (0.5 + 255 t) / 256 so t = 0 and t = 1 land on the first and last texel centres; what it
// then shows is colormap_sample(map, t). Needs a current GL 4.5 context.
Texture make_colormap_texture(ColorMap map);

}  // namespace clothlab::vis
