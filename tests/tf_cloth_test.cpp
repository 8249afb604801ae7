// solver.backend = "transform_feedback" (gpu/tf_cloth.hpp): the step as a vertex shader whose
// outputs transform feedback captures. On a non-square sheet with three pins in gusty wind it
// follows the CPU solver within float round-off (the library's CPU kernel fuses multiply-adds
// under -march=native, the shaders do not), with each integrator it runs, the same bytes run to
// run; the geometry shader's flat normals are the CPU's face normals; copies move and are drawn
// from the captured buffer; the panel switch carries the motion over; and what the path cannot
// run is refused with the key named.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/view/sim_session.hpp"
#include "factory/solver_factory.hpp"
#include "gl/program.hpp"
#include "gl_context_fixture.hpp"
#include "gpu/backend_solver.hpp"
#include "render_frame.hpp"
#include "sim/cloth/scene_copies.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/scene/validate.hpp"
#include "sim/solver.hpp"
#include "sim/step_backend.hpp"
#include "test_scenes.hpp"
#include "vis/render/headless_renderer.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
namespace {

constexpr int kNu = 21, kNv = 14;

// A 1.2 m x 0.8 m sheet (0.3 kg, 300 N/m, damped, drag) pinned at both top corners and the
// middle of its top edge, in a gusty wind whose force depends on the surface normals, the
// velocities and the seeded noise.
Scene tf_windy(IntegratorKind kind) {
  Scene s = testing::sheet(kNu, 1.0, 0.3, 300.0, kind, 1e-3);
  s.cloths[0].size = {1.2, 0.8};
  s.cloths[0].resolution = {kNu, kNv};
  s.cloths[0].origin = {-0.6, 1.5, 0.0};
  s.cloths[0].pins = {{0, 0}, {kNu / 2, 0}, {kNu - 1, 0}};
  s.springs.damping = 0.05;
  s.forces.drag = 0.005;
  s.forces.wind.enabled = true;
  s.forces.wind.velocity = {2.0, 0.0, 3.0};
  s.forces.wind.gust = 0.6;
  s.forces.wind.seed = 11;
  s.forces.wind.gust_period = 0.05;
  s.forces.wind.coefficient = 1.5;
  s.solver.dt_auto = true;
  s.solver.backend = Backend::transform_feedback;
  return s;
}

double tf_largest_difference(const Solver& a, const Solver& b) {
  double d = 0.0;
  for (int i = 0; i < static_cast<int>(a.vertex_count()); ++i) {
    const Vec3d p = a.position(i), q = b.position(i);
    d = std::max(d, std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
  }
  return d;
}

Eigen::Vector3d vertex_at(const Solver& s, int i) {
  const Vec3d p = s.position(i);
  return {p[0], p[1], p[2]};
}

std::unique_ptr<Solver> tf_solver(const Scene& scene) {
  auto solver = gpu::make_gpu_solver(scene);
  EXPECT_STREQ(backend_name(*solver), "GPU transform feedback");
  return solver;
}

class TfClothTest : public testing::GlContextTest {
 protected:
  // 0.4 s of the windy sheet on both backends.
  static void follows_the_cpu(IntegratorKind kind) {
    const Scene scene = tf_windy(kind);
    const auto cpu = testing::solver<float>(scene, SpringKernel::neighbour_list);
    const auto tf = tf_solver(scene);
    ASSERT_EQ(tf->dt(), cpu->dt());
    const long steps = std::lround(0.4 / cpu->dt());
    const auto start = testing::solver<float>(scene, SpringKernel::neighbour_list);
    ASSERT_TRUE(cpu->step(steps).ok());
    ASSERT_TRUE(tf->step(steps).ok());
    const double d = tf_largest_difference(*cpu, *tf), moved = tf_largest_difference(*start, *tf);
    std::printf("%s, %ld steps to 0.4 s: transform feedback %.2e m from the CPU, moved %.3f m\n",
                to_string(kind), steps, d, moved);
    EXPECT_LT(d, 1e-4);
    EXPECT_GT(moved, 0.05);
    for (int i : {0, kNu / 2, kNu - 1}) EXPECT_EQ(tf->position(i), start->position(i));
  }
};

// Each integrator the path runs.
class TfClothIntegrators : public TfClothTest,
                           public ::testing::WithParamInterface<IntegratorKind> {};

TEST_P(TfClothIntegrators, FollowsTheCpu) {
  follows_the_cpu(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Rules, TfClothIntegrators,
                         ::testing::Values(IntegratorKind::symplectic_euler,
                                           IntegratorKind::explicit_euler,
                                           IntegratorKind::seed_hack),
                         [](const auto& case_info) {
                           return std::string(to_string(case_info.param));
                         });

TEST_F(TfClothTest, SameBytesRunToRun) {
  const Scene scene = tf_windy(IntegratorKind::symplectic_euler);
  const auto a = tf_solver(scene), b = tf_solver(scene);
  ASSERT_TRUE(a->step(200).ok());
  ASSERT_TRUE(b->step(200).ok());
  for (int i = 0; i < static_cast<int>(a->vertex_count()); ++i) {
    ASSERT_EQ(a->position(i), b->position(i)) << i;
    ASSERT_EQ(a->velocity(i), b->velocity(i)) << i;
  }
}

// The renderer's geometry shader (shaders/cloth_flat.geom, as ClothPass builds it) captured by
// transform feedback: every corner of every triangle carries the triangle's unit normal, equal to
// the CPU's face normal normalize((x1 - x0) x (x2 - x0)) of the same positions.
TEST_F(TfClothTest, GeometryShaderNormalsAreTheCpuFaceNormals) {
  const Scene scene = tf_windy(IntegratorKind::symplectic_euler);
  const auto tf = tf_solver(scene);
  ASSERT_TRUE(tf->step(300).ok());  // a folded, moving sheet
  const DeviceCloth& device = *tf->device_cloth();
  ASSERT_TRUE(device.flat_normals());
  const std::vector<std::array<int, 3>>& triangles = tf->triangles();
  const vis::Program program = vis::build_program({"cloth.vert", "cloth_flat.geom"},
                                                  "#define FLAT_NORMALS 1\n", {"v_normal"});
  std::vector<std::uint32_t> corners;
  for (const auto& t : triangles) corners.insert(corners.end(), t.begin(), t.end());
  vis::Buffer elements = vis::make_buffer(), captured = vis::make_buffer();
  glNamedBufferStorage(elements.get(), GLsizeiptr(corners.size() * 4), corners.data(), 0);
  glNamedBufferStorage(captured.get(), GLsizeiptr(corners.size() * 12), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  vis::VertexArray vao = vis::make_vertex_array();
  glVertexArrayVertexBuffer(vao.get(), 0, device.position_buffer(), 0, 16);
  glEnableVertexArrayAttrib(vao.get(), 0);
  glVertexArrayAttribFormat(vao.get(), 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao.get(), 0, 0);
  glVertexArrayElementBuffer(vao.get(), elements.get());
  vis::TransformFeedback feedback = vis::make_transform_feedback();
  glTransformFeedbackBufferBase(feedback.get(), 0, captured.get());
  vis::Framebuffer target = vis::make_framebuffer();  // a surfaceless context has none
  glNamedFramebufferParameteri(target.get(), GL_FRAMEBUFFER_DEFAULT_WIDTH, 1);
  glNamedFramebufferParameteri(target.get(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, target.get());
  glEnable(GL_RASTERIZER_DISCARD);
  glUseProgram(program.get());
  glBindVertexArray(vao.get());
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback.get());
  glBeginTransformFeedback(GL_TRIANGLES);
  glDrawElements(GL_TRIANGLES, GLsizei(corners.size()), GL_UNSIGNED_INT, nullptr);
  glEndTransformFeedback();
  glDisable(GL_RASTERIZER_DISCARD);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<float> normals(3 * corners.size());
  glGetNamedBufferSubData(captured.get(), 0, GLsizeiptr(normals.size() * 4), normals.data());
  double worst = 0.0, at_vertex_0 = INFINITY;
  std::vector<float> arrows(3 * tf->vertex_count());  // the arrows' normals
  device.read_normals(arrows.data());
  const Eigen::Vector3d arrow_0(arrows[0], arrows[1], arrows[2]);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Eigen::Vector3d p0 = vertex_at(*tf, triangles[t][0]),
                          p1 = vertex_at(*tf, triangles[t][1]),
                          p2 = vertex_at(*tf, triangles[t][2]);
    const Eigen::Vector3d c = (p1 - p0).cross(p2 - p0);
    const Eigen::Vector3d n = c / c.norm();
    if (std::count(triangles[t].begin(), triangles[t].end(), 0) > 0)
      at_vertex_0 = std::min(at_vertex_0, (arrow_0 - n).norm());
    for (int k = 0; k < 3; ++k) {
      const float* g = &normals[3 * (3 * t + k)];
      worst = std::max(worst, (Eigen::Vector3d(g[0], g[1], g[2]) - n).norm());
    }
  }
  std::printf("geometry shader against CPU face normals over %zu triangles: %.2e\n",
              triangles.size(), worst);
  EXPECT_LT(worst, 1e-5);
  // The arrows' normal at a vertex is one of its triangles' normals.
  EXPECT_LT(at_vertex_0, 1e-5);
}

// Four copies of the windy sheet: each moves as the original, shifted.
TEST_F(TfClothTest, CopiesMoveAsTheOriginal) {
  constexpr int kCopies = 4;
  constexpr double kSpacing = 2.0;  // a power of two: the offsets add no rounding of their own
  Scene scene = tf_windy(IntegratorKind::symplectic_euler);
  scene.forces.wind.enabled = false;  // the gusts vary across space
  const auto tf = tf_solver(with_copies(scene, kCopies, kSpacing));
  ASSERT_TRUE(tf->step(300).ok());
  const int n = kNu * kNv;
  double worst = 0.0;
  for (int k = 1; k < kCopies; ++k) {
    const Vec3d off = copy_offset(k, kCopies, kSpacing);
    for (int i = 0; i < n; ++i) {
      const Vec3d a = tf->position(i), b = tf->position(k * n + i);
      worst = std::max(worst, std::hypot(b[0] - off[0] - a[0], b[1] - a[1], b[2] - off[2] - a[2]));
    }
  }
  EXPECT_LT(worst, 1e-5);
}

// The panel's backend switch carries the motion over to transform feedback and back; an
// integrator the path does not run is refused with the key named and the motion kept.
TEST_F(TfClothTest, PanelSwitchCarriesTheMotionOver) {
  Scene scene = tf_windy(IntegratorKind::symplectic_euler);
  scene.solver.backend = Backend::cpu;
  vis::SimSession session(scene, make_backend_solver);
  const FrameStepper stepper;
  for (int f = 0; f < 5; ++f) session.advance(stepper, 1.0 / 60.0);
  const Vec3d p = session.solver().position(kNu * kNv - 1);
  session.draft().solver.backend = Backend::transform_feedback;
  session.apply_dynamics();
  ASSERT_NE(session.solver().device_cloth(), nullptr);
  EXPECT_STREQ(backend_name(session.solver()), "GPU transform feedback");
  EXPECT_EQ(session.solver().position(kNu * kNv - 1), p);
  for (int f = 0; f < 5; ++f) session.advance(stepper, 1.0 / 60.0);
  const Vec3d q = session.solver().position(kNu * kNv - 1);
  EXPECT_NE(q, p);
  session.draft().solver.integrator = IntegratorKind::verlet;
  session.apply_dynamics();
  EXPECT_NE(session.error().find("solver.integrator"), std::string::npos) << session.error();
  EXPECT_STREQ(backend_name(session.solver()), "GPU transform feedback");
  session.draft().solver.integrator = IntegratorKind::symplectic_euler;
  session.draft().solver.backend = Backend::gpu;
  session.apply_dynamics();
  EXPECT_STREQ(backend_name(session.solver()), "GPU");
  EXPECT_EQ(session.solver().position(kNu * kNv - 1), q);
}

// What the path does not run is refused when the scene is checked, naming the key.
TEST(TfClothRefusal, UnsupportedOptionsNameTheirKey) {
  const auto message = [](const Scene& s) {
    try {
      validate_scene(s);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Scene s = tf_windy(IntegratorKind::verlet);
  EXPECT_NE(message(s).find("solver.integrator"), std::string::npos) << message(s);
  EXPECT_NE(message(s).find("not verlet"), std::string::npos) << message(s);
  s = tf_windy(IntegratorKind::symplectic_euler);
  EXPECT_EQ(message(s), "");
  s.solver.precision = Precision::f64;
  EXPECT_NE(message(s).find("solver.precision"), std::string::npos) << message(s);
  s = tf_windy(IntegratorKind::symplectic_euler);
  s.cloths[0].shape = "tube";
  s.cloths[0].pins.clear();
  EXPECT_NE(message(s).find("cloth.shape"), std::string::npos) << message(s);
}

// The renderer draws the captured buffer itself: in mode 1 (the springs, positions only) the
// frame of the transform-feedback state equals the CPU-drawn frame of the same state, copies
// included, and it shows the moved cloth; the probe picks the same vertex from it.
TEST(TfClothRender, DrawsTheCapturedBufferAsTheCpuDrawsItsState) {
  vis::HeadlessRenderer renderer(320, 240);  // its context is current from here on
  Scene scene = tf_windy(IntegratorKind::symplectic_euler);
  scene.forces.wind.enabled = false;
  scene = with_copies(scene, 2, 2.0);
  const auto tf = tf_solver(scene);
  const auto cpu = testing::solver<float>(scene, SpringKernel::neighbour_list);
  renderer.set_cloth(*tf);
  vis::ViewSettings view = vis::scene_view(scene, *tf);
  view.mode = vis::DisplayMode::springs;
  const std::vector<std::uint8_t> rest = test::render_frame(renderer, *tf, view);
  ASSERT_TRUE(tf->step(300).ok());
  cpu->load_state(*tf);
  const auto [same_size, worst, moved] = test::compare_with_cpu(renderer, *tf, *cpu, view, rest);
  ASSERT_TRUE(same_size);
  std::printf(
      "transform-feedback-drawn against CPU-drawn frame (2 copies): largest channel "
      "difference %d; %ld channels differ from the rest frame\n",
      worst, moved);
  EXPECT_LE(worst, 2);
  EXPECT_GT(moved, 500);
  // The probe's field pass reads the captured buffer too (its vec4 stride).
  view.mode = vis::DisplayMode::lambert;
  std::optional<vis::ProbeSample> a;
  int x = 0, y = 120;
  for (x = 40; x < 320 && !a; x += 20) a = test::probe_frame(renderer, *cpu, view, x, y);
  ASSERT_TRUE(a) << "no cloth along the middle row";
  renderer.set_cloth(*tf);
  const auto b = test::probe_frame(renderer, *tf, view, x - 20, y);
  ASSERT_TRUE(b);
  EXPECT_EQ(a->vertex, b->vertex);
  EXPECT_LT(glm::length(a->velocity - b->velocity), 1e-5f);
}

}  // namespace
}  // namespace clothlab
