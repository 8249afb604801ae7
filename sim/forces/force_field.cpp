#include "sim/forces/force_field.hpp"

#include <cmath>

#include "sim/core/parallel.hpp"
#include "sim/forces/spring_forces.hpp"
#include "sim/forces/wind.hpp"

namespace clothlab {
namespace {

template <class T>
void add_body_forces(const Model<T>& m, const Vec3Array<T>& v, Vec3Array<T>& f, std::size_t b,
                     std::size_t e) {
  const T gx = m.gravity[0], gy = m.gravity[1], gz = m.gravity[2], drag = m.drag;
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    const T mi = m.mass[i];
    f.x[i] = mi * gx - drag * v.x[i];
    f.y[i] = mi * gy - drag * v.y[i];
    f.z[i] = mi * gz - drag * v.z[i];
  }
}

template <class T>
void compute_face_cross(const Model<T>& m, const Vec3Array<T>& x, Vec3Array<T>& out, std::size_t b,
                        std::size_t e) {
  for (std::size_t t = b; t < e; ++t) {
    const auto [i0, i1, i2] = m.triangles[t];
    const T ax = x.x[i1] - x.x[i0], ay = x.y[i1] - x.y[i0], az = x.z[i1] - x.z[i0];
    const T bx = x.x[i2] - x.x[i0], by = x.y[i2] - x.y[i0], bz = x.z[i2] - x.z[i0];
    out.set(t, ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx);
  }
}

template <class T>
void add_wind_forces(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                     const Vec3Array<T>& cross, Vec3Array<T>& f, std::size_t b, std::size_t e) {
  for (std::size_t i = b; i < e; ++i) {
    double nx = 0, ny = 0, nz = 0, twice_area = 0;
    for (int k = m.incident_offset[i]; k < m.incident_offset[i + 1]; ++k) {
      const auto tri = static_cast<std::size_t>(m.incident_triangle[static_cast<std::size_t>(k)]);
      nx += cross.x[tri];
      ny += cross.y[tri];
      nz += cross.z[tri];
      twice_area +=
          std::sqrt(double(cross.x[tri]) * cross.x[tri] + double(cross.y[tri]) * cross.y[tri] +
                    double(cross.z[tri]) * cross.z[tri]);
    }
    const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (len == 0.0) continue;
    nx /= len, ny /= len, nz /= len;
    const Vec3d w = wind_velocity(m.wind, t, {double(x.x[i]), double(x.y[i]), double(x.z[i])});
    const double normal_speed = (w[0] - v.x[i]) * nx + (w[1] - v.y[i]) * ny + (w[2] - v.z[i]) * nz;
    const double scale = m.wind.coefficient * (twice_area / 6.0) * normal_speed;
    f.x[i] += static_cast<T>(scale * nx);
    f.y[i] += static_cast<T>(scale * ny);
    f.z[i] += static_cast<T>(scale * nz);
  }
}

}  // namespace

Vec3d wind_velocity(const WindSpec& wind, double t, const Vec3d& p) {
  const Vec3d& W = wind.velocity;
  const double speed = std::sqrt(W[0] * W[0] + W[1] * W[1] + W[2] * W[2]);
  if (speed == 0.0) return {0.0, 0.0, 0.0};
  const double along = (p[0] * W[0] + p[1] * W[1] + p[2] * W[2]) / speed;
  const double factor =
      1.0 + wind.gust * gust_noise(wind.seed, (t - along / speed) / wind.gust_period);
  return {W[0] * factor, W[1] * factor, W[2] * factor};
}

template <class T>
void compute_forces(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                    Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads) {
  const bool damped = m.has_damping;
  for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
    add_body_forces(m, v, f, b, e);
    if (damped) {
      add_spring_forces<T, true>(m, x, v, f, b, e);
    } else {
      add_spring_forces<T, false>(m, x, v, f, b, e);
    }
  });
  if (!m.wind.enabled || m.triangles.empty()) return;
  for_each_block(m.triangles.size(), threads, [&](std::size_t b, std::size_t e) {
    compute_face_cross(m, x, ws.face_cross, b, e);
  });
  for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
    add_wind_forces(m, t, x, v, ws.face_cross, f, b, e);
  });
}

template void compute_forces<float>(const Model<float>&, double, const Vec3Array<float>&,
                                    const Vec3Array<float>&, Vec3Array<float>&,
                                    ForceWorkspace<float>&, int);
template void compute_forces<double>(const Model<double>&, double, const Vec3Array<double>&,
                                     const Vec3Array<double>&, Vec3Array<double>&,
                                     ForceWorkspace<double>&, int);

}  // namespace clothlab
