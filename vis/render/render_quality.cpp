#include "vis/render/render_quality.hpp"

#include <algorithm>
#include <cmath>

namespace clothlab::vis {

bool software_renderer(std::string_view gl_renderer) {
  for (std::string_view name : {"llvmpipe", "softpipe", "swrast"})
    if (gl_renderer.find(name) != std::string_view::npos) return true;
  return false;
}

RenderQuality resolve_quality(RenderQuality quality, std::string_view gl_renderer) {
  if (quality != RenderQuality::automatic) return quality;
  return software_renderer(gl_renderer) ? RenderQuality::fast : RenderQuality::full;
}

int msaa_samples(RenderQuality resolved, DisplayMode mode) {
  return resolved == RenderQuality::fast && mode != DisplayMode::springs ? 1 : 4;
}

int shadow_map_texels(RenderQuality resolved, int scene_texels) {
  return resolved == RenderQuality::fast ? std::max(512, scene_texels / 2) : scene_texels;
}

int diffusion_atlas_texels(RenderQuality resolved) {
  return resolved == RenderQuality::fast ? 256 : 512;
}

int scaled_shadow_map(int scene_texels, float scale) {
  return std::max(256, int(std::lround(float(scene_texels) * scale)));
}

float window_scale(RenderQuality resolved, DisplayMode mode, float scene_scale) {
  if (msaa_samples(resolved, mode) > 1) return 1.0f;
  return std::clamp(scene_scale, 0.25f, 1.0f);
}

}  // namespace clothlab::vis
