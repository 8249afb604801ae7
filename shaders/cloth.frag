#version 450 core
#include "frame.glsl"
#include "lighting.glsl"
#include "brdf.glsl"
#include "weave.glsl"
#include "yarn.glsl"

// Colour by a scalar through a colour map (ViewSettings::color), or
// 2: world-space normal as colour (n * 0.5 + 0.5); 3: Lambert with the fabric texture; 4-6 below.
layout(location = 1) uniform float u_texture_repeat;  // fabric repeats per cloth
layout(location = 3) uniform vec2 u_range;      // the scalar's min and max
layout(location = 4) uniform int u_shaded;      // 1: the mapped colour lit as an albedo
// Mode 4, the cloth's look ([render.cloth]): x Oren-Nayar roughness, y sheen strength, z sheen
// alpha; the metal threads' F0 (linear, 0 when there are none) and their glint lights.
layout(location = 5) uniform vec3 u_look;
layout(location = 6) uniform vec3 u_metal_f0;
layout(location = 7) uniform vec3 u_glint_lights[2];  // positions (m), specular only
layout(location = 9) uniform vec3 u_flat_albedo;      // sRGB, used when u_use_flat = 1
layout(location = 10) uniform int u_use_flat;         // a plain colour instead of the weave
layout(location = 11) uniform vec2 u_translucency;    // mode 5: coverage c, transmission tau
layout(binding = 0) uniform sampler2D u_fabric;
layout(binding = 1) uniform sampler2D u_lut;  // 256 x 1 colour map, sRGB
layout(binding = 2) uniform sampler2D u_threads;  // r: metal thread mask, g: weft on top (linear)
// Mode 6's subsurface imitation (vis/passes/diffusion_pass.cpp): the irradiance on the lit side
// blurred by three growing Gaussians in the cloth's UV atlas, and their weights per channel
// (x: the sharp per-pixel term, then the three blurs; each channel sums to 1).
layout(binding = 10) uniform sampler2D u_diffused[3];
layout(location = 12) uniform vec4 u_diffusion_weights[3];  // r, g, b rows: (w0, w1, w2, w3)
layout(location = 15) uniform int u_subsurface;            // 1: the blurred terms are in use
layout(location = 16) uniform int u_glints;                // mode 4: 1 = the glint lights are on

const vec3 kNanColor = vec3(1.0, 0.0, 1.0);  // magenta: no finite value

in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in float v_scalar;
in vec4 v_tangent;
in vec2 v_atlas_uv;
out vec4 color;

// Key 4: the layered cloth BRDF (Oren-Nayar base under a Charlie sheen, shaders/brdf.glsl) and,
// where the thread mask says so, gold or silver threads: anisotropic GGX with its long axis along
// the thread (the weft runs along the tangent, the warp along the bitangent). Radiance is
// pi * f * E * cos, so a Lambert surface gives mode 3's albedo * E * cos; two glint lights near
// the camera add the metal lobe only.
vec3 cloth_brdf_lit(vec3 n, vec3 albedo) {
  vec3 v = normalize(eye.xyz - v_world);
  vec3 l = light_vector(v_world);
  vec3 vis = shadow_visibility(v_world, n);  // outside branches: it takes derivatives
  vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
  float w = v_tangent.w < 0.0 ? -1.0 : 1.0;
  vec3 b = w * cross(n, t);
  if (!gl_FrontFacing) b = -b;  // n was turned to the viewer: keep the frame right-handed
  vec2 thread = texture(u_threads, v_uv * u_texture_repeat).rg;
  float metal = dot(u_metal_f0, vec3(1.0)) > 0.0 ? thread.r : 0.0;
  vec3 along = thread.g > 0.5 ? t : b;  // the thread on top here
  vec3 across = thread.g > 0.5 ? b : -t;
  float sigma = on_sigma_from_roughness(u_look.x);
  vec3 sheen = sqrt(albedo) * u_look.y;
  float nl = dot(n, l);
  vec3 radiance = vec3(0.0);
  if (nl > 0.0) {
    vec3 f = brdf_cloth(n, v, l, albedo, sigma, sheen, u_look.z);
    vec3 fm = brdf_metal_aniso(u_metal_f0, 0.35, 0.08, n, along, across, v, l);
    radiance = kPi * mix(f, fm, metal) * light_irradiance(v_world) * nl * vis;
  }
  for (int i = 0; i < 2 * u_glints; ++i) {
    vec3 to_glint = u_glint_lights[i] - v_world;
    vec3 gl = normalize(to_glint);
    float gnl = dot(n, gl);
    if (gnl > 0.0 && metal > 0.0) {
      vec3 fm = brdf_metal_aniso(u_metal_f0, 0.35, 0.08, n, along, across, v, gl);
      radiance += kPi * metal * fm * 0.25 * light_irradiance(v_world) * gnl;
    }
  }
  return radiance + albedo * light_color.a;
}

// Key 5: translucent cloth. Light on the side we see is reflected (Lambert); light from behind
// comes through, tinted by the dye (diffuse transmission tau * filter(albedo), shaders/yarn.glsl:
// the glow of a back-lit cloth, as KHR_materials_translucency); the threads cover a fraction c
// of the surface, which is the alpha the cloth is blended with, so what lies behind shows
// through the gaps.
vec4 translucent_lit(vec3 n, vec3 albedo) {
  vec3 l = light_vector(v_world);
  vec3 vis = shadow_visibility(v_world, n);  // outside branches: it takes derivatives
  float nl = dot(n, l);
  vec3 e = light_irradiance(v_world) * abs(nl) * vis;
  vec3 lit = nl > 0.0 ? albedo * e : u_translucency.y * yarn_filter(albedo) * e;
  return vec4(lit + albedo * light_color.a, u_translucency.x);
}

// Key 6: the weave's relief in the per-vertex frame; seen from behind, the relief is the
// front's turned inside out (the mapped normal negated). With the subsurface imitation on, the
// light that reaches the lit side is spread through the yarn (texture-space diffusion, d'Eon &
// Luebke, GPU Gems 3 ch. 14): the per-pixel irradiance keeps a share w0 per channel, the rest
// comes from its blurred copies in the UV atlas, red spreading farthest.
vec3 weave_lit(vec3 n_seen, vec3 albedo) {
  vec3 n_front = gl_FrontFacing ? n_seen : -n_seen;
  vec3 mapped = weave_normal_front(n_front, v_tangent, v_uv * u_texture_repeat);
  vec3 n = gl_FrontFacing ? mapped : -mapped;
  vec3 l = light_vector(v_world);
  vec3 vis = shadow_visibility(v_world, n);  // outside branches: it takes derivatives
  vec3 e = light_irradiance(v_world) * max(dot(n, l), 0.0) * vis;
  if (u_subsurface == 1) {
    // The atlas holds the irradiance of the side facing the light: it reaches the viewer only
    // on that side.
    bool lit_side = dot(n_seen, l) > 0.0;
    vec3 w0 = vec3(u_diffusion_weights[0].x, u_diffusion_weights[1].x, u_diffusion_weights[2].x);
    vec3 spread = vec3(0.0);
    for (int k = 0; k < 3; ++k) {
      vec3 wk = vec3(u_diffusion_weights[0][k + 1], u_diffusion_weights[1][k + 1],
                     u_diffusion_weights[2][k + 1]);
      spread += wk * texture(u_diffused[k], v_atlas_uv).rgb;
    }
    e = w0 * e + (lit_side ? spread : vec3(0.0));
  }
  return albedo * (e + vec3(light_color.a));
}

// CLOTH_MODE (2-6) and CLOTH_COLOR_BY (1: coloured by a scalar) are compile-time choices, one
// program per mode (vis/passes/cloth_pass.cpp): llvmpipe runs every branch on a uniform with its
// lanes masked off, so one shader for all modes cost mode 3 the BRDF and the weave as well.
#ifndef CLOTH_MODE
#define CLOTH_MODE 3
#endif
#ifndef CLOTH_COLOR_BY
#define CLOTH_COLOR_BY 0
#endif

void main() {
  // Cloth has two sides: shade the side we see, with the normal turned towards us.
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
#if CLOTH_COLOR_BY
  // Mapped per fragment (the interpolated scalar, not interpolated colours), clamped at the
  // ends; texel centres at (0.5 + 255 t) / 256 so t = 0 and 1 give the table's end entries.
  float t = clamp((v_scalar - u_range.x) / (u_range.y - u_range.x), 0.0, 1.0);
  vec3 mapped = isnan(v_scalar) ? kNanColor : texture(u_lut, vec2((0.5 + 255.0 * t) / 256.0, 0.5)).rgb;
  color = vec4(u_shaded == 1 ? lambert_lit(v_world, n, mapped) : mapped, 1.0);
#elif CLOTH_MODE == 2
  color = vec4(srgb_to_linear(n * 0.5 + 0.5), 1.0);
#else
  vec3 albedo = u_use_flat == 1 ? srgb_to_linear(u_flat_albedo)
                                : texture(u_fabric, v_uv * u_texture_repeat).rgb;
#if CLOTH_MODE == 5
  color = translucent_lit(n, albedo);
#elif CLOTH_MODE == 4
  color = vec4(cloth_brdf_lit(n, albedo), 1.0);
#elif CLOTH_MODE == 6
  color = vec4(weave_lit(n, albedo), 1.0);
#else
  color = vec4(lambert_lit(v_world, n, albedo), 1.0);
#endif
#endif
}
