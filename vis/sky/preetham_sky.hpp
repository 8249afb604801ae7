// Asset-free daylight sky (docs/rendering.md section 7): the Preetham, Shirley & Smits analytic
// model evaluated on the CPU and baked into a linear-RGB cube map for the skybox pass. No GL here;
// the renderer uploads CubeFaces as GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, one glTexImage2D per
// face (RGB float, rows bottom-up in t exactly as stored).
//
// Source: A. J. Preetham, P. Shirley, B. Smits, "A Practical Analytic Model for Daylight",
// SIGGRAPH 1999, section 3 and appendix A.2 (Perez distribution coefficients for Y, x, y linear in
// turbidity; zenith luminance and chromaticity). Coordinates: y is up (the zenith), as in the
// renderer's world space.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

namespace clothlab::vis {

// How far the sun may turn before the sky pass bakes its cube map again (vis/passes/sky_pass.hpp);
// tests/sky_test.cpp measures what the sky away from the sun's disc moves by within it.
inline constexpr float kSkySunToleranceDeg = 0.25f;

struct SkyParams {
  // Towards the sun (need not be normalised). Below the horizon the model is evaluated with the
  // sun on the horizon (Preetham's fit is for daylight only).
  glm::vec3 sun_direction{0.38f, 0.62f, 0.68f};
  // Atmospheric turbidity; clamped to [1.7, 10], the range where the fit stays positive.
  float turbidity = 3.0f;
  // Multiplier from luminance in kcd/m^2 to the stored linear values. <= 0 (default): automatic,
  // 1 / (the largest sky luminance without the disc: towards the sun or, at low turbidity, on the
  // horizon below it), so the brightest non-sun sky is about 1 whatever the sun's elevation.
  float exposure = 0.0f;
  bool draw_sun_disc = true;
  // Angular radius of the drawn disc in degrees (the real sun is 0.27; larger stays visible on a
  // coarse cube map; bake_sky() widens it to at least one texel) and its radiance as a multiple
  // of the sky radiance towards the sun.
  float sun_disc_radius_deg = 1.0f;
  float sun_disc_intensity = 20.0f;
  // Below the horizon: a neutral grey ground, albedo times the (exposed) zenith luminance,
  // blended in over `ground_blend_deg` below the horizon from the sky colour at the horizon.
  float ground_albedo = 0.3f;
  float ground_blend_deg = 3.0f;
};

// Linear sRGB (Rec. 709 primaries, D65 white) radiance seen along `direction` (need not be
// normalised; a zero vector counts as straight down). Finite and >= 0 everywhere.
glm::vec3 sky_radiance(const SkyParams& params, glm::vec3 direction);

// Unit direction of the cube map texel at (s, t) in [-1, 1]^2 on `face` (0..5 = +X, -X, +Y, -Y,
// +Z, -Z), following the OpenGL 4.5 core specification, section 8.13 and table 8.19 (major axis
// ma and sc, tc per face; s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2):
//   +X: (1, -t, -s)   -X: (-1, -t, s)   +Y: (s, 1, t)   -Y: (s, -1, -t)   +Z: (s, -t, 1)
//   -Z: (-s, -t, -1)   (then normalised).
// Texel (i, j) of a size x size face has its centre at s = 2 (i + 0.5) / size - 1,
// t = 2 (j + 0.5) / size - 1.
glm::vec3 cube_direction(int face, float s, float t);

struct CubeFaces {
  int size = 0;
  // Linear RGB, 3 floats per texel, texel (i, j) at index 3 * (j * size + i): i along s, row j
  // along t, row 0 first (what glTexImage2D takes for the face). GL face order.
  std::array<std::vector<float>, 6> rgb;
};

// Evaluates sky_radiance() at every texel centre, except that the sun disc is drawn at least one
// texel (2 / size radians) in radius so point sampling cannot miss it. Throws
// std::invalid_argument if size < 1.
CubeFaces bake_sky(const SkyParams& params, int size);

}  // namespace clothlab::vis
