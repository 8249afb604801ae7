// Cloth and metal-thread BRDFs (docs/rendering.md section 2), written once in the common subset of
// GLSL 4.50 and C++ with GLM: vis/shading/brdf.hpp includes this very file into the C++
// namespace clothlab::vis::brdf, where tests/brdf_test.cpp checks normalisation, reciprocity and
// energy on the CPU. Rules for editing:
// - only plain functions of values (no out/inout parameters, no swizzles beyond .x/.y/.z reads);
// - float literals carry the f suffix (valid GLSL since 1.30; keeps C++ in float, since GLM's
//   vec3 * double does not compile);
// - every function starts with BRDF_FN (empty in GLSL, `inline` in C++);
// - no #version: the including shader has it.
// Conventions: every vector is unit length and points away from the surface (N normal, V to the
// eye, L to the light, H = normalize(V + L)); each function returns the BRDF value f, not f*cos;
// alpha = perceptual roughness^2 for the microfacet lobes.
#ifndef CLOTHLAB_BRDF_GLSL
#define CLOTHLAB_BRDF_GLSL

#ifndef BRDF_FN
#define BRDF_FN
#endif

const float BRDF_PI = 3.14159265358979f;

// Normal-incidence reflectance F0 of the thread metals, linear RGB (Real-Time Rendering 4th ed.,
// Akenine-Moeller et al. 2018, table 9.2).
const vec3 BRDF_F0_GOLD = vec3(1.00f, 0.71f, 0.29f);
const vec3 BRDF_F0_SILVER = vec3(0.95f, 0.93f, 0.88f);

// ---- Diffuse --------------------------------------------------------------------------------

// Lambert (1760): f = albedo / pi.
BRDF_FN vec3 brdf_lambert(vec3 albedo) {
  return albedo * (1.0f / BRDF_PI);
}

// The Oren-Nayar roughness sigma (radians: the standard deviation of the facet slope angle) for a
// [0, 1] diffuse roughness, mapped as MaterialX does (sigma = roughness * pi).
BRDF_FN float on_sigma_from_roughness(float roughness) {
  return roughness * BRDF_PI;
}

// Oren-Nayar (1994) qualitative model in Fujii's trig-free form ("A tiny improvement of
// Oren-Nayar reflectance model", 2012; MaterialX mx_oren_nayar_diffuse, pbrlib
// mx_microfacet_diffuse.glsl): s = L.V - N.L N.V, t = max(N.L, N.V) where s > 0 else 1,
// f = albedo / pi * (A + B s / t), A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33),
// B = 0.45 sigma^2 / (sigma^2 + 0.09). sigma in radians; sigma = 0 gives Lambert exactly.
// Symmetric in L and V (reciprocal); its directional albedo stays below 1 for albedo 1.
BRDF_FN vec3 brdf_oren_nayar(vec3 albedo, float sigma, float NdotL, float NdotV, float LdotV) {
  float s = LdotV - NdotL * NdotV;
  float t = s > 0.0f ? max(max(NdotL, NdotV), 1e-6f) : 1.0f;
  float sigma2 = sigma * sigma;
  float a = 1.0f - 0.5f * sigma2 / (sigma2 + 0.33f);
  float b = 0.45f * sigma2 / (sigma2 + 0.09f);
  return albedo * ((a + b * s / t) / BRDF_PI);
}

// ---- Sheen ----------------------------------------------------------------------------------

// "Charlie" sheen distribution (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen
// BRDF"; Filament D_Charlie): D = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi), normalised so
// that the integral of D (N.H) over the hemisphere is 1. alpha is clamped to >= 0.07 (threeify
// charlie.glsl) and sin^2 to >= 2^-7 (Filament) so it stays finite.
BRDF_FN float d_charlie(float alpha, float NdotH) {
  float inv_alpha = 1.0f / max(alpha, 0.07f);
  float sin2h = max(1.0f - NdotH * NdotH, 0.0078125f);
  return (2.0f + inv_alpha) * pow(sin2h, 0.5f * inv_alpha) / (2.0f * BRDF_PI);
}

// Neubelt & Pettineo's sheen visibility ("Crafting a Next-Gen Material Pipeline for The Order:
// 1886", 2013; Filament V_Neubelt): V = 1 / (4 (N.L + N.V - N.L N.V)). Not energy conserving.
BRDF_FN float v_neubelt(float NdotV, float NdotL) {
  return 1.0f / max(4.0f * (NdotL + NdotV - NdotL * NdotV), 1e-6f);
}

// The sheen lobe (Filament cloth model, F = 1): f = sheen_color D_Charlie V_Neubelt.
BRDF_FN vec3 brdf_sheen(vec3 sheen_color, float alpha, float NdotH, float NdotV, float NdotL) {
  return sheen_color * (d_charlie(alpha, NdotH) * v_neubelt(NdotV, NdotL));
}

// Directional albedo E(N.V, alpha) of brdf_sheen with sheen_color 1 (the integral of f cos over
// the light directions). Our own fit (not MaterialX's curve fit, which belongs to its own sheen
// visibility): a rational function of sqrt(N.V) and sqrt(alpha), fitted near-minimax to a table
// integrated numerically (600 x 600 cosine-weighted grid) for N.V in [0.05, 1], alpha in
// [0.07, 1]; alpha is clamped to that range. Its error there was within +-0.0064; the constant
// +0.006 biases it up so that it never underestimates (the layered furnace needs that):
// fit - E is in [0, 0.015] (tests/brdf_test.cpp checks it against its own integration).
// E exceeds 1 where Neubelt's V gains energy (alpha < 0.1 at grazing N.V).
BRDF_FN float sheen_albedo(float NdotV, float alpha) {
  float x = sqrt(clamp(NdotV, 0.0f, 1.0f));
  float y = sqrt(clamp(alpha, 0.07f, 1.0f));
  float num = 0.043173f - 0.19527f * x + 0.42996f * y - 0.63231f * x * y + 0.18491f * x * x +
              0.31319f * y * y;
  float den = -0.025277f + 0.0404f * x + 0.22426f * y - 0.38794f * x * y + 0.14326f * x * x + y * y;
  return max(num / den + 0.006f, 0.0f);
}

// The layered cloth BRDF for one light: sheen over Oren-Nayar (KHR_materials_sheen):
// f = f_sheen + f_base * min(1 - max3(sheen_color) E(N.V), 1 - max3(sheen_color) E(N.L)).
// The min over both directions is the glTF spec's reciprocal form of the albedo scaling. Where
// Neubelt's lobe reflects more than it receives (E > 1: alpha < 0.1, grazing) the sheen lobe is
// divided by max(1, E(N.V), E(N.L)), which keeps the layer's albedo <= 1 and is reciprocal too.
// sigma: Oren-Nayar roughness (radians); sheen_alpha: Charlie alpha. Zero below the horizon.
BRDF_FN vec3 brdf_cloth(vec3 N, vec3 V, vec3 L, vec3 albedo, float sigma, vec3 sheen_color,
                        float sheen_alpha) {
  float NdotL = min(dot(N, L), 1.0f);
  float NdotV = min(dot(N, V), 1.0f);
  if (NdotL <= 0.0f || NdotV <= 0.0f) return vec3(0.0f);
  float NdotH = clamp(dot(N, normalize(V + L)), 0.0f, 1.0f);
  float e_v = sheen_albedo(NdotV, sheen_alpha);
  float e_l = sheen_albedo(NdotL, sheen_alpha);
  float sheen_max = max(sheen_color.x, max(sheen_color.y, sheen_color.z));
  float base_scale = max(min(1.0f - sheen_max * e_v, 1.0f - sheen_max * e_l), 0.0f);
  float sheen_norm = max(1.0f, max(e_v, e_l));
  return brdf_sheen(sheen_color, sheen_alpha, NdotH, NdotV, NdotL) / sheen_norm +
         brdf_oren_nayar(albedo, sigma, NdotL, NdotV, dot(L, V)) * base_scale;
}

// ---- Metal (gold and silver threads) --------------------------------------------------------

// GGX / Trowbridge-Reitz distribution (Walter et al. 2007; Filament D_GGX form):
// D = alpha^2 / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2), written as k^2 / pi with
// k = alpha / (1 - (N.H)^2 + (N.H alpha)^2). alpha > 0.
BRDF_FN float d_ggx(float alpha, float NdotH) {
  float a = NdotH * alpha;
  float k = alpha / max(1.0f - NdotH * NdotH + a * a, 1e-12f);
  return k * k / BRDF_PI;
}

// Anisotropic GGX (Burley 2012; Filament D_GGX_Anisotropic): ax along the tangent T, ay along
// the bitangent B: D = 1 / (pi ax ay ((T.H/ax)^2 + (B.H/ay)^2 + (N.H)^2)^2).
BRDF_FN float d_ggx_aniso(float ax, float ay, float NdotH, float TdotH, float BdotH) {
  float a2 = ax * ay;
  vec3 w = vec3(ay * TdotH, ax * BdotH, a2 * NdotH);
  float w2 = a2 / max(dot(w, w), 1e-30f);
  return a2 * w2 * w2 / BRDF_PI;
}

// Height-correlated Smith visibility for GGX, V = G2 / (4 N.L N.V) (Heitz 2014, "Understanding
// the Masking-Shadowing Function in Microfacet-Based BRDFs"; Filament V_SmithGGXCorrelated).
BRDF_FN float v_smith_ggx_correlated(float alpha, float NdotV, float NdotL) {
  float a2 = alpha * alpha;
  float ggx_v = NdotL * sqrt(NdotV * NdotV * (1.0f - a2) + a2);
  float ggx_l = NdotV * sqrt(NdotL * NdotL * (1.0f - a2) + a2);
  return 0.5f / max(ggx_v + ggx_l, 1e-12f);
}

// Its anisotropic form (Heitz 2014; Filament V_SmithGGXCorrelated_Anisotropic).
BRDF_FN float v_smith_ggx_correlated_aniso(float ax, float ay, float TdotV, float BdotV,
                                           float TdotL, float BdotL, float NdotV, float NdotL) {
  float lambda_v = NdotL * length(vec3(ax * TdotV, ay * BdotV, NdotV));
  float lambda_l = NdotV * length(vec3(ax * TdotL, ay * BdotL, NdotL));
  return 0.5f / max(lambda_v + lambda_l, 1e-12f);
}

// Schlick's Fresnel (Schlick 1994): F = F0 + (1 - F0) (1 - V.H)^5.
BRDF_FN vec3 f_schlick(vec3 f0, float VdotH) {
  float x = clamp(1.0f - VdotH, 0.0f, 1.0f);
  float x2 = x * x;
  return f0 + (vec3(1.0f) - f0) * (x2 * x2 * x);
}

// Metallic GGX (Cook-Torrance with the terms above; Filament's standard model with metallic 1):
// f = D V F. Zero below the horizon.
BRDF_FN vec3 brdf_metal(vec3 f0, float alpha, vec3 N, vec3 V, vec3 L) {
  float NdotL = min(dot(N, L), 1.0f);
  float NdotV = min(dot(N, V), 1.0f);
  if (NdotL <= 0.0f || NdotV <= 0.0f) return vec3(0.0f);
  vec3 H = normalize(V + L);
  float NdotH = clamp(dot(N, H), 0.0f, 1.0f);
  float VdotH = clamp(dot(V, H), 0.0f, 1.0f);
  return f_schlick(f0, VdotH) * (d_ggx(alpha, NdotH) * v_smith_ggx_correlated(alpha, NdotV, NdotL));
}

// Anisotropic metallic GGX: ax along the thread tangent T, ay along B (T, B, N orthonormal).
BRDF_FN vec3 brdf_metal_aniso(vec3 f0, float ax, float ay, vec3 N, vec3 T, vec3 B, vec3 V, vec3 L) {
  float NdotL = min(dot(N, L), 1.0f);
  float NdotV = min(dot(N, V), 1.0f);
  if (NdotL <= 0.0f || NdotV <= 0.0f) return vec3(0.0f);
  vec3 H = normalize(V + L);
  float NdotH = clamp(dot(N, H), 0.0f, 1.0f);
  float VdotH = clamp(dot(V, H), 0.0f, 1.0f);
  float d = d_ggx_aniso(ax, ay, NdotH, dot(T, H), dot(B, H));
  float vis = v_smith_ggx_correlated_aniso(ax, ay, dot(T, V), dot(B, V), dot(T, L), dot(B, L),
                                           NdotV, NdotL);
  return f_schlick(f0, VdotH) * (d * vis);
}

#endif  // CLOTHLAB_BRDF_GLSL
