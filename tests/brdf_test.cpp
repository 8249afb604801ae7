// The cloth and metal-thread BRDFs of shaders/brdf.glsl, compiled as C++ (vis/shading/brdf.hpp):
// normalisation of the distributions, reciprocity, white-furnace energy bounds and the sheen
// albedo fit on the CPU (integrals accumulated in double), and the same text compiled as
// GLSL 4.50, its GPU values compared with the CPU's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "gl/gl_error.hpp"
#include "gl/headless_context.hpp"
#include "gl/objects.hpp"
#include "gl/program.hpp"
#include "vis/shading/brdf.hpp"

namespace clothlab {
namespace {

namespace brdf = vis::brdf;
using glm::dvec3;
using glm::vec3;

// The view direction at cosine mu in the xz plane (normal +z).
vec3 view_at(double mu) {
  return vec3(dvec3(std::sqrt(1.0 - mu * mu), 0.0, mu));
}

// Directional albedo: the integral of f(l) cos(theta_l) over the hemisphere of l (normal +z),
// as pi times the mean of f over an n x n midpoint grid mapped to cosine-distributed directions
// (Malley's method; deterministic, so every run gives the same value).
template <class F>
double cosine_grid_albedo(F f, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n, r = std::sqrt(u), z = std::sqrt(1.0 - u);
    for (int j = 0; j < n; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / n;
      sum += f(vec3(dvec3(r * std::cos(phi), r * std::sin(phi), z)));
    }
  }
  return std::numbers::pi * sum / (static_cast<double>(n) * n);
}

// Directional albedo of a GGX-type lobe at view v, sampled by half vectors: h distributed as
// D_aniso(h) (n.h) for roughness (ax, ay) (GGX slopes of roughness 1 stretched by ax, ay), so
// the integral of f cos over l becomes the mean of f cos(theta_l) 4 (v.h) / (D(h) (n.h)), with
// D evaluated here in double, independently of the code under test.
template <class F>
double ggx_half_vector_albedo(F f, double ax, double ay, const dvec3& v, int n) {
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n, r = std::sqrt(u / (1.0 - u));
    for (int j = 0; j < n; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / n;
      const dvec3 h = glm::normalize(dvec3(-ax * r * std::cos(phi), -ay * r * std::sin(phi), 1.0));
      const double q = (h.x / ax) * (h.x / ax) + (h.y / ay) * (h.y / ay) + h.z * h.z;
      const double d = 1.0 / (std::numbers::pi * ax * ay * q * q);
      const double vh = glm::dot(v, h);
      if (vh <= 0.0) continue;
      const dvec3 l = 2.0 * vh * h - v;
      if (l.z <= 0.0) continue;
      sum += f(vec3(glm::normalize(l))) * l.z * 4.0 * vh / (d * h.z);
    }
  }
  return sum / (static_cast<double>(n) * n);
}

// A random unit vector in the hemisphere around n.
vec3 random_in_hemisphere(std::mt19937& rng, const dvec3& n) {
  std::normal_distribution<double> g;
  dvec3 d;
  do d = dvec3(g(rng), g(rng), g(rng));
  while (glm::dot(d, d) < 1e-12);
  d = glm::normalize(d);
  if (glm::dot(d, n) < 0.0) d = -d;
  return vec3(d);
}

// |a - b| relative to the larger, channel by channel.
double relative_difference(const vec3& a, const vec3& b) {
  double worst = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double scale = std::max({std::abs(double(a[k])), std::abs(double(b[k])), 1e-30});
    worst = std::max(worst, std::abs(double(a[k]) - double(b[k])) / scale);
  }
  return worst;
}

const std::vector<double> kViewCosines = {0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0};
const std::vector<double> kSigmas = {0.0, 0.25, 0.5, 1.0, std::numbers::pi / 2, std::numbers::pi};
const std::vector<double> kSheenAlphas = {0.07, 0.1, 0.15, 0.2, 0.35, 0.5, 0.75, 1.0};

// ---- Normalisation: the integral of D(h) (n.h) over the hemisphere is 1 -------------------

// Midpoint rule in theta for an isotropic D(cos theta): 2 pi times the integral of
// D cos sin dtheta over [0, pi/2].
template <class D>
double isotropic_projected_area(D d, int n) {
  double sum = 0.0;
  const double dtheta = 0.5 * std::numbers::pi / n;
  for (int i = 0; i < n; ++i) {
    const double theta = (i + 0.5) * dtheta;
    sum += d(static_cast<float>(std::cos(theta))) * std::cos(theta) * std::sin(theta);
  }
  return 2.0 * std::numbers::pi * sum * dtheta;
}

TEST(BrdfTest, CharlieDistributionIsNormalised) {
  for (double alpha : {0.1, 0.3, 0.6, 1.0}) {
    const double area = isotropic_projected_area(
        [&](float c) { return brdf::d_charlie(static_cast<float>(alpha), c); }, 200000);
    std::printf("  Charlie alpha %.1f: integral D (n.h) = %.6f\n", alpha, area);
    EXPECT_NEAR(area, 1.0, 0.01) << "alpha " << alpha;
  }
}

TEST(BrdfTest, GgxDistributionIsNormalised) {
  for (double alpha : {0.05, 0.1, 0.3, 0.6, 1.0}) {
    const double area = isotropic_projected_area(
        [&](float c) { return brdf::d_ggx(static_cast<float>(alpha), c); }, 200000);
    std::printf("  GGX alpha %.2f: integral D (n.h) = %.6f\n", alpha, area);
    EXPECT_NEAR(area, 1.0, 0.01) << "alpha " << alpha;
  }
}

TEST(BrdfTest, AnisotropicGgxDistributionIsNormalised) {
  // theta = atan(a s) with s = w / (1 - w) puts the grid where the lobe is (a = min(ax, ay)).
  const int nw = 4096, nphi = 512;
  for (auto [ax, ay] : std::vector<std::pair<double, double>>{
           {0.1, 0.5}, {0.5, 0.1}, {0.3, 0.05}, {0.6, 0.2}, {1.0, 0.3}, {0.4, 0.4}}) {
    const double a = std::min(ax, ay);
    double sum = 0.0;
    for (int i = 0; i < nw; ++i) {
      const double w = (i + 0.5) / nw, s = w / (1.0 - w), theta = std::atan(a * s);
      const double dtheta_dw = a / (1.0 + a * a * s * s) / ((1.0 - w) * (1.0 - w));
      const double ct = std::cos(theta), st = std::sin(theta);
      double ring = 0.0;
      for (int j = 0; j < nphi; ++j) {
        const double phi = 2.0 * std::numbers::pi * (j + 0.5) / nphi;
        ring += brdf::d_ggx_aniso(float(ax), float(ay), float(ct), float(st * std::cos(phi)),
                                  float(st * std::sin(phi)));
      }
      sum += ring * (2.0 * std::numbers::pi / nphi) * ct * st * dtheta_dw / nw;
    }
    std::printf("  GGX ax %.2f ay %.2f: integral D (n.h) = %.6f\n", ax, ay, sum);
    EXPECT_NEAR(sum, 1.0, 0.01) << "ax " << ax << " ay " << ay;
  }
}

// ---- Oren-Nayar at sigma 0 and reciprocity --------------------------------------------------

TEST(BrdfTest, OrenNayarAtSigmaZeroIsLambertExactly) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const dvec3 n(0.0, 0.0, 1.0);
  for (int k = 0; k < 10000; ++k) {
    const vec3 v = random_in_hemisphere(rng, n), l = random_in_hemisphere(rng, n);
    const vec3 albedo(uni(rng), uni(rng), uni(rng));
    const vec3 on = brdf::brdf_oren_nayar(albedo, 0.0f, l.z, v.z, glm::dot(l, v));
    const vec3 lambert = brdf::brdf_lambert(albedo);
    ASSERT_EQ(on.x, lambert.x) << k;
    ASSERT_EQ(on.y, lambert.y) << k;
    ASSERT_EQ(on.z, lambert.z) << k;
  }
  EXPECT_FLOAT_EQ(brdf::brdf_lambert(vec3(1.0f)).x, float(1.0 / std::numbers::pi));
}

TEST(BrdfTest, BrdfsAreReciprocal) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const int pairs = 10000;
  const double tolerance = 1e-5;  // relative, float evaluation
  double worst_on = 0, worst_sheen = 0, worst_cloth = 0, worst_metal = 0, worst_aniso = 0;
  for (int k = 0; k < pairs; ++k) {
    // A random orthonormal frame (N, T, B) and two directions above it.
    const dvec3 nd = glm::dvec3(random_in_hemisphere(rng, dvec3(0, 0, 1)));
    const dvec3 n = glm::normalize(nd);
    const dvec3 t = glm::normalize(glm::cross(n, glm::dvec3(random_in_hemisphere(rng, n))));
    const vec3 N(n), T(t), B(glm::cross(n, t));
    const vec3 V = random_in_hemisphere(rng, n), L = random_in_hemisphere(rng, n);
    const float nv = glm::dot(N, V), nl = glm::dot(N, L), lv = glm::dot(L, V);
    const float nh = glm::dot(N, glm::normalize(V + L));
    const vec3 albedo(uni(rng), uni(rng), uni(rng)), sheen(uni(rng), uni(rng), uni(rng));
    const float sigma = float(std::numbers::pi * uni(rng)),
                sheen_alpha = float(0.07 + 0.93 * uni(rng));
    const float alpha = float(0.03 + 0.97 * uni(rng)), ax = float(0.03 + 0.97 * uni(rng)),
                ay = float(0.03 + 0.97 * uni(rng));

    worst_on =
        std::max(worst_on, relative_difference(brdf::brdf_oren_nayar(albedo, sigma, nl, nv, lv),
                                               brdf::brdf_oren_nayar(albedo, sigma, nv, nl, lv)));
    worst_sheen = std::max(worst_sheen,
                           relative_difference(brdf::brdf_sheen(sheen, sheen_alpha, nh, nv, nl),
                                               brdf::brdf_sheen(sheen, sheen_alpha, nh, nl, nv)));
    worst_cloth =
        std::max(worst_cloth,
                 relative_difference(brdf::brdf_cloth(N, V, L, albedo, sigma, sheen, sheen_alpha),
                                     brdf::brdf_cloth(N, L, V, albedo, sigma, sheen, sheen_alpha)));
    worst_metal = std::max(
        worst_metal, relative_difference(brdf::brdf_metal(brdf::BRDF_F0_GOLD, alpha, N, V, L),
                                         brdf::brdf_metal(brdf::BRDF_F0_GOLD, alpha, N, L, V)));
    worst_aniso = std::max(
        worst_aniso,
        relative_difference(brdf::brdf_metal_aniso(brdf::BRDF_F0_SILVER, ax, ay, N, T, B, V, L),
                            brdf::brdf_metal_aniso(brdf::BRDF_F0_SILVER, ax, ay, N, T, B, L, V)));
  }
  std::printf(
      "  largest relative |f(l,v) - f(v,l)| over %d pairs: Oren-Nayar %.2e, sheen %.2e, "
      "cloth %.2e, metal %.2e, anisotropic metal %.2e\n",
      pairs, worst_on, worst_sheen, worst_cloth, worst_metal, worst_aniso);
  EXPECT_LE(worst_on, tolerance);
  EXPECT_LE(worst_sheen, tolerance);
  EXPECT_LE(worst_cloth, tolerance);
  EXPECT_LE(worst_metal, tolerance);
  EXPECT_LE(worst_aniso, tolerance);
}

// ---- White furnace: directional albedo <= 1 + 1e-3 ------------------------------------------

constexpr double kFurnaceTolerance = 1e-3;  // above 1; quadrature error is far smaller
constexpr int kGrid = 384;

TEST(BrdfTest, WhiteFurnaceLambertIsOne) {
  for (double mu : kViewCosines) {
    const double e = cosine_grid_albedo([](vec3) { return brdf::brdf_lambert(vec3(1.0f)).x; }, 64);
    EXPECT_NEAR(e, 1.0, 1e-6) << "N.V " << mu;
  }
}

TEST(BrdfTest, WhiteFurnaceOrenNayar) {
  double lowest = 2.0, highest = 0.0;
  for (double sigma : kSigmas)
    for (double mu : kViewCosines) {
      const vec3 v = view_at(mu);
      const double e = cosine_grid_albedo(
          [&](vec3 l) {
            return brdf::brdf_oren_nayar(vec3(1.0f), float(sigma), l.z, v.z, glm::dot(l, v)).x;
          },
          kGrid);
      lowest = std::min(lowest, e);
      highest = std::max(highest, e);
      EXPECT_LE(e, 1.0 + kFurnaceTolerance) << "sigma " << sigma << " N.V " << mu;
      // Rough surfaces lose energy in this single-scattering form, but not more than half.
      EXPECT_GE(e, 0.5) << "sigma " << sigma << " N.V " << mu;
      if (sigma == 0.0) {
        EXPECT_NEAR(e, 1.0, 1e-5) << "N.V " << mu;
      }
    }
  std::printf("  Oren-Nayar albedo over sigma 0..pi, N.V 0.05..1: %.4f .. %.4f\n", lowest, highest);
}

TEST(BrdfTest, WhiteFurnaceLayeredCloth) {
  double highest = 0.0, highest_sigma = 0, highest_alpha = 0, highest_mu = 0, lowest = 2.0;
  for (double sigma : kSigmas)
    for (double sheen_alpha : kSheenAlphas)
      for (double mu : kViewCosines) {
        const vec3 v = view_at(mu), n(0.0f, 0.0f, 1.0f);
        const double e = cosine_grid_albedo(
            [&](vec3 l) {
              return brdf::brdf_cloth(n, v, l, vec3(1.0f), float(sigma), vec3(1.0f),
                                      float(sheen_alpha))
                  .x;
            },
            kGrid);
        EXPECT_LE(e, 1.0 + kFurnaceTolerance)
            << "sigma " << sigma << " sheen alpha " << sheen_alpha << " N.V " << mu;
        lowest = std::min(lowest, e);
        if (e > highest) {
          highest = e;
          highest_sigma = sigma;
          highest_alpha = sheen_alpha;
          highest_mu = mu;
        }
      }
  std::printf(
      "  layered cloth albedo (albedo 1, sheen 1): %.4f .. %.4f (max at sigma %.2f, "
      "sheen alpha %.2f, N.V %.2f)\n",
      lowest, highest, highest_sigma, highest_alpha, highest_mu);
  // Sheen without the base must not exceed 1 either; the base at sigma 0 with sheen 0 is 1.
  const vec3 v = view_at(0.5), n(0.0f, 0.0f, 1.0f);
  const double no_sheen = cosine_grid_albedo(
      [&](vec3 l) { return brdf::brdf_cloth(n, v, l, vec3(1.0f), 0.0f, vec3(0.0f), 0.3f).x; },
      kGrid);
  EXPECT_NEAR(no_sheen, 1.0, 1e-3);
}

// Neubelt's visibility makes the bare sheen lobe reflect more than it receives for smooth sheen
// at grazing view: the reason brdf_cloth normalises the lobe by max(1, E).
TEST(BrdfTest, BareSheenLobeGainsEnergyAtGrazingView) {
  const vec3 v = view_at(0.05), n(0.0f, 0.0f, 1.0f);
  const double e = cosine_grid_albedo(
      [&](vec3 l) {
        const float nh = glm::dot(n, glm::normalize(v + l));
        return brdf::brdf_sheen(vec3(1.0f), 0.07f, nh, v.z, l.z).x;
      },
      kGrid);
  std::printf("  bare sheen albedo at N.V 0.05, alpha 0.07: %.4f\n", e);
  EXPECT_GT(e, 1.0);
}

TEST(BrdfTest, WhiteFurnaceMetal) {
  const int n = 512;
  double highest = 0.0, lowest_smooth = 2.0;
  for (double alpha : {0.03, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0})
    for (double mu : kViewCosines) {
      const dvec3 v(std::sqrt(1.0 - mu * mu), 0.0, mu);
      const vec3 vf(v), nf(0.0f, 0.0f, 1.0f);
      const double e = ggx_half_vector_albedo(
          [&](vec3 l) { return brdf::brdf_metal(vec3(1.0f), float(alpha), nf, vf, l).x; }, alpha,
          alpha, v, n);
      EXPECT_LE(e, 1.0 + kFurnaceTolerance) << "alpha " << alpha << " N.V " << mu;
      highest = std::max(highest, e);
      // Single-scattering GGX loses little energy when smooth (Kulla & Conty 2017: the loss
      // grows with alpha; about 10 % at alpha 0.2, N.V 0.5, 3 % at alpha 0.1).
      if (alpha <= 0.1 && mu >= 0.5) {
        EXPECT_GE(e, 0.95) << "alpha " << alpha << " N.V " << mu;
        lowest_smooth = std::min(lowest_smooth, e);
      }
    }
  std::printf("  metal albedo (F0 1): max %.5f, smooth (alpha <= 0.1, N.V >= 0.5) min %.5f\n",
              highest, lowest_smooth);
}

TEST(BrdfTest, WhiteFurnaceAnisotropicMetal) {
  const int n = 512;
  double highest = 0.0;
  const vec3 nf(0.0f, 0.0f, 1.0f), tf(1.0f, 0.0f, 0.0f), bf(0.0f, 1.0f, 0.0f);
  for (auto [ax, ay] : std::vector<std::pair<double, double>>{
           {0.05, 0.3}, {0.3, 0.05}, {0.2, 0.6}, {1.0, 0.2}, {0.5, 0.5}})
    for (double mu : kViewCosines)
      for (double view_phi : {0.0, 0.7, 1.5707963}) {
        const double s = std::sqrt(1.0 - mu * mu);
        const dvec3 v(s * std::cos(view_phi), s * std::sin(view_phi), mu);
        const vec3 vf(v);
        const double e = ggx_half_vector_albedo(
            [&](vec3 l) {
              return brdf::brdf_metal_aniso(vec3(1.0f), float(ax), float(ay), nf, tf, bf, vf, l).x;
            },
            ax, ay, v, n);
        EXPECT_LE(e, 1.0 + kFurnaceTolerance)
            << "ax " << ax << " ay " << ay << " N.V " << mu << " phi " << view_phi;
        highest = std::max(highest, e);
      }
  std::printf("  anisotropic metal albedo (F0 1): max %.5f\n", highest);
}

// ---- The sheen albedo fit against numerical integration -------------------------------------

// The fit may overestimate by up to 0.015 (its error band, biased up) and must not
// underestimate by more than 1e-3 (the layered furnace relies on that).
TEST(BrdfTest, SheenAlbedoFitMatchesIntegration) {
  double worst_over = -1.0, worst_under = 1.0;
  for (double alpha : {0.07, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 1.0})
    for (double mu : {0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0}) {
      const vec3 v = view_at(mu), n(0.0f, 0.0f, 1.0f);
      const double integrated = cosine_grid_albedo(
          [&](vec3 l) {
            const float nh = glm::dot(n, glm::normalize(v + l));
            return brdf::brdf_sheen(vec3(1.0f), float(alpha), nh, v.z, l.z).x;
          },
          kGrid);
      const double fit = brdf::sheen_albedo(v.z, float(alpha));
      EXPECT_LE(fit - integrated, 0.015) << "alpha " << alpha << " N.V " << mu;
      EXPECT_GE(fit - integrated, -1e-3) << "alpha " << alpha << " N.V " << mu;
      worst_over = std::max(worst_over, fit - integrated);
      worst_under = std::min(worst_under, fit - integrated);
    }
  std::printf("  sheen albedo fit - integral: %+.5f .. %+.5f\n", worst_under, worst_over);
}

// ---- The same text as GLSL 4.50 -------------------------------------------------------------

class BrdfGlslTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = std::make_unique<vis::HeadlessContext>(); }
  static void TearDownTestSuite() { context_.reset(); }
  static std::unique_ptr<vis::HeadlessContext> context_;
};
std::unique_ptr<vis::HeadlessContext> BrdfGlslTest::context_;

TEST_F(BrdfGlslTest, CompilesInAFragmentShader) {
  const std::string vert = R"(#version 450 core
void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }
)";
  const std::string frag = R"(#version 450 core
#include "brdf.glsl"
layout(location = 0) out vec4 color;
void main() {
  vec3 n = vec3(0.0, 0.0, 1.0), v = normalize(vec3(0.3, 0.1, 1.0));
  vec3 l = normalize(vec3(-0.2, 0.4, 1.0));
  vec3 c = brdf_cloth(n, v, l, vec3(0.8), 0.5, vec3(0.5), 0.3) +
           brdf_metal(BRDF_F0_GOLD, 0.25, n, v, l) +
           brdf_metal_aniso(BRDF_F0_SILVER, 0.1, 0.4, n, vec3(1.0, 0.0, 0.0),
                            vec3(0.0, 1.0, 0.0), v, l) + brdf_lambert(vec3(0.5));
  color = vec4(c, 1.0);
}
)";
  try {
    vis::Program program = vis::link_program({{GL_VERTEX_SHADER, "brdf_check.vert", vert},
                                              {GL_FRAGMENT_SHADER, "brdf_check.frag", frag}});
    EXPECT_TRUE(program);
  } catch (const vis::ShaderError& e) {
    FAIL() << e.what();
  }
}

// Every term evaluated by a compute shader on random configurations equals the C++ value
// (relative 1e-3: the driver's pow, sqrt and normalize differ from libm in the last bits).
TEST_F(BrdfGlslTest, GpuValuesEqualCpuValues) {
  const std::string comp = R"(#version 450 core
layout(local_size_x = 64) in;
#include "brdf.glsl"
struct Case { vec4 n; vec4 v; vec4 l; vec4 t; vec4 p; };
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(cases.length())) return;
  Case c = cases[i];
  vec3 N = c.n.xyz, V = c.v.xyz, L = c.l.xyz, T = c.t.xyz, B = cross(N, T);
  float nh = dot(N, normalize(V + L));
  results[4u * i + 0u] = vec4(brdf_cloth(N, V, L, vec3(0.8, 0.5, 0.3), c.p.x,
                                         vec3(0.9, 0.7, 0.6), c.p.y),
                              sheen_albedo(dot(N, V), c.p.y));
  results[4u * i + 1u] = vec4(brdf_metal(BRDF_F0_GOLD, c.p.z, N, V, L), d_charlie(c.p.y, nh));
  results[4u * i + 2u] = vec4(brdf_metal_aniso(BRDF_F0_SILVER, c.p.z, c.p.w, N, T, B, V, L),
                              d_ggx(c.p.z, nh));
  results[4u * i + 3u] = vec4(brdf_oren_nayar(vec3(0.8, 0.5, 0.3), c.p.x, dot(N, L), dot(N, V),
                                              dot(L, V)),
                              v_neubelt(dot(N, V), dot(N, L)));
}
)";
  struct Case {
    glm::vec4 n, v, l, t, p;
  };
  static_assert(sizeof(Case) == 80);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<Case> cases(1024);
  std::vector<glm::vec4> expected;
  for (Case& c : cases) {
    const dvec3 n = glm::dvec3(random_in_hemisphere(rng, dvec3(0, 0, 1)));
    const dvec3 t = glm::normalize(glm::cross(n, glm::dvec3(random_in_hemisphere(rng, n))));
    const vec3 N(n), T(t), B(glm::cross(N, T));
    const vec3 V = random_in_hemisphere(rng, n), L = random_in_hemisphere(rng, n);
    const glm::vec4 p(float(std::numbers::pi * uni(rng)), float(0.07 + 0.93 * uni(rng)),
                      float(0.05 + 0.95 * uni(rng)), float(0.05 + 0.95 * uni(rng)));
    c = {glm::vec4(N, 0.0f), glm::vec4(V, 0.0f), glm::vec4(L, 0.0f), glm::vec4(T, 0.0f), p};
    const float nh = glm::dot(N, glm::normalize(V + L));
    expected.emplace_back(
        brdf::brdf_cloth(N, V, L, vec3(0.8f, 0.5f, 0.3f), p.x, vec3(0.9f, 0.7f, 0.6f), p.y),
        brdf::sheen_albedo(glm::dot(N, V), p.y));
    expected.emplace_back(brdf::brdf_metal(brdf::BRDF_F0_GOLD, p.z, N, V, L),
                          brdf::d_charlie(p.y, nh));
    expected.emplace_back(brdf::brdf_metal_aniso(brdf::BRDF_F0_SILVER, p.z, p.w, N, T, B, V, L),
                          brdf::d_ggx(p.z, nh));
    expected.emplace_back(brdf::brdf_oren_nayar(vec3(0.8f, 0.5f, 0.3f), p.x, glm::dot(N, L),
                                                glm::dot(N, V), glm::dot(L, V)),
                          brdf::v_neubelt(glm::dot(N, V), glm::dot(N, L)));
  }

  vis::Program program;
  try {
    program = vis::link_program({{GL_COMPUTE_SHADER, "brdf_check.comp", comp}});
  } catch (const vis::ShaderError& e) {
    FAIL() << e.what();
  }
  vis::Buffer in = vis::make_buffer(), out = vis::make_buffer();
  glNamedBufferStorage(in.get(), static_cast<GLsizeiptr>(cases.size() * sizeof(Case)), cases.data(),
                       0);
  glNamedBufferStorage(out.get(), static_cast<GLsizeiptr>(expected.size() * sizeof(glm::vec4)),
                       nullptr, GL_DYNAMIC_STORAGE_BIT);
  glUseProgram(program.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.get());
  glDispatchCompute(static_cast<GLuint>((cases.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> gpu(expected.size());
  glGetNamedBufferSubData(out.get(), 0, static_cast<GLsizeiptr>(gpu.size() * sizeof(glm::vec4)),
                          gpu.data());
  glUseProgram(0);
  ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  double worst = 0.0;
  int mismatches = 0;
  for (std::size_t i = 0; i < gpu.size(); ++i)
    for (int k = 0; k < 4; ++k) {
      const double a = gpu[i][k], b = expected[i][k];
      const double err = std::abs(a - b) / std::max(std::abs(b), 1e-3);
      worst = std::max(worst, err);
      if (!(err <= 1e-3) && mismatches++ < 5)
        ADD_FAILURE() << "case " << i / 4 << " row " << i % 4 << " component " << k << ": GPU " << a
                      << ", CPU " << b;
    }
  std::printf("  GPU (%s) vs CPU: largest relative difference %.2e over %zu values\n",
              context_->renderer().c_str(), worst, 4 * gpu.size());
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace clothlab
