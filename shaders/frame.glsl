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
