// What the two paths of vertex block descent share: the neighbour-list path (vbd.cpp, every
// cloth) and the grid path (vbd_grid.cpp, grid cloths). The method and its formulas are in
// vbd.cpp's header; both paths do the same arithmetic per spring, so they differ only by the
// order in which a vertex sums its springs (round-off).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/integrators/integrator.hpp"

namespace clothlab {

// On the 32 x 32 falling sheet at 1/60 s (k0 = 1e3) 10 iterations leave the lattice so stretched
// that its energy peaks at 20 J (ten times what the fall releases), 30 at 2.4 J (XPBD's one
// sweep in 39 substeps: 2.3 J), 100 never above the start.
inline constexpr int kVbdDefaultIterations = 30;
// Chebyshev (docs/solver.md): rho 0.9, from the fourth iteration on. On the 32 x 32 sheet at
// 1/60 s, 10 iterations: rho 0 / 0.5 / 0.9 leave it 497 / 486 / 397 mm from RK4 at 0.5 s; with
// the acceleration from the second iteration, 10 substeps of 2 iterations blew up (the
// extrapolation after a single sweep adds energy every step), from the fourth they run. Larger
// rho gains little at 30 iterations (0.95 / 0.98 / 0.99: 304 / 286 / 269 mm at k0 = 1e3, 445 /
// 366 / 551 mm at 1e5): Gauss-Seidel's slow modes here are the lattice's long stretching waves.
inline constexpr double kVbdChebyshevRho = 0.9;
inline constexpr int kVbdChebyshevDelay = 3;  // iterations (0-based) before the first accelerated

// One vertex's start of a step: x_n, the inertial target t and the initial guess, per axis.
template <class T>
struct VbdStart {
  std::array<T, 3> start, target, guess;
};

// vbd.cpp's header: t = x_n + h v_n + h^2 f / w, and the guess x_n + h v_n + h^2 a~ with a~ the
// last step's acceleration along gravity clamped to [0, |g|] (the paper's eq. (19); the full
// gravity when not warm). Pinned vertices sit at x_n in all three.
template <class T>
VbdStart<T> vbd_start(const Model<T>& m, std::size_t i, const State<T>& s, const Vec3Array<T>& f,
                      const Vec3Array<T>& last_vel, T h, bool warm) {
  const std::array<T, 3>& g = m.gravity;
  const T g_norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  const bool free = m.inv_mass[i] != T(0);
  const T w = m.mass[i] + h * m.drag;
  T along = g_norm;
  if (warm && g_norm > T(0)) {
    T a_dot_g = 0;
    for (int a = 0; a < 3; ++a) a_dot_g += (s.vel.axis(a)[i] - last_vel.axis(a)[i]) / h * g[a];
    along = std::clamp(a_dot_g / g_norm, T(0), g_norm);
  }
  VbdStart<T> r;
  for (int a = 0; a < 3; ++a) {
    const T x = s.pos.axis(a)[i], v = free ? s.vel.axis(a)[i] : T(0);
    const T inertial = x + h * v;
    const T dir = g_norm > T(0) ? g[a] / g_norm : T(0);
    r.start[a] = x;
    r.target[a] = free ? inertial + h * h * f.axis(a)[i] / w : x;
    r.guess[a] = free ? inertial + h * h * along * dir : x;
  }
  return r;
}

// A vertex's gradient g and Hessian H (symmetric: six entries) of the incremental potential.
template <class T>
struct VbdBlock {
  T gx, gy, gz, hxx, hxy, hxz, hyy, hyz, hzz;
};

// The block's inertial term: g = w (x - t) from (dx, dy, dz) = x - t, and H = w I.
template <class T>
[[gnu::always_inline]] inline VbdBlock<T> vbd_inertia(T w, T dx, T dy, T dz) {
  return {w * dx, w * dy, w * dz, w, T(0), T(0), w, T(0), w};
}

// Adds one spring to the block of its end i (vbd.cpp's header): (ex, ey, ez) = x_j - x_i,
// (rx, ry, rz) = dx_i - dx_j, kh2 = h^2 k, ch = h c. A spring of no length has no direction and
// adds only its isotropic stiffness. Branch-free, so the grid path's loops vectorise.
template <class T>
[[gnu::always_inline]] inline void vbd_add_spring(T ex, T ey, T ez, T rx, T ry, T rz, T kh2, T ch,
                                                  T rest, VbdBlock<T>& b) {
  const T len = std::sqrt(ex * ex + ey * ey + ez * ez);
  const T inv_len = len > T(0) ? T(1) / len : T(0);
  const T nx = ex * inv_len, ny = ey * inv_len, nz = ez * inv_len;
  // Along n: Hooke's pull and the damper on the relative displacement this step.
  const T pull = -kh2 * (len - rest) + ch * (nx * rx + ny * ry + nz * rz);
  b.gx += pull * nx, b.gy += pull * ny, b.gz += pull * nz;
  const T tw = len > rest ? kh2 * (T(1) - rest * inv_len) : T(0);  // transverse
  const T iso = len > T(0) ? tw : kh2;
  const T along = kh2 + ch - tw;
  b.hxx += iso + along * nx * nx, b.hyy += iso + along * ny * ny, b.hzz += iso + along * nz * nz;
  b.hxy += along * nx * ny, b.hxz += along * nx * nz, b.hyz += along * ny * nz;
}

// The Newton step H^-1 g (adjugate over determinant) into (sx, sy, sz); returns det(H), which
// is positive where H is positive definite (else the caller leaves the vertex).
template <class T>
[[gnu::always_inline]] inline T vbd_newton_step(const VbdBlock<T>& b, T& sx, T& sy, T& sz) {
  const T cxx = b.hyy * b.hzz - b.hyz * b.hyz, cxy = b.hxz * b.hyz - b.hxy * b.hzz,
          cxz = b.hxy * b.hyz - b.hxz * b.hyy;
  const T cyy = b.hxx * b.hzz - b.hxz * b.hxz, cyz = b.hxy * b.hxz - b.hxx * b.hyz,
          czz = b.hxx * b.hyy - b.hxy * b.hxy;
  const T det = b.hxx * cxx + b.hxy * cxy + b.hxz * cxz;
  const T inv = det > T(0) ? T(1) / det : T(0);
  sx = (cxx * b.gx + cxy * b.gy + cxz * b.gz) * inv;
  sy = (cxy * b.gx + cyy * b.gy + cyz * b.gz) * inv;
  sz = (cxz * b.gx + cyz * b.gy + czz * b.gz) * inv;
  return det;
}

}  // namespace clothlab
