// Per-frame values shared by every pass (std140 uniform block, binding 0; FrameBlock in
// vis/render/renderer.cpp), the scene's light and its shadow map.

layout(std140, binding = 0) uniform Frame {
  mat4 view_proj;
  mat4 light_view_proj;  // world -> the shadow map's clip space
  vec4 eye;              // xyz: camera position (m)
  vec4 light_position;   // xyz: spot light position (m); w: 0 spot, 1 directional
  vec4 light_direction;  // xyz: unit direction the light travels; w: cos of the cone's edge
  vec4 light_color;      // rgb: radiant intensity (spot) or irradiance (directional), a: ambient
  vec4 params;           // x: strain range of the colour map, y: floor height (m)
  vec4 shadow;           // x: filter (0 none, 1 PCF, 2 PCSS), y: 1 / map size, z: light size
                         // in shadow-map uv at unit distance, w: normal offset (m)
  vec4 shadow_range;     // x: near, y: far (m, spot: perspective), z: 1 = orthographic,
                         // w: 1 = translucent casters (coloured shadows, mode 5)
};

const float kPi = 3.14159265358979;

// Compile-time choices of the lit shaders (vis/render/shading_variant.hpp; llvmpipe pays for both
// sides of a branch on a uniform): SHADOW_FILTER 0 none, 1 PCF, 2 PCSS; SHADOW_COLOURED 1 where a
// translucent cloth tints the shadows (mode 5); SHADOW_TAPS, the kernel's taps: 16 (full) or 4
// (render.quality fast: a rotated grid of four hardware 2x2 comparisons, the same radius in the
// world). SHADOW_FAST_COORD: the vertex shader computes the receiver's shadow-map coordinate
// (shadow_clip at the vertices, interpolated) instead of every fragment.
#ifndef SHADOW_FILTER
#define SHADOW_FILTER 1
#endif
#ifndef SHADOW_COLOURED
#define SHADOW_COLOURED 0
#endif
#ifndef SHADOW_TAPS
#define SHADOW_TAPS 16
#endif
#define SHADOW_FAST_COORD (SHADOW_TAPS <= 4 && SHADOW_FILTER != 0)

// The framebuffer is sRGB: GL encodes what a shader writes. A colour meant as display values
// (a colour map, a normal shown as colour) is decoded first so it arrives unchanged
// (IEC 61966-2-1 transfer function).
vec3 srgb_to_linear(vec3 c) {
  vec3 low = c / 12.92;
  vec3 high = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(high, low, lessThanEqual(c, vec3(0.04045)));
}

// Unit vector from p towards the light.
vec3 light_vector(vec3 p) {
  return light_position.w > 0.5 ? -light_direction.xyz : normalize(light_position.xyz - p);
}

// Irradiance at p on a surface facing the light, without the cosine: a spot light's radiant
// intensity over d^2 inside its cone (a smooth edge over the outer 10 % of the cone's cosine
// range), or the directional light's irradiance.
vec3 light_irradiance(vec3 p) {
  if (light_position.w > 0.5) return light_color.rgb;
  vec3 d = p - light_position.xyz;
  float d2 = max(dot(d, d), 1e-4);
  float c = dot(d * inversesqrt(d2), light_direction.xyz);
  float edge = light_direction.w;
  float cone = smoothstep(edge, edge + 0.1 * (1.0 - edge), c);
  return light_color.rgb * cone / d2;
}

// The receiver point p in the shadow map's clip space, moved along its normal n (turned towards
// the light) by about a texel, more on a slope (normal-offset shadows, Holbert 2011), so neither
// acne nor peter-panning shows; the casters are drawn with a slope-scaled depth offset too.
vec4 shadow_clip(vec3 p, vec3 n) {
  vec3 l = light_vector(p);
  float nl = dot(n, l);
  float slope = 1.0 - abs(nl);
  return light_view_proj * vec4(p + n * shadow.w * (0.5 + slope), 1.0);
}

// At a vertex (SHADOW_FAST_COORD), with n turned to the side the light reaches: a two-sided
// cloth's vertex does not know which side is seen, and only the lit side's shadow shows.
vec4 shadow_clip_vertex(vec3 p, vec3 n) {
  return shadow_clip(p, dot(n, light_vector(p)) < 0.0 ? -n : n);
}
