// render.quality for the GL renderer at hand (docs/rendering.md, "Render quality"): automatic
// picks fast on a software renderer, where every pixel is shaded by the CPU, and full elsewhere.
#pragma once

#include <string_view>

#include "sim/scene/render_spec.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab::vis {

// Mesa's CPU rasterisers, by the GL_RENDERER string: llvmpipe, softpipe, swrast.
bool software_renderer(std::string_view gl_renderer);

// full or fast: `quality` unless it is automatic.
RenderQuality resolve_quality(RenderQuality quality, std::string_view gl_renderer);

// What fast changes besides the shaders' kernels (vis/render/shading_variant.hpp), for a
// resolved quality (full or fast):
// - samples per pixel of the framebuffer the scene is drawn into: 4x MSAA at full, one at fast
//   (llvmpipe shades a multisampled sRGB target at several times the cost; geometry edges are
//   then aliased: the one place where fast looks different), except in mode 1, whose springs
//   are lines a pixel wide: one sample leaves gaps between them where the floor shows through;
int msaa_samples(RenderQuality resolved, DisplayMode mode);
// - the shadow map's texels per side: the scene's at full, half of them (at least 512) at fast,
//   the filter kernel keeping its width in the world;
int shadow_map_texels(RenderQuality resolved, int scene_texels);
// - mode 6's diffusion atlas, texels per side: 512 at full, 256 at fast.
int diffusion_atlas_texels(RenderQuality resolved);
// - in the window, the scene's pixels per side as a fraction of the window's: render.window_scale
//   at fast (drawn into a target of that size and scaled up with linear filtering; llvmpipe's
//   cost is mostly per pixel), 1 at full and in mode 1, whose springs are lines a pixel wide.
//   Renders (headless) always draw at the size asked for.
float window_scale(RenderQuality resolved, DisplayMode mode, float scene_scale);
// - the shadow map's texels per side for a scene drawn at `scale` of the window's pixels: as
//   many texels to a pixel as at 1 (at least 256, the smallest render.shadow_map_size).
int scaled_shadow_map(int scene_texels, float scale);

}  // namespace clothlab::vis
