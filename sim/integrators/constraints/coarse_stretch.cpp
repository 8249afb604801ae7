#include "sim/integrators/constraints/coarse_stretch.hpp"

#include <algorithm>
#include <cmath>

#include "sim/integrators/constraints/tethers.hpp"

namespace clothlab {
namespace {

// The coarse stencil: axes and diagonals (a coarse edge spans two fine ones).
constexpr int kCoarseOffsets[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};

}  // namespace

int coarse_level_count(int nu, int nv) {
  int levels = 0;
  while (std::min(nu, nv) >= 2 * kCoarseMinSide) {
    nu = (nu + 1) / 2;
    nv = (nv + 1) / 2;
    ++levels;
  }
  return levels;
}

template <class T>
CoarseStretch<T>::CoarseStretch(const Model<T>& m) {
  for (std::size_t c = 0; c < m.cloths.size(); ++c) {
    const ClothRange& r = m.cloths[c];
    if (!stretch_limited(m, c)) continue;
    const int count = coarse_level_count(r.nu, r.nv);
    if (count == 0) continue;
    Cloth cloth{r.offset, r.nu, r.nv, {}, cloth_slack(m, c)};
    int nu = r.nu, nv = r.nv;
    std::vector<std::int32_t> under(static_cast<std::size_t>(nu) * nv);
    for (std::size_t k = 0; k < under.size(); ++k)
      under[k] = static_cast<std::int32_t>(r.offset + static_cast<int>(k));
    for (int l = 0; l < count; ++l) {
      Level level;
      level.nu = (nu + 1) / 2;
      level.nv = (nv + 1) / 2;
      for (int J = 0; J < level.nv; ++J)
        for (int I = 0; I < level.nu; ++I)
          level.fine.push_back(under[static_cast<std::size_t>(2 * J) * nu + 2 * I]);
      for (int o = 0; o < 4; ++o) {
        const auto [di, dj] = kCoarseOffsets[o];
        const int a = std::max(0, -di), b = a + dj * level.nu + di;  // the first such pair
        level.rest[o] = static_cast<T>(rest_distance(m, static_cast<std::size_t>(level.fine[a]),
                                                     static_cast<std::size_t>(level.fine[b])));
        level.limit[o] = level.rest[o];
      }
      level.x.resize(level.fine.size());
      level.x0.resize(level.fine.size());
      level.w.resize(level.fine.size());
      under = level.fine;
      nu = level.nu;
      nv = level.nv;
      cloth.levels.push_back(std::move(level));
    }
    cloths_.push_back(std::move(cloth));
  }
}

template <class T>
void CoarseStretch<T>::apply(Vec3Array<T>& pos, const T* inv_mass) {
  for (Cloth& c : cloths_) {
    restrict_positions(c, pos, inv_mass);
    for (auto l = c.levels.size(); l-- > 0;) {
      Level& level = c.levels[l];
      for (int sweep = 0; sweep < kCoarseSweeps; ++sweep) project(level);
      if (l > 0) {
        Level& finer = c.levels[l - 1];
        prolong(level, finer.nu, finer.nv, finer.x.x.data(), finer.x.y.data(), finer.x.z.data(),
                finer.w.data());
      }
    }
    const auto o = static_cast<std::size_t>(c.offset);
    prolong(c.levels.front(), c.nu, c.nv, pos.x.data() + o, pos.y.data() + o, pos.z.data() + o,
            inv_mass + o);
  }
}

template <class T>
void CoarseStretch<T>::restrict_positions(Cloth& c, const Vec3Array<T>& pos, const T* inv_mass) {
  for (Level& level : c.levels) {
    const long n = static_cast<long>(level.fine.size());
#pragma omp for schedule(static)
    for (long k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(level.fine[static_cast<std::size_t>(k)]);
      const auto kk = static_cast<std::size_t>(k);
      for (int a = 0; a < 3; ++a) level.x.axis(a)[kk] = level.x0.axis(a)[kk] = pos.axis(a)[i];
      level.w[kk] = inv_mass[i];
    }
  }
}

// PBD's projection of the one-sided distance constraint |x_a - x_b| <= rest (rigid: the coarse
// levels only remove stretch the fine sweeps left), pass by pass.
template <class T>
void CoarseStretch<T>::project(Level& l) {
  for (int o = 0; o < 4; ++o)
    for (int cls = 0; cls < 2; ++cls) project_rows(l, o, cls);
}

namespace {

// Springs (a + k Step, a + k Step + shift), k in [0, count): one row of one pass; Step is 2
// within a row (one parity class of the row's own offset), 1 across rows.
template <class T, int Step>
void project_run(T* x, T* y, T* z, const T* w, std::size_t a0, std::size_t shift, int count,
                 T rest) {
  T* __restrict ax = x + a0;
  T* __restrict ay = y + a0;
  T* __restrict az = z + a0;
  T* __restrict bx = x + a0 + shift;
  T* __restrict by = y + a0 + shift;
  T* __restrict bz = z + a0 + shift;
  const T* __restrict wa = w + a0;
  const T* __restrict wb = w + a0 + shift;
#pragma omp simd
  for (int k = 0; k < count; ++k) {
    const int i = k * Step;
    const T dx = ax[i] - bx[i], dy = ay[i] - by[i], dz = az[i] - bz[i];
    const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
    const T wsum = wa[i] + wb[i];
    // Selects: a constraint that does not act leaves its ends' bits alone.
    const bool acts = len > rest && wsum > T(0);
    const T f = acts ? (len - rest) / (len * wsum) : T(0);
    ax[i] = acts ? ax[i] - wa[i] * f * dx : ax[i];
    ay[i] = acts ? ay[i] - wa[i] * f * dy : ay[i];
    az[i] = acts ? az[i] - wa[i] * f * dz : az[i];
    bx[i] = acts ? bx[i] + wb[i] * f * dx : bx[i];
    by[i] = acts ? by[i] + wb[i] * f * dy : by[i];
    bz[i] = acts ? bz[i] + wb[i] * f * dz : bz[i];
  }
}

}  // namespace

template <class T>
void CoarseStretch<T>::set_substep(double h) {
  for (Cloth& c : cloths_) {
    const double scale = c.slack.scale(h);
    for (Level& l : c.levels)
      for (int o = 0; o < 4; ++o) l.limit[o] = static_cast<T>(double(l.rest[o]) * scale);
  }
}

template <class T>
void CoarseStretch<T>::project_rows(Level& l, int o, int cls) {
  // Plain variables, not a structured binding: clang before 16 cannot use one inside the
  // `omp for` loop below (scripts/fuzz builds with clang).
  const int di = kCoarseOffsets[o][0], dj = kCoarseOffsets[o][1];
  const int rows = l.nv - dj;
  const int first = dj > 0 ? std::max(0, -di) : cls;
  const int last = l.nu - std::max(0, di);  // exclusive end of the start column
  const std::size_t shift = static_cast<std::size_t>(dj * l.nu + di);
#pragma omp for schedule(static)
  for (int J = 0; J < rows; ++J) {
    if (dj > 0 && (J & 1) != cls) continue;
    const std::size_t a0 = static_cast<std::size_t>(J) * l.nu + static_cast<std::size_t>(first);
    if (dj > 0) {
      project_run<T, 1>(l.x.x.data(), l.x.y.data(), l.x.z.data(), l.w.data(), a0, shift,
                        std::max(0, last - first), l.limit[o]);
    } else {
      project_run<T, 2>(l.x.x.data(), l.x.y.data(), l.x.z.data(), l.w.data(), a0, shift,
                        std::max(0, (last - first + 1) / 2), l.limit[o]);
    }
  }
}

// Finer vertex (i, j) lies at coarse (i / 2, j / 2) when both are even, else halfway between two
// or four coarse vertices: the mean of their displacements (clamped at the far edge of an even
// side, whose last column or row has no coarse vertex beyond it). Per finer row and chunk of
// coarse columns, the coarse displacements interpolated between the two coarse rows go into a
// buffer first (one beyond the chunk, clamped), so that the even and the odd columns read
// contiguous memory (reading column I + 1 clamped, GCC gathered). Pinned vertices do not move.
template <class T>
void CoarseStretch<T>::prolong(const Level& c, int nu, int nv, T* x, T* y, T* z, const T* w) {
  constexpr int kChunk = 256;
  T* target[3] = {x, y, z};
  const int pairs = nu / 2;  // columns 2I and 2I + 1 with I + 1 < c.nu, or clamped
#pragma omp for schedule(static)
  for (int j = 0; j < nv; ++j) {
    const int J0 = std::min(j / 2, c.nv - 1), J1 = std::min(J0 + (j & 1), c.nv - 1);
    const std::size_t r0 = static_cast<std::size_t>(J0) * c.nu,
                      r1 = static_cast<std::size_t>(J1) * c.nu;
    const std::size_t f0 = static_cast<std::size_t>(j) * nu;
    for (int a = 0; a < 3; ++a) {
      const T* __restrict now = c.x.axis(a).data();
      const T* __restrict was = c.x0.axis(a).data();
      T* __restrict out = target[a] + f0;
      const T* __restrict wf = w + f0;
      // Coarse column I's displacement, interpolated between the two coarse rows.
      const auto displacement = [&](std::size_t I) {
        return T(0.5) * ((now[r0 + I] - was[r0 + I]) + (now[r1 + I] - was[r1 + I]));
      };
      for (int I0 = 0; I0 < c.nu; I0 += kChunk) {
        const int n = std::min(kChunk, c.nu - I0), m = std::min(n + 1, c.nu - I0);
        alignas(64) T d[kChunk + 1];  // coarse column I0 + k's displacement
#pragma omp simd
        for (int k = 0; k < m; ++k) d[k] = displacement(static_cast<std::size_t>(I0 + k));
        if (m == n) d[n] = d[n - 1];
        const int count = std::min(n, pairs - I0);
        T* __restrict o = out + 2 * static_cast<std::size_t>(I0);
        const T* __restrict wo = wf + 2 * static_cast<std::size_t>(I0);
#pragma omp simd
        for (int k = 0; k < count; ++k) {
          const T even = d[k], odd = T(0.5) * (d[k] + d[k + 1]);
          o[2 * k] += wo[2 * k] > T(0) ? even : T(0);
          o[2 * k + 1] += wo[2 * k + 1] > T(0) ? odd : T(0);
        }
      }
      if (nu % 2 == 1)
        out[nu - 1] += wf[nu - 1] > T(0) ? displacement(std::size_t(c.nu - 1)) : T(0);
    }
  }
}

template class CoarseStretch<float>;
template class CoarseStretch<double>;

}  // namespace clothlab
