// Probing (clothlab render --probe): the field pass's float targets give back, under the pixel
// of a vertex, the solver's own force, velocity and position there, and nothing off the cloth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "render_frame.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"

namespace clothlab {
namespace {

constexpr int kProbeWidth = 320, kProbeHeight = 240;

double probe_distance(const Vec3d& a, const Vec3d& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}
Vec3d to_d(glm::vec3 v) {
  return {v.x, v.y, v.z};
}

// A 16 x 16 sheet hanging from its top corners, 0.3 s into its swing, so force and velocity
// vary over the cloth; one solver thread (GL tests share the cores with llvmpipe).
class ProbeTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    Scene s = testing::sheet(16, 1.0, 0.2, 100.0, IntegratorKind::symplectic_euler, 1e-3);
    s.cloths[0].pins = {{0, 0}, {15, 0}};
    s.cloths[0].origin = {-0.5, 1.5, 0.0};
    s.cloths[0].v_axis = {0.0, -0.8, -0.6};  // tilted, so it swings in depth too
    s.springs.damping = 0.01;
    solver_ = make_solver(s);
    ASSERT_TRUE(solver_->step(300).ok());
    renderer_ = std::make_unique<vis::HeadlessRenderer>(kProbeWidth, kProbeHeight);
    renderer_->set_cloth(*solver_);
    view_ = vis::default_view(*solver_);
    test::render_frame(*renderer_, *solver_, view_);
  }
  static void TearDownTestSuite() {
    renderer_.reset();
    solver_.reset();
  }

  // The pixel (top-left origin) whose area holds the projection of world point p, with the
  // renderer's own camera matrices.
  static std::array<int, 2> pixel_of(const Vec3d& p) {
    const glm::vec4 c = vis::view_projection(view_.camera, kProbeWidth, kProbeHeight) *
                        glm::vec4(float(p[0]), float(p[1]), float(p[2]), 1.0f);
    const double x = (c.x / c.w * 0.5 + 0.5) * kProbeWidth,
                 y = (c.y / c.w * 0.5 + 0.5) * kProbeHeight;
    return {static_cast<int>(std::floor(x)), kProbeHeight - 1 - static_cast<int>(std::floor(y))};
  }

  static std::unique_ptr<Solver> solver_;
  static std::unique_ptr<vis::HeadlessRenderer> renderer_;
  static vis::ViewSettings view_;
};
std::unique_ptr<Solver> ProbeTest::solver_;
std::unique_ptr<vis::HeadlessRenderer> ProbeTest::renderer_;
vis::ViewSettings ProbeTest::view_;

// The probe samples the pixel's centre, up to half a pixel from the vertex's projection, and
// interpolates linearly over the triangle there. So the error bound is, per field: distance d
// from the vertex to the probed surface point (<= ~0.71 pixel footprints) times the field's
// gradient, which on a triangle is at most 2x the largest difference quotient
// |f_a - f_b| / |x_a - x_b| along the edges of the vertex's triangles (2 covers corner angles
// down to 60 degrees), plus float32 rounding (1e-5 relative).
TEST_F(ProbeTest, VertexPixelGivesTheSolversValuesAndNamesTheVertex) {
  Solver& solver = *solver_;
  solver.update_force_field();
  const double footprint = 2.0 * view_.camera.distance *
                           std::tan(0.5 * view_.camera.fov_deg * M_PI / 180.0) / kProbeHeight;
  for (const auto [i, j] : {std::array<int, 2>{8, 8}, {4, 5}, {11, 10}, {7, 13}}) {
    const int v = solver.vertex_index({0, i, j});
    const auto [px, py] = pixel_of(solver.position(v));
    const std::optional<vis::ProbeSample> s = test::probe_frame(*renderer_, solver, view_, px, py);
    ASSERT_TRUE(s) << "vertex (" << i << ", " << j << ") at pixel " << px << "," << py;
    EXPECT_EQ(s->vertex, v) << "vertex (" << i << ", " << j << ")";

    const double d = probe_distance(to_d(s->position), solver.position(v));
    EXPECT_LE(d, 1.5 * footprint) << "pixel footprint " << footprint << " m";
    // Largest difference quotients of force and velocity over the vertex's triangles.
    double grad_f = 0.0, grad_v = 0.0, max_f = 0.0, max_v = 0.0;
    for (const auto& t : solver.triangles()) {
      if (std::find(t.begin(), t.end(), v) == t.end()) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const double len = probe_distance(solver.position(a), solver.position(b));
        grad_f = std::max(grad_f, probe_distance(solver.force(a), solver.force(b)) / len);
        grad_v = std::max(grad_v, probe_distance(solver.velocity(a), solver.velocity(b)) / len);
        max_f = std::max(max_f, probe_distance(solver.force(a), {0, 0, 0}));
        max_v = std::max(max_v, probe_distance(solver.velocity(a), {0, 0, 0}));
      }
    }
    const double err_f = probe_distance(to_d(s->force), solver.force(v));
    const double err_v = probe_distance(to_d(s->velocity), solver.velocity(v));
    const double bound_f = 2.0 * grad_f * d + 1e-5 * max_f;
    const double bound_v = 2.0 * grad_v * d + 1e-5 * max_v;
    EXPECT_LE(err_f, bound_f) << "force at (" << i << ", " << j << ")";
    EXPECT_LE(err_v, bound_v) << "velocity at (" << i << ", " << j << ")";
    std::printf(
        "vertex (%d, %d) pixel (%d, %d): position error %.3g m (footprint %.3g m); force error "
        "%.3g N of |f| %.3g (bound %.3g); velocity error %.3g m/s of |v| %.3g (bound %.3g)\n",
        i, j, px, py, d, footprint, err_f, probe_distance(solver.force(v), {0, 0, 0}), bound_f,
        err_v, probe_distance(solver.velocity(v), {0, 0, 0}), bound_v);
  }
}

TEST_F(ProbeTest, PixelOffTheClothGivesNothing) {
  EXPECT_FALSE(test::probe_frame(*renderer_, *solver_, view_, 0, 0));  // sky corner
  EXPECT_FALSE(test::probe_frame(*renderer_, *solver_, view_, kProbeWidth - 1,
                                 kProbeHeight - 1));  // floor: not cloth
  EXPECT_FALSE(
      test::probe_frame(*renderer_, *solver_, view_, kProbeWidth, 0));  // outside the image
}

}  // namespace
}  // namespace clothlab
