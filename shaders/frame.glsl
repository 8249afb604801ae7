// Per-frame values shared by every pass (std140 uniform block, binding 0), and the light model.

layout(std140, binding = 0) uniform Frame {
  mat4 view_proj;
  vec4 eye;             // xyz: camera position (m)
  vec4 light_position;  // xyz: point light position (m)
  vec4 light_color;     // rgb: radiant intensity (linear), a: ambient level
  vec4 params;          // x: strain range of the colour map, y: floor height (m)
};

// Point light with inverse-square falloff and a Lambert surface (Lambert 1760): outgoing
// radiance albedo / pi * E, with E = I cos(theta) / d^2; the 1/pi is folded into the intensity.
vec3 lambert_point_light(vec3 p, vec3 n, vec3 albedo) {
  vec3 to_light = light_position.xyz - p;
  float d2 = max(dot(to_light, to_light), 1e-4);
  float cos_theta = max(dot(n, to_light * inversesqrt(d2)), 0.0);
  return albedo * (light_color.rgb * cos_theta / d2 + vec3(light_color.a));
}

// The framebuffer is sRGB: GL encodes what a shader writes. A colour meant as display values
// (a colour map, a normal shown as colour) is decoded first so it arrives unchanged
// (IEC 61966-2-1 transfer function).
vec3 srgb_to_linear(vec3 c) {
  vec3 low = c / 12.92;
  vec3 high = pow((c + 0.055) / 1.055, vec3(2.4));
  return mix(high, low, lessThanEqual(c, vec3(0.04045)));
}
