#include "sim/forces/force_field.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/parallel.hpp"
#include "sim/forces/body_forces.hpp"
#include "sim/forces/grid_spring_forces.hpp"
#include "sim/forces/spring_forces.hpp"
#include "sim/forces/wind.hpp"

namespace clothlab {
namespace {

// The spring forces over the model's kernel (bands of grid rows, or vertex blocks), each band
// or block first initialised by start(b, e): the body forces for compute_forces, zero for the
// springs alone. One loop for both, so the force source "springs" is exactly the springs' share
// of the total.
template <class T, class Start>
void spring_pass(const Model<T>& m, const Vec3Array<T>& x, const Vec3Array<T>& v, Vec3Array<T>& f,
                 ForceWorkspace<T>& ws, int threads, Start start) {
  const bool damped = m.has_damping;
  if (m.kernel == SpringKernel::row_sweep) {
    for (std::size_t c = 0; c < m.grids.size(); ++c) {
      const GridStencil<T>& g = m.grids[c];
      GridBands<T>& bands = ws.grid_bands[c];
      for_each_index_then(
          bands.count, threads,
          [&](int b) {
            const auto [begin, end] = grid_rows(g, bands.first_row(b), bands.end_row(b, g.nv));
            start(begin, end);
            add_band_spring_forces(g, bands, x, v, f, b, damped);
          },
          [&](int b) { add_band_halo(g, bands, f, b); });
    }
  } else {
    for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
      start(b, e);
      if (damped) {
        add_spring_forces<T, true>(m, x, v, f, b, e);
      } else {
        add_spring_forces<T, false>(m, x, v, f, b, e);
      }
    });
  }
}

template <class T>
void compute_faces(const Model<T>& m, const Vec3Array<T>& x, ForceWorkspace<T>& ws, std::size_t b,
                   std::size_t e) {
  for (std::size_t t = b; t < e; ++t) {
    const auto [i0, i1, i2] = m.triangles[t];
    const T ax = x.x[i1] - x.x[i0], ay = x.y[i1] - x.y[i0], az = x.z[i1] - x.z[i0];
    const T bx = x.x[i2] - x.x[i0], by = x.y[i2] - x.y[i0], bz = x.z[i2] - x.z[i0];
    const T cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
    ws.face_cross.set(t, cx, cy, cz);
    ws.face_area[t] = T(0.5) * std::sqrt(cx * cx + cy * cy + cz * cz);
  }
}

// Area-weighted vertex normals (Max 1999 compares the weightings; area weighting is the cheap
// one that is exact for the sum of incident face normals) and vertex areas A_i = sum(area) / 3.
template <class T>
void compute_vertex_normals(const Model<T>& m, ForceWorkspace<T>& ws, std::size_t b,
                            std::size_t e) {
  const T* cx = ws.face_cross.x.data();
  const T* cy = ws.face_cross.y.data();
  const T* cz = ws.face_cross.z.data();
  const T* area = ws.face_area.data();
  const std::int32_t* tri = m.incident_triangle.data();
  const std::size_t n = m.n;
  const int slots = m.incident_slots;
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    T nx = 0, ny = 0, nz = 0, sum_area = 0;
    for (int s = 0; s < slots; ++s) {
      const auto t = static_cast<std::size_t>(tri[static_cast<std::size_t>(s) * n + i]);
      nx += cx[t];
      ny += cy[t];
      nz += cz[t];
      sum_area += area[t];
    }
    const T len = std::sqrt(nx * nx + ny * ny + nz * nz);
    const T inv = len > T(0) ? T(1) / len : T(0);  // a vertex with no area gets no wind
    ws.normal.set(i, nx * inv, ny * inv, nz * inv);
    ws.vertex_area[i] = sum_area * (T(1) / T(3));
  }
}

template <class T>
void add_wind_forces(const WindField& wind, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                     ForceWorkspace<T>& ws, Vec3Array<T>& f, std::size_t b, std::size_t e) {
  // The gust factor per vertex: a scalar sweep (noise hashing does not vectorise), cheap because
  // the cache hashes only when the lattice cell changes.
  // A steady wind skips the noise: it was half the cost of a step with wind.
  GustCache cache;
  if (wind.steady()) {
    std::fill(ws.gust_factor.begin() + static_cast<std::ptrdiff_t>(b),
              ws.gust_factor.begin() + static_cast<std::ptrdiff_t>(e), T(1));
  } else {
    for (std::size_t i = b; i < e; ++i)
      ws.gust_factor[i] = static_cast<T>(wind.factor(t, x.x[i], x.y[i], x.z[i], cache));
  }
  const T wx = static_cast<T>(wind.spec().velocity[0]);
  const T wy = static_cast<T>(wind.spec().velocity[1]);
  const T wz = static_cast<T>(wind.spec().velocity[2]);
  const T coefficient = static_cast<T>(wind.spec().coefficient);
#pragma omp simd
  for (std::size_t i = b; i < e; ++i) {
    const T k = ws.gust_factor[i];
    const T nx = ws.normal.x[i], ny = ws.normal.y[i], nz = ws.normal.z[i];
    const T normal_speed = (wx * k - v.x[i]) * nx + (wy * k - v.y[i]) * ny + (wz * k - v.z[i]) * nz;
    const T scale = coefficient * ws.vertex_area[i] * normal_speed;
    f.x[i] += scale * nx;
    f.y[i] += scale * ny;
    f.z[i] += scale * nz;
  }
}

template <class T>
void add_wind(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
              Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads) {
  if (!wind_acts(m)) return;
  const WindField wind(m.wind);
  compute_surface(m, x, ws, threads);
  for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
    add_wind_forces(wind, t, x, v, ws, f, b, e);
  });
}

}  // namespace

template <class T>
bool wind_acts(const Model<T>& m) {
  return m.wind.enabled && !WindField(m.wind).calm() && !m.triangles.empty();
}

template <class T>
void compute_forces(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                    Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads) {
  spring_pass(m, x, v, f, ws, threads,
              [&](std::size_t b, std::size_t e) { add_body_forces(m, v, f, b, e); });
  add_wind(m, t, x, v, f, ws, threads);
}

template <class T>
void compute_external_forces(const Model<T>& m, double t, const Vec3Array<T>& x,
                             const Vec3Array<T>& v, Vec3Array<T>& f, ForceWorkspace<T>& ws,
                             int threads) {
  for_each_block(m.n, threads,
                 [&](std::size_t b, std::size_t e) { add_body_forces(m, v, f, b, e); });
  add_wind(m, t, x, v, f, ws, threads);
}

template <class T>
void compute_force_source(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                          Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads, ForceSource source) {
  switch (source) {
    case ForceSource::total:
      compute_forces(m, t, x, v, f, ws, threads);
      return;
    case ForceSource::springs:
      spring_pass(m, x, v, f, ws, threads,
                  [&](std::size_t b, std::size_t e) { zero_forces(f, b, e); });
      return;
    case ForceSource::gravity:
      for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
        add_body_forces<T, true, false>(m, v, f, b, e);
      });
      return;
    case ForceSource::drag:
      for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) {
        add_body_forces<T, false, true>(m, v, f, b, e);
      });
      return;
    case ForceSource::wind:
      for_each_block(m.n, threads, [&](std::size_t b, std::size_t e) { zero_forces(f, b, e); });
      add_wind(m, t, x, v, f, ws, threads);
      return;
  }
}

template <class T>
void compute_surface(const Model<T>& m, const Vec3Array<T>& x, ForceWorkspace<T>& ws, int threads) {
  if (m.kernel != SpringKernel::row_sweep) {
    compute_surface_from_triangles(m, x, ws, threads);
    return;
  }
  for (std::size_t c = 0; c < m.grids.size(); ++c) {
    const GridStencil<T>& g = m.grids[c];
    GridFaces<T>& faces = ws.grid_faces[c];
    for_each_index(g.nv - 1, threads, [&](int qj) { grid_face_row(g, x, faces, qj); });
    for_each_index(g.nv, threads,
                   [&](int j) { grid_normal_row(g, faces, ws.normal, ws.vertex_area, j); });
  }
}

template <class T>
void compute_surface_from_triangles(const Model<T>& m, const Vec3Array<T>& x, ForceWorkspace<T>& ws,
                                    int threads) {
  for_each_block(m.triangles.size(), threads,
                 [&](std::size_t b, std::size_t e) { compute_faces(m, x, ws, b, e); });
  for_each_block(m.n, threads,
                 [&](std::size_t b, std::size_t e) { compute_vertex_normals(m, ws, b, e); });
}

template bool wind_acts<float>(const Model<float>&);
template bool wind_acts<double>(const Model<double>&);
template void compute_surface_from_triangles<float>(const Model<float>&, const Vec3Array<float>&,
                                                    ForceWorkspace<float>&, int);
template void compute_surface_from_triangles<double>(const Model<double>&, const Vec3Array<double>&,
                                                     ForceWorkspace<double>&, int);
template void compute_surface<float>(const Model<float>&, const Vec3Array<float>&,
                                     ForceWorkspace<float>&, int);
template void compute_surface<double>(const Model<double>&, const Vec3Array<double>&,
                                      ForceWorkspace<double>&, int);
template void compute_external_forces<float>(const Model<float>&, double, const Vec3Array<float>&,
                                             const Vec3Array<float>&, Vec3Array<float>&,
                                             ForceWorkspace<float>&, int);
template void compute_external_forces<double>(const Model<double>&, double,
                                              const Vec3Array<double>&, const Vec3Array<double>&,
                                              Vec3Array<double>&, ForceWorkspace<double>&, int);
template void compute_force_source<float>(const Model<float>&, double, const Vec3Array<float>&,
                                          const Vec3Array<float>&, Vec3Array<float>&,
                                          ForceWorkspace<float>&, int, ForceSource);
template void compute_force_source<double>(const Model<double>&, double, const Vec3Array<double>&,
                                           const Vec3Array<double>&, Vec3Array<double>&,
                                           ForceWorkspace<double>&, int, ForceSource);
template void compute_forces<float>(const Model<float>&, double, const Vec3Array<float>&,
                                    const Vec3Array<float>&, Vec3Array<float>&,
                                    ForceWorkspace<float>&, int);
template void compute_forces<double>(const Model<double>&, double, const Vec3Array<double>&,
                                     const Vec3Array<double>&, Vec3Array<double>&,
                                     ForceWorkspace<double>&, int);

}  // namespace clothlab
