#version 450 core
#include "frame.glsl"
#include "lighting.glsl"

// Colour by a scalar through a colour map (ViewSettings::color), or
// 2: world-space normal as colour (n * 0.5 + 0.5); 3: Lambert with the fabric texture.
layout(location = 0) uniform int u_mode;
layout(location = 1) uniform float u_texture_repeat;  // fabric repeats per cloth
layout(location = 2) uniform int u_color_by;   // 1: colour by the scalar through the map
layout(location = 3) uniform vec2 u_range;      // the scalar's min and max
layout(location = 4) uniform int u_shaded;      // 1: the mapped colour lit as an albedo
layout(binding = 0) uniform sampler2D u_fabric;
layout(binding = 1) uniform sampler2D u_lut;  // 256 x 1 colour map, sRGB

const vec3 kNanColor = vec3(1.0, 0.0, 1.0);  // magenta: no finite value

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in float v_scalar;
out vec4 color;

void main() {
  // Cloth has two sides: shade the side we see, with the normal turned towards us.
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  if (u_color_by == 1) {
    // Mapped per fragment (the interpolated scalar, not interpolated colours), clamped at the
    // ends; texel centres at (0.5 + 255 t) / 256 so t = 0 and 1 give the table's end entries.
    float t = clamp((v_scalar - u_range.x) / (u_range.y - u_range.x), 0.0, 1.0);
    vec3 mapped = isnan(v_scalar) ? kNanColor : texture(u_lut, vec2((0.5 + 255.0 * t) / 256.0, 0.5)).rgb;
    color = vec4(u_shaded == 1 ? lambert_lit(v_world, n, mapped) : mapped, 1.0);
    return;
  }
  if (u_mode == 2) {
    color = vec4(srgb_to_linear(n * 0.5 + 0.5), 1.0);
    return;
  }
  vec3 albedo = texture(u_fabric, v_uv * u_texture_repeat).rgb;
  color = vec4(lambert_lit(v_world, n, albedo), 1.0);
}
