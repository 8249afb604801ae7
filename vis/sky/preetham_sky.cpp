// Preetham, Shirley & Smits 1999, "A Practical Analytic Model for Daylight". The Perez et al.
// (1993) all-weather luminance distribution
//   F(theta, gamma) = (1 + A exp(B / cos theta)) (1 + C exp(D gamma) + E cos^2 gamma)
// (theta: angle from the zenith, gamma: angle to the sun) is used for luminance Y and for both
// chromaticities x, y, each relative to its zenith value:
//   Y = Y_z F(theta, gamma) / F(0, theta_s), likewise x and y.
// The coefficients (paper, appendix A.2) are linear in turbidity T; the zenith values are the
// paper's fits in T and the sun's zenith angle theta_s. Coefficients typed in from the paper.
#include "vis/sky/preetham_sky.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace clothlab::vis {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

struct Perez {
  float a, b, c, d, e;
  // Caller keeps cos_theta > 0.
  float operator()(float cos_theta, float gamma, float cos_gamma) const {
    return (1.0f + a * std::exp(b / cos_theta)) *
           (1.0f + c * std::exp(d * gamma) + e * cos_gamma * cos_gamma);
  }
};

// Everything that depends on the parameters only, shared by all directions of a bake.
struct SkyModel {
  glm::vec3 sun{0.0f, 1.0f, 0.0f};        // unit, the sun as drawn
  glm::vec3 model_sun{0.0f, 1.0f, 0.0f};  // unit, at or above the horizon
  Perez perez_Y{}, perez_x{}, perez_y{};
  float Yz = 1.0f, xz = 0.3f, yz = 0.3f;              // zenith values
  float norm_Y = 1.0f, norm_x = 1.0f, norm_y = 1.0f;  // 1 / F(0, theta_s)
  float exposure = 1.0f;
  glm::vec3 ground{0.0f};
  glm::vec3 sun_disc{0.0f};
  float cos_disc_outer = 1.0f, cos_disc_inner = 1.0f;
  float ground_blend = 0.05f;  // radians
  bool draw_disc = false;

  // min_disc_radius (radians): the drawn disc is at least this large (bake_sky: one texel, so
  // point sampling at texel centres cannot miss it).
  explicit SkyModel(const SkyParams& p, float min_disc_radius = 0.0f);

  // Appendix A.2: distribution coefficients, linear in turbidity.
  void set_distributions(float T);

  void set_zenith(float T, float theta_s);

  // 1 / the brightest point of the model's sky. Across the sun's vertical plane the
  // circumsolar term falls off with gamma and the gradation term (A < 0 for T < 8.2) rises
  // towards the horizon, so the maximum lies on that great circle: towards the sun, or (low
  // turbidity) on the horizon below it. Searched at 1 degree steps, plus the sun itself.
  float auto_exposure() const;

  void set_disc(const SkyParams& p, float min_disc_radius);

  static float clamp_cos(float c) { return std::max(c, 1e-3f); }

  // Luminance in kcd/m^2 along unit direction d (d.y >= 0).
  float luminance(glm::vec3 d) const;

  // Exposed linear sRGB of the sky model along unit d with d.y >= 0 (no disc).
  glm::vec3 sky_above(glm::vec3 d) const;

  glm::vec3 radiance(glm::vec3 d) const;
};

inline SkyModel::SkyModel(const SkyParams& p, float min_disc_radius) {
  const float T = std::clamp(p.turbidity, 1.7f, 10.0f);
  const float len = glm::length(p.sun_direction);
  sun = len > 0.0f && std::isfinite(len) ? p.sun_direction / len : glm::vec3(0, 1, 0);
  // The fit is for daylight: keep the model's sun at least on the horizon.
  model_sun = sun;
  if (model_sun.y < 0.0f) {
    const glm::vec2 h(model_sun.x, model_sun.z);
    const float hl = glm::length(h);
    model_sun = hl > 0.0f ? glm::vec3(h.x / hl, 0.0f, h.y / hl) : glm::vec3(0, 1, 0);
  }
  const float theta_s = std::acos(std::clamp(model_sun.y, 0.0f, 1.0f));

  set_distributions(T);
  set_zenith(T, theta_s);
  const float cos_s = std::cos(theta_s);
  norm_Y = 1.0f / perez_Y(1.0f, theta_s, cos_s);
  norm_x = 1.0f / perez_x(1.0f, theta_s, cos_s);
  norm_y = 1.0f / perez_y(1.0f, theta_s, cos_s);
  exposure = p.exposure > 0.0f && std::isfinite(p.exposure) ? p.exposure : auto_exposure();
  ground = glm::vec3(std::max(p.ground_albedo, 0.0f) * Yz * exposure);
  ground_blend = std::max(p.ground_blend_deg, 0.01f) * kPi / 180.0f;
  set_disc(p, min_disc_radius);
}

inline void SkyModel::set_distributions(float T) {
  perez_Y = {0.1787f * T - 1.4630f, -0.3554f * T + 0.4275f, -0.0227f * T + 5.3251f,
             0.1206f * T - 2.5771f, -0.0670f * T + 0.3703f};
  perez_x = {-0.0193f * T - 0.2592f, -0.0665f * T + 0.0008f, -0.0004f * T + 0.2125f,
             -0.0641f * T - 0.8989f, -0.0033f * T + 0.0452f};
  perez_y = {-0.0167f * T - 0.2608f, -0.0950f * T + 0.0092f, -0.0079f * T + 0.2102f,
             -0.0441f * T - 1.6537f, -0.0109f * T + 0.0529f};
}

inline void SkyModel::set_zenith(float T, float theta_s) {
  // Zenith luminance (kcd/m^2): Y_z = (4.0453 T - 4.9710) tan(chi) - 0.2155 T + 2.4192,
  // chi = (4/9 - T/120) (pi - 2 theta_s).
  const float chi = (4.0f / 9.0f - T / 120.0f) * (kPi - 2.0f * theta_s);
  Yz = std::max((4.0453f * T - 4.9710f) * std::tan(chi) - 0.2155f * T + 2.4192f, 1e-4f);
  // Zenith chromaticity: [T^2 T 1] M [theta_s^3 theta_s^2 theta_s 1]^T.
  const float t2 = T * T, s1 = theta_s, s2 = s1 * s1, s3 = s2 * s1;
  xz = t2 * (0.00166f * s3 - 0.00375f * s2 + 0.00209f * s1) +
       T * (-0.02903f * s3 + 0.06377f * s2 - 0.03202f * s1 + 0.00394f) +
       (0.11693f * s3 - 0.21196f * s2 + 0.06052f * s1 + 0.25886f);
  yz = t2 * (0.00275f * s3 - 0.00610f * s2 + 0.00317f * s1) +
       T * (-0.04214f * s3 + 0.08970f * s2 - 0.04153f * s1 + 0.00516f) +
       (0.15346f * s3 - 0.26756f * s2 + 0.06670f * s1 + 0.26688f);
}

inline float SkyModel::auto_exposure() const {
  float brightest = luminance(model_sun);
  const glm::vec2 h(model_sun.x, model_sun.z);
  const float hl = glm::length(h);
  const glm::vec2 az = hl > 1e-6f ? h / hl : glm::vec2(1.0f, 0.0f);
  for (int k = 0; k <= 180; ++k) {
    const float a = kPi * float(k) / 180.0f;  // from one horizon over the zenith to the other
    const glm::vec3 d(std::cos(a) * az.x, std::sin(a), std::cos(a) * az.y);
    brightest = std::max(brightest, luminance(d));
  }
  return 1.0f / std::max(brightest, 1e-6f);
}

inline void SkyModel::set_disc(const SkyParams& p, float min_disc_radius) {
  draw_disc = p.draw_sun_disc && p.sun_disc_radius_deg > 0.0f && p.sun_disc_intensity > 0.0f;
  if (!draw_disc) return;
  const float r = std::max(std::min(p.sun_disc_radius_deg, 45.0f) * kPi / 180.0f, min_disc_radius);
  cos_disc_outer = std::cos(r);
  cos_disc_inner = std::cos(0.8f * r);  // soft edge over the outer fifth of the radius
  sun_disc = p.sun_disc_intensity * sky_above(model_sun);
}

inline float SkyModel::luminance(glm::vec3 d) const {
  const float cos_gamma = std::clamp(glm::dot(d, model_sun), -1.0f, 1.0f);
  return Yz * perez_Y(clamp_cos(d.y), std::acos(cos_gamma), cos_gamma) * norm_Y;
}

inline glm::vec3 SkyModel::sky_above(glm::vec3 d) const {
  const float cos_theta = clamp_cos(d.y);
  const float cos_gamma = std::clamp(glm::dot(d, model_sun), -1.0f, 1.0f);
  const float gamma = std::acos(cos_gamma);
  const float Y = Yz * perez_Y(cos_theta, gamma, cos_gamma) * norm_Y * exposure;
  const float x = xz * perez_x(cos_theta, gamma, cos_gamma) * norm_x;
  const float y = std::max(yz * perez_y(cos_theta, gamma, cos_gamma) * norm_y, 1e-4f);
  // xyY -> XYZ -> linear sRGB (IEC 61966-2-1 matrix, D65).
  const float X = x / y * Y;
  const float Z = (1.0f - x - y) / y * Y;
  const glm::vec3 rgb(3.2404542f * X - 1.5371385f * Y - 0.4985314f * Z,
                      -0.9692660f * X + 1.8760108f * Y + 0.0415560f * Z,
                      0.0556434f * X - 0.2040259f * Y + 1.0572252f * Z);
  return glm::max(rgb, glm::vec3(0.0f));
}

inline glm::vec3 SkyModel::radiance(glm::vec3 d) const {
  const float len = glm::length(d);
  d = len > 0.0f && std::isfinite(len) ? d / len : glm::vec3(0.0f, -1.0f, 0.0f);
  glm::vec3 sky_dir = d;
  float ground_weight = 0.0f;
  if (d.y < 0.0f) {
    // Sky colour at the horizon in the same azimuth, fading into the ground.
    const glm::vec2 h(d.x, d.z);
    const float hl = glm::length(h);
    sky_dir = hl > 0.0f ? glm::vec3(h.x / hl, 0.0f, h.y / hl) : glm::vec3(1, 0, 0);
    const float depression = std::asin(std::min(-d.y, 1.0f));
    const float u = std::min(depression / ground_blend, 1.0f);
    ground_weight = u * u * (3.0f - 2.0f * u);  // smoothstep
  }
  glm::vec3 c(0.0f);
  if (ground_weight < 1.0f) {
    c = sky_above(sky_dir);
    if (draw_disc) {
      // The disc itself (not the horizon-projected direction), hidden by the ground.
      const float cos_gamma = glm::dot(d, sun);
      if (cos_gamma > cos_disc_outer) {
        const float w = std::min(
            (cos_gamma - cos_disc_outer) / std::max(cos_disc_inner - cos_disc_outer, 1e-9f), 1.0f);
        c = glm::mix(c, sun_disc, w * w * (3.0f - 2.0f * w));
      }
    }
  }
  return glm::mix(c, ground, ground_weight);
}

}  // namespace

glm::vec3 sky_radiance(const SkyParams& params, glm::vec3 direction) {
  return SkyModel(params).radiance(direction);
}

glm::vec3 cube_direction(int face, float s, float t) {
  glm::vec3 d;
  switch (face) {
    case 0:
      d = {1.0f, -t, -s};
      break;
    case 1:
      d = {-1.0f, -t, s};
      break;
    case 2:
      d = {s, 1.0f, t};
      break;
    case 3:
      d = {s, -1.0f, -t};
      break;
    case 4:
      d = {s, -t, 1.0f};
      break;
    case 5:
      d = {-s, -t, -1.0f};
      break;
    default:
      throw std::invalid_argument("cube_direction: face must be 0..5");
  }
  return glm::normalize(d);
}

CubeFaces bake_sky(const SkyParams& params, int size) {
  if (size < 1) throw std::invalid_argument("bake_sky: size must be >= 1");
  // Disc at least one texel (2 / size radians at a face centre) in radius.
  const SkyModel model(params, 2.0f / float(size));
  CubeFaces out;
  out.size = size;
  for (int face = 0; face < 6; ++face) {
    std::vector<float>& px = out.rgb[face];
    px.resize(std::size_t(3) * size * size);
    for (int j = 0; j < size; ++j) {
      const float t = 2.0f * (float(j) + 0.5f) / float(size) - 1.0f;
      for (int i = 0; i < size; ++i) {
        const float s = 2.0f * (float(i) + 0.5f) / float(size) - 1.0f;
        const glm::vec3 c = model.radiance(cube_direction(face, s, t));
        float* dst = px.data() + 3 * (std::size_t(j) * size + i);
        dst[0] = c.r;
        dst[1] = c.g;
        dst[2] = c.b;
      }
    }
  }
  return out;
}

}  // namespace clothlab::vis
