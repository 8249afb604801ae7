// The GPU cloth step (gpu/gpu_cloth.hpp) follows the CPU solver: after 200 steps of a 64 x 64
// sheet pinned at two corners (springs with damping, drag, gravity) the positions agree within
// 1e-5 m and the velocities within 1e-4 m/s, pins exactly, for symplectic Euler and Verlet; the
// smoothed normals agree within 1e-6. The project builds with -march=native, where g++ fuses
// multiply-adds (-ffp-contract=fast is GCC's default, also in ISO C++ mode), so the library's
// solver is not bit-identical to the shaders; this file is compiled with -ffp-contract=off
// (tests/CMakeLists.txt) and holds a copy of the CPU kernel and integrators in the CPU's order,
// which on llvmpipe the GPU matches bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "gl_context_fixture.hpp"
#include "gpu/gpu_cloth.hpp"
#include "sim/integrators/integrator.hpp"
#include "sim/solver.hpp"
#include "test_scenes.hpp"

namespace clothlab {
namespace {

constexpr int kGpuClothRes = 64;

// A soft 1 m sheet (1 kg, stiffness 50 N/m) lying horizontal, pinned at the two corners of one
// edge, released at rest: in 200 steps it falls and starts to fold, so every term of the force is
// exercised. dt = "auto" (0.8 of the stability limit; soft, so the steps cover 0.1 s or more).
Scene sheet_scene(IntegratorKind kind) {
  Scene s = testing::sheet(kGpuClothRes, 1.0, 1.0, 50.0, kind, 1e-3);
  s.cloths[0].v_axis = {0.0, 0.0, 1.0};
  s.cloths[0].pins = {{0, 0}, {kGpuClothRes - 1, 0}};
  s.springs.damping = 0.05;
  s.forces.drag = 0.01;
  s.solver.dt_auto = true;
  s.solver.precision = Precision::f32;
  s.solver.threads = 1;
  return s;
}

// A copy of the CPU step without contraction (this file is compiled with -ffp-contract=off):
// sim/forces/force_field.cpp add_body_forces, sim/forces/spring_forces.hpp add_spring_forces and
// sim/integrators/explicit/{symplectic_euler,verlet}.cpp, the same expressions in the same order. A
// copy, not the header's template: its float instantiation in the library is compiled with
// contraction and the linker may keep either.
class ReferenceCloth {
 public:
  ReferenceCloth(const Model<float>& m, const State<float>& s) : m_(m), s_(s) {
    f_.resize(m.n);
    vp_.resize(m.n);
  }

  void step(float dt, IntegratorKind kind) {
    const std::size_t n = m_.n;
    if (kind == IntegratorKind::symplectic_euler) {
      forces(s_.vel);
      for (int a = 0; a < 3; ++a)
        for (std::size_t i = 0; i < n; ++i) {
          const float acc = f_.axis(a)[i] * m_.inv_mass[i];
          s_.vel.axis(a)[i] += dt * acc;
          s_.pos.axis(a)[i] += dt * s_.vel.axis(a)[i];
        }
      force_valid_ = false;
      return;
    }
    if (!force_valid_) forces(s_.vel);
    const float half_dt = 0.5f * dt;
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = 0; i < n; ++i) {
        const float kick = half_dt * f_.axis(a)[i] * m_.inv_mass[i];
        s_.vel.axis(a)[i] += kick;
        s_.pos.axis(a)[i] += dt * s_.vel.axis(a)[i];
        vp_.axis(a)[i] = s_.vel.axis(a)[i] + kick;
      }
    forces(vp_);
    for (int a = 0; a < 3; ++a)
      for (std::size_t i = 0; i < n; ++i)
        s_.vel.axis(a)[i] += half_dt * f_.axis(a)[i] * m_.inv_mass[i];
    force_valid_ = true;
  }
  const State<float>& state() const { return s_; }

 private:
  void forces(const Vec3Array<float>& v) {
    const Vec3Array<float>& x = s_.pos;
    const std::size_t n = m_.n;
    for (std::size_t i = 0; i < n; ++i) {
      const float mi = m_.mass[i];
      f_.x[i] = mi * m_.gravity[0] - m_.drag * v.x[i];
      f_.y[i] = mi * m_.gravity[1] - m_.drag * v.y[i];
      f_.z[i] = mi * m_.gravity[2] - m_.drag * v.z[i];
    }
    for (int s = 0; s < m_.slots; ++s) {
      const std::size_t base = static_cast<std::size_t>(s) * n;
      for (std::size_t i = 0; i < n; ++i) {
        const auto j = static_cast<std::size_t>(m_.neighbour[base + i]);
        const float dx = x.x[j] - x.x[i], dy = x.y[j] - x.y[i], dz = x.z[j] - x.z[i];
        const float len = std::sqrt(dx * dx + dy * dy + dz * dz);
        const float inv_len = len > 0.0f ? 1.0f / len : 0.0f;
        float scale = m_.stiffness[base + i] * (len - m_.rest_length[base + i]) * inv_len;
        if (m_.has_damping) {
          const float rvx = v.x[j] - v.x[i], rvy = v.y[j] - v.y[i], rvz = v.z[j] - v.z[i];
          scale += m_.damping[base + i] * (rvx * dx + rvy * dy + rvz * dz) * inv_len * inv_len;
        }
        f_.x[i] += scale * dx;
        f_.y[i] += scale * dy;
        f_.z[i] += scale * dz;
      }
    }
  }

  const Model<float>& m_;
  State<float> s_;
  Vec3Array<float> f_, vp_;
  bool force_valid_ = false;
};

// Unit area-weighted normals without contraction: sim/forces/force_field.cpp compute_faces and
// compute_vertex_normals, in the same order.
std::vector<float> reference_normals(const Model<float>& m, const Vec3Array<float>& x) {
  const std::size_t count = m.triangles.size();
  std::vector<float> face(4 * (count + 1), 0.0f);  // (c, area), the zero dummy last
  for (std::size_t t = 0; t < count; ++t) {
    const auto [i0, i1, i2] = m.triangles[t];
    const float ax = x.x[i1] - x.x[i0], ay = x.y[i1] - x.y[i0], az = x.z[i1] - x.z[i0];
    const float bx = x.x[i2] - x.x[i0], by = x.y[i2] - x.y[i0], bz = x.z[i2] - x.z[i0];
    const float cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    face[4 * t] = cx;
    face[4 * t + 1] = cy;
    face[4 * t + 2] = cz;
    face[4 * t + 3] = 0.5f * std::sqrt(cx * cx + cy * cy + cz * cz);
  }
  std::vector<float> normal(3 * m.n);
  for (std::size_t i = 0; i < m.n; ++i) {
    float nx = 0, ny = 0, nz = 0;
    for (int s = 0; s < m.incident_slots; ++s) {
      const auto t = static_cast<std::size_t>(m.incident_triangle[s * m.n + i]);
      nx += face[4 * t];
      ny += face[4 * t + 1];
      nz += face[4 * t + 2];
    }
    const float len = std::sqrt(nx * nx + ny * ny + nz * nz);
    const float inv = len > 0.0f ? 1.0f / len : 0.0f;
    normal[3 * i] = nx * inv;
    normal[3 * i + 1] = ny * inv;
    normal[3 * i + 2] = nz * inv;
  }
  return normal;
}

// The CPU solver on the neighbour-list kernel (what the GPU step mirrors), with the model and the
// start state it was built from, for the GPU and the reference to start from.
struct CpuSheet {
  explicit CpuSheet(const Scene& scene, SpringKernel kernel = SpringKernel::neighbour_list)
      : model(build_model<float>(scene, kernel)),
        start{model.rest_positions, {}},
        solver(testing::solver<float>(scene, kernel)) {
    start.vel.resize(model.n);
  }
  // The solver's positions and velocities, interleaved (x, y, z per vertex), as floats.
  std::vector<float> positions() const {
    std::vector<float> x(3 * model.n);
    solver->copy_positions(x.data());
    return x;
  }
  std::vector<float> velocities() const {
    std::vector<float> v(3 * model.n);
    solver->copy_velocities(v.data());
    return v;
  }
  Model<float> model;
  State<float> start;
  std::unique_ptr<Solver> solver;
};

Vec3Array<float> deinterleave(const std::vector<float>& xyz) {
  Vec3Array<float> a;
  a.resize(xyz.size() / 3);
  for (std::size_t i = 0; i < a.size(); ++i) a.set(i, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  return a;
}

std::vector<float> interleave(const Vec3Array<float>& a) {
  std::vector<float> out(3 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    out[3 * i] = a.x[i];
    out[3 * i + 1] = a.y[i];
    out[3 * i + 2] = a.z[i];
  }
  return out;
}

// Largest distance between corresponding 3-vectors.
double max_distance(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i + 2 < a.size(); i += 3)
    worst = std::max(worst, std::hypot(double(a[i]) - b[i], double(a[i + 1]) - b[i + 1],
                                       double(a[i + 2]) - b[i + 2]));
  return worst;
}

struct Readback {
  std::vector<float> x, v;
};
Readback read_text(const gpu::GpuCloth& gpu) {
  Readback r{std::vector<float>(3 * gpu.vertex_count()),
             std::vector<float>(3 * gpu.vertex_count())};
  gpu.read_positions(r.x.data());
  gpu.read_velocities(r.v.data());
  return r;
}

class GpuClothTest : public testing::GlContextTest {
 protected:
  static bool llvmpipe() { return context().renderer().find("llvmpipe") != std::string::npos; }

  // 200 steps on the CPU solver, the contraction-free reference and the GPU, compared.
  static void compare_after_200_steps(IntegratorKind kind) {
    const CpuSheet sheet(sheet_scene(kind));
    Solver& cpu = *sheet.solver;
    ASSERT_EQ(cpu.substeps(), 1);
    const auto h = static_cast<float>(cpu.dt());
    ReferenceCloth reference(sheet.model, sheet.start);
    gpu::GpuCloth gpu(sheet.model, sheet.start.pos, sheet.start.vel);
    constexpr int kSteps = 200;
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    ASSERT_TRUE(cpu.step(kSteps).ok());
    const auto t1 = Clock::now();
    // Two calls: Verlet carries its end-of-step force from one call to the next, as the CPU does.
    gpu.step(kSteps / 2, h, kind);
    gpu.step(kSteps - kSteps / 2, h, kind);
    gpu.finish();
    const auto t2 = Clock::now();
    for (int k = 0; k < kSteps; ++k) reference.step(h, kind);

    const Readback g = read_text(gpu);
    const std::vector<float> cx = sheet.positions(), cv = sheet.velocities();
    const std::vector<float> rx = interleave(reference.state().pos);
    const std::vector<float> rv = interleave(reference.state().vel);
    const double dx = max_distance(g.x, cx), dv = max_distance(g.v, cv);
    const double rdx = max_distance(g.x, rx), rdv = max_distance(g.v, rv);
    auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count() / kSteps; };
    std::printf(
        "[gpu_cloth] %s, %d x %d, h = %.3g s, %d steps: max |x_gpu - x_cpu| = %.3g m, "
        "|v_gpu - v_cpu| = %.3g m/s; against the -ffp-contract=off reference %.3g m, %.3g m/s "
        "(%s); %.3f ms/step GPU, %.3f ms/step CPU, 1 thread (shared machine: noisy)\n",
        kind == IntegratorKind::verlet ? "verlet" : "symplectic_euler", kGpuClothRes, kGpuClothRes,
        double(h), kSteps, dx, dv, rdx, rdv, context().renderer().c_str(), ms(t2 - t1),
        ms(t1 - t0));
    EXPECT_LT(dx, 1e-5);
    EXPECT_LT(dv, 1e-4);
    // The cloth moved (by 6 mm or more), 100 times the tolerance: not two resting sheets.
    EXPECT_GT(max_distance(cx, interleave(sheet.model.rest_positions)), 1e-3);
    ASSERT_EQ(sheet.model.pinned.size(), 2u);
    for (int p : sheet.model.pinned)
      for (int a = 0; a < 3; ++a) {
        const auto k = static_cast<std::size_t>(3 * p + a);
        EXPECT_EQ(g.x[k], cx[k]) << "pinned vertex " << p;
        EXPECT_EQ(g.v[k], 0.0f) << "pinned vertex " << p;
      }
    // llvmpipe rounds every operation as IEEE does (no fused multiply-add under `precise`, exact
    // division and square root): bit for bit. Other drivers may round division and sqrt their way.
    if (llvmpipe()) {
      EXPECT_EQ(rdx, 0.0);
      EXPECT_EQ(rdv, 0.0);
    }
  }
};

TEST_F(GpuClothTest, SymplecticEulerFollowsTheCpuSolverFor200Steps) {
  compare_after_200_steps(IntegratorKind::symplectic_euler);
}

TEST_F(GpuClothTest, VerletFollowsTheCpuSolverFor200Steps) {
  compare_after_200_steps(IntegratorKind::verlet);
}

// The smoothed normals after 50 steps: of the GPU's own state against the CPU solver's
// copy_normals (both surfaces have moved their own way, by round-off), and of the CPU's state
// uploaded to the GPU, which isolates the two normal passes.
TEST_F(GpuClothTest, NormalsMatchTheCpuSurface) {
  const IntegratorKind kind = IntegratorKind::symplectic_euler;
  const CpuSheet sheet(sheet_scene(kind));
  Solver& cpu = *sheet.solver;
  gpu::GpuCloth gpu(sheet.model, sheet.start.pos, sheet.start.vel);
  ASSERT_TRUE(cpu.step(50).ok());
  gpu.step(50, static_cast<float>(cpu.dt()), kind);
  const std::size_t n = cpu.vertex_count();
  std::vector<float> cpu_normals(3 * n), gpu_normals(3 * n), same_state(3 * n);
  cpu.copy_normals(cpu_normals.data());
  gpu.compute_normals();
  gpu.read_normals(gpu_normals.data());
  const Vec3Array<float> cpu_pos = deinterleave(sheet.positions());
  gpu.set_state(cpu_pos, deinterleave(sheet.velocities()));
  gpu.compute_normals();
  gpu.read_normals(same_state.data());
  const double own = max_distance(gpu_normals, cpu_normals);
  const double same = max_distance(same_state, cpu_normals);
  const double exact = max_distance(same_state, reference_normals(sheet.model, cpu_pos));
  std::printf(
      "[gpu_cloth] normals after 50 steps: max |n_gpu - n_cpu| = %.3g (GPU state), %.3g "
      "(the CPU's state on the GPU); %.3g against the -ffp-contract=off reference\n",
      own, same, exact);
  EXPECT_LT(own, 1e-6);
  EXPECT_LT(same, 1e-6);
  if (llvmpipe()) {
    EXPECT_EQ(exact, 0.0);
  }
  // They are unit normals of a surface that has started to bend.
  double unit = 0.0, tilt = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const float* g = &gpu_normals[3 * i];
    unit = std::max(unit, std::abs(std::hypot(double(g[0]), g[1], g[2]) - 1.0));
    tilt = std::max(tilt, 1.0 - std::abs(double(g[1])));
  }
  EXPECT_LT(unit, 1e-6);
  EXPECT_GT(tilt, 1e-3);
}

// The long run, printed rather than asserted: round-off differences grow with the motion.
TEST_F(GpuClothTest, DifferencesAfter2000StepsArePrinted) {
  for (IntegratorKind kind : {IntegratorKind::symplectic_euler, IntegratorKind::verlet}) {
    const CpuSheet sheet(sheet_scene(kind));
    Solver& cpu = *sheet.solver;
    ReferenceCloth reference(sheet.model, sheet.start);
    gpu::GpuCloth gpu(sheet.model, sheet.start.pos, sheet.start.vel);
    const auto h = static_cast<float>(cpu.dt());
    constexpr int kSteps = 2000;
    ASSERT_TRUE(cpu.step(kSteps).ok());
    gpu.step(kSteps, h, kind);
    for (int k = 0; k < kSteps; ++k) reference.step(h, kind);
    const Readback g = read_text(gpu);
    std::printf(
        "[gpu_cloth] %s, %d steps (%.3g s): max |x_gpu - x_cpu| = %.3g m, |v_gpu - v_cpu| "
        "= %.3g m/s; against the -ffp-contract=off reference %.3g m, %.3g m/s\n",
        kind == IntegratorKind::verlet ? "verlet" : "symplectic_euler", kSteps, kSteps * double(h),
        max_distance(g.x, sheet.positions()), max_distance(g.v, sheet.velocities()),
        max_distance(g.x, interleave(reference.state().pos)),
        max_distance(g.v, interleave(reference.state().vel)));
    for (float value : g.x) ASSERT_TRUE(std::isfinite(value));
  }
}

TEST_F(GpuClothTest, RefusesTheRowSweepModelAndOtherIntegrators) {
  const CpuSheet row(sheet_scene(IntegratorKind::symplectic_euler), SpringKernel::row_sweep);
  EXPECT_THROW(gpu::GpuCloth(row.model, row.start.pos, row.start.vel), std::invalid_argument);
  const CpuSheet cpu(sheet_scene(IntegratorKind::symplectic_euler));
  gpu::GpuCloth gpu(cpu.model, cpu.start.pos, cpu.start.vel);
  EXPECT_THROW(gpu.step(1, 1e-3f, IntegratorKind::rk4), std::invalid_argument);
}

}  // namespace
}  // namespace clothlab
