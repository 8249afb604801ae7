#version 450 core
#include "frame.glsl"

// Mode 6's irradiance pass (vis/passes/diffusion_pass.cpp): the cloth rasterised in its UV atlas
// (d'Eon & Luebke 2007: gl_Position from the texture coordinate), carrying what lighting needs.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 5) in vec4 tangent;
layout(location = 6) in vec2 atlas_uv;

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out vec4 v_tangent;
#if SHADOW_FAST_COORD
out vec4 v_shadow_clip;
#endif

void main() {
  v_world = position;
  v_normal = normal;
  v_uv = uv;
  v_tangent = tangent;
  gl_Position = vec4(atlas_uv * 2.0 - 1.0, 0.0, 1.0);
#if SHADOW_FAST_COORD
  v_shadow_clip = shadow_clip_vertex(position, normal);
#endif
}
