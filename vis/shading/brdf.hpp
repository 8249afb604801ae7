// The cloth and metal-thread BRDFs of shaders/brdf.glsl as C++: the very same text, compiled
// with GLM's GLSL-like types and functions inside clothlab::vis::brdf, so the CPU tests
// (tests/brdf_test.cpp) check exactly what the fragment shaders evaluate. See that file for the
// terms, their sources and conventions (unit vectors pointing away from the surface; each
// function returns f, not f * cos).
//
// API (all in clothlab::vis::brdf, vec3 = glm::vec3):
//   vec3  brdf_lambert(vec3 albedo)
//   float on_sigma_from_roughness(float roughness)                 // sigma = roughness * pi
//   vec3  brdf_oren_nayar(vec3 albedo, float sigma, float NdotL, float NdotV, float LdotV)
//   float d_charlie(float alpha, float NdotH)
//   float v_neubelt(float NdotV, float NdotL)
//   vec3  brdf_sheen(vec3 sheen_color, float alpha, float NdotH, float NdotV, float NdotL)
//   float sheen_albedo(float NdotV, float alpha)                   // E(N.V, alpha), a fit
//   vec3  brdf_cloth(vec3 N, vec3 V, vec3 L, vec3 albedo, float sigma, vec3 sheen_color,
//                    float sheen_alpha)
//   float d_ggx(float alpha, float NdotH)
//   float d_ggx_aniso(float ax, float ay, float NdotH, float TdotH, float BdotH)
//   float v_smith_ggx_correlated(float alpha, float NdotV, float NdotL)
//   float v_smith_ggx_correlated_aniso(float ax, float ay, float TdotV, float BdotV,
//                                      float TdotL, float BdotL, float NdotV, float NdotL)
//   vec3  f_schlick(vec3 f0, float VdotH)
//   vec3  brdf_metal(vec3 f0, float alpha, vec3 N, vec3 V, vec3 L)
//   vec3  brdf_metal_aniso(vec3 f0, float ax, float ay, vec3 N, vec3 T, vec3 B, vec3 V, vec3 L)
//   constants BRDF_PI, BRDF_F0_GOLD, BRDF_F0_SILVER
#pragma once

#include <cmath>

#include <glm/glm.hpp>

// Include path: the project root (the vis library's public include directory).
#define BRDF_FN inline
namespace clothlab::vis::brdf {
// The GLSL built-ins the shader text uses, declared here so that a same-named function in an
// enclosing namespace can never hide them (add any new one the shader text starts to use).
using glm::clamp;
using glm::cross;
using glm::dot;
using glm::exp;
using glm::inversesqrt;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::pow;
using glm::sqrt;
using glm::vec2;
using glm::vec3;
using glm::vec4;
#include "shaders/brdf.glsl"
}  // namespace clothlab::vis::brdf
#undef BRDF_FN
