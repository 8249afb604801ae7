// Shadowed lighting for fragment shaders (include after frame.glsl): the scene's shadow map and
// the lit surface models that use it. Fragment-only: the kernels turn with gl_FragCoord.
//
// The filter, coloured shadows and the kernel's taps are compile-time choices (frame.glsl).

// The shadow map (vis/render/shadow_pass.cpp): one depth texture read through two samplers, a
// comparing one for PCF and a plain one for the blocker search (docs/rendering.md section 0).
layout(binding = 6) uniform sampler2DShadow u_shadow_compare;
layout(binding = 7) uniform sampler2D u_shadow_depth;
// With a translucent cloth (mode 5, shadow_range.w = 1): the opaque casters' own depth map and the
// product of the translucent layers' transmittances (docs/rendering.md section 5).
layout(binding = 8) uniform sampler2DShadow u_shadow_opaque;
layout(binding = 9) uniform sampler2D u_shadow_colour;

// Interleaved gradient noise (Jimenez 2014, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare"): a per-pixel rotation for the filter kernels, so banding becomes fine noise.
float interleaved_gradient_noise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// 16 points of a Poisson disk in the unit circle.
const vec2 kPoisson[16] = vec2[](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.09418410, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));
// The fast kernels: 4 points of a rotated grid (the 4-sample rotated-grid pattern of
// anti-aliasing) at about the Poisson disk's mean radius, and a diagonal pair of them. Each tap is
// a hardware 2x2 comparison, so two taps already blend four texels across the edge.
const vec2 kRotatedGrid[4] = vec2[](vec2(0.75, 0.25), vec2(-0.25, 0.75), vec2(-0.75, -0.25),
                                    vec2(0.25, -0.75));
const vec2 kDiagonalPair[2] = vec2[](vec2(0.5, 0.5), vec2(-0.5, -0.5));

// The kernel's i-th point in the unit circle.
vec2 kernel_point(int i) {
#if SHADOW_TAPS == 2
  return kDiagonalPair[i];
#elif SHADOW_TAPS == 4
  return kRotatedGrid[i];
#else
  return kPoisson[i];
#endif
}

// A depth-map value as distance from the light along its axis (m): perspective maps store
// non-linear depth (LearnOpenGL "Shadow mapping", linearised depth); orthographic ones are linear.
float linear_light_depth(float d) {
  float n = shadow_range.x, f = shadow_range.y;
  if (shadow_range.z > 0.5) return n + d * (f - n);
  return 2.0 * n * f / (f + n - (2.0 * d - 1.0) * (f - n));
}

// Percentage-closer filtering over a rotated Poisson disk of radius `radius` (shadow-map uv),
// each tap a hardware 2x2 comparison (Reeves, Salesin & Cook 1987) against the receiver's depth
// carried along its own plane to the tap (receiver-plane depth bias, Isidoro 2006), so wide
// kernels on sloped receivers do not shadow the receiver itself.
// With translucent casters each tap is (z <= D_opaque) ? ((z <= D_all) ? 1 : C) : 0: an opaque
// caster blocks fully, a cloth in front tints by its transmittance C, and a receiver between the
// light and the cloth stays untinted.
vec3 pcf(vec3 coord, vec2 dz_duv, float radius, mat2 rotation) {
  vec3 lit = vec3(0.0);
  for (int i = 0; i < SHADOW_TAPS; ++i) {
    vec2 offset = rotation * kernel_point(i) * radius;
    vec3 tap = vec3(coord.xy + offset, coord.z + dot(dz_duv, offset));
    float all_casters = texture(u_shadow_compare, tap);
#if SHADOW_COLOURED
    float opaque = texture(u_shadow_opaque, tap);
    vec3 c = texture(u_shadow_colour, tap.xy).rgb;
    lit += opaque * (all_casters + (1.0 - all_casters) * c);
#else
    lit += vec3(all_casters);
#endif
  }
  return lit / float(SHADOW_TAPS);
}

// Percentage-closer soft shadows (Fernando 2005; NVIDIA's "PCSS Integration" formulas): the
// average depth of the blockers found in a search region sized by the light, the penumbra
// width from similar triangles, then PCF over that width.
vec3 pcss(vec3 coord, vec2 dz_duv, mat2 rotation) {
  float z_receiver = linear_light_depth(coord.z);
  float n = shadow_range.x;
  float light_uv = shadow.z;
  bool ortho = shadow_range.z > 0.5;
  // Blockers lie in the cone from the receiver to the light's extent: its width at the near
  // plane (perspective) or per metre of depth (orthographic, light_uv = angular size / width).
  float search = ortho ? light_uv * (z_receiver - n) : light_uv * (z_receiver - n) / z_receiver;
  search = clamp(search, 2.0 * shadow.y, 0.08);
  float blockers = 0.0, sum = 0.0;
  for (int i = 0; i < SHADOW_TAPS; ++i) {
    vec2 offset = rotation * kernel_point(i) * search;
    float d = texture(u_shadow_depth, coord.xy + offset).r;
    // A blocker lies in front of the receiver's plane at that tap (plus a texel's slack).
    if (d < coord.z + dot(dz_duv, offset) - 2.0 * shadow.y * length(dz_duv) - 1e-5) {
      sum += linear_light_depth(d);
      blockers += 1.0;
    }
  }
  if (blockers == 0.0) return vec3(1.0);
  float z_blocker = sum / blockers;
  // Penumbra width at the receiver, as a fraction of the map: w = size (z_r - z_b) / z_b for a
  // point-like frustum; for an orthographic map the light's angular size times the distance.
  float penumbra = ortho ? light_uv * (z_receiver - z_blocker)
                         : light_uv * (z_receiver - z_blocker) / z_blocker * n / z_receiver;
  return pcf(coord, dz_duv, clamp(penumbra, shadow.y, 0.08), rotation);
}

// How much of the light reaches p, per channel (0 shadowed .. 1 lit; tinted behind a
// translucent cloth) on a surface of normal n. The receiver
// is moved along its normal by about a texel (normal-offset shadows, Holbert 2011) and the
// casters were drawn with a slope-scaled depth offset, so neither acne nor peter-panning shows.
#if SHADOW_FAST_COORD
in vec4 v_shadow_clip;  // shadow_clip() of the vertex shader, interpolated
#endif

vec3 shadow_visibility(vec3 p, vec3 n) {
#if SHADOW_FILTER == 0
  return vec3(1.0);
#else
#if SHADOW_FAST_COORD
  vec4 c = v_shadow_clip;
#else
  vec4 c = shadow_clip(p, n);
#endif
  vec3 coord = c.xyz / c.w * 0.5 + 0.5;
  // The receiver's depth gradient in shadow-map uv, from its screen-space derivatives (taken
  // here, in uniform control flow: callers must not branch around this function).
#if SHADOW_TAPS <= 4 && SHADOW_FILTER == 1
  // The small fast kernel (1.5 texels) relies on the normal offset and the casters' slope-scaled
  // offset alone: the receiver plane's derivatives cost a CPU renderer more than the taps. PCSS
  // keeps them: its search and penumbrae reach far beyond a texel.
  vec2 dz_duv = vec2(0.0);
#else
  vec3 dx = dFdx(coord), dy = dFdy(coord);
  float det = dx.x * dy.y - dx.y * dy.x;
  vec2 dz_duv = abs(det) > 1e-12 ? vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det
                                 : vec2(0.0);
  dz_duv = clamp(dz_duv, vec2(-8.0), vec2(8.0));  // grazing receivers: bounded
#endif
  // Beyond the map's depth range or its borders: lit (the map covers every caster).
  if (coord.z >= 1.0 || any(lessThan(coord.xy, vec2(0.0))) || any(greaterThan(coord.xy, vec2(1.0))))
    return vec3(1.0);
#if SHADOW_TAPS <= 4
  // The rotated grid as it is: with four taps a per-pixel rotation would show as grain, and its
  // sine and cosine cost a CPU renderer more than the taps.
  mat2 rotation = mat2(1.0);
#else
  float angle = 6.2831853 * interleaved_gradient_noise(gl_FragCoord.xy);
  mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
#endif
#if SHADOW_FILTER == 1
  // 1.5 texels of the full map; the fast map has half its texels (vis/render/renderer.cpp).
  return pcf(coord, dz_duv, (SHADOW_TAPS <= 4 ? 0.75 : 1.5) * shadow.y, rotation);
#else
  return pcss(coord, dz_duv, rotation);
#endif
#endif
}

// Lambert (1760) under the scene's light, shadowed, plus a constant ambient: outgoing radiance
// albedo / pi * E, with the 1/pi folded into the light's intensity.
vec3 lambert_lit(vec3 p, vec3 n, vec3 albedo) {
  vec3 l = light_vector(p);
  float cos_theta = max(dot(n, l), 0.0);
  vec3 vis = shadow_visibility(p, n);  // outside any branch: it takes derivatives
  return albedo * (light_irradiance(p) * cos_theta * vis + vec3(light_color.a));
}
