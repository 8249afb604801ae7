// The band kernel for grid cloths: the same physics as spring_forces.hpp (Hooke plus
// along-spring damping), with each spring evaluated once and its force applied to both ends
// (F_ab = -F_ba exactly), and the neighbours of one grid row under one stencil offset read as a
// contiguous run of memory: no index array, no gathers, every loop streams and vectorises.
//
// Rows are cut into bands of a fixed number of rows that depends on the grid alone (never on
// the thread count). A spring runs from its lower-index end a to b = a + di + dj * nu with
// dj > 0, or dj = 0 and di > 0, so it adds to row j (a) and row j + dj (b). Within a band
// everything is added in place; forces on the `reach` rows after the band go into the band's
// halo, which a second pass adds after every band is done. Each vertex's forces are summed in
// one fixed order whatever the thread count, so a step is the same bits on 1 and 2 threads.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "sim/model/model.hpp"

namespace clothlab {

// Rows per band: at least kBandVertices vertices, and never fewer rows than the stencil reaches
// (so a band's halo lands inside the next band) nor fewer than kMinBandRows (so the halo pass
// touches at most a quarter of the rows).
inline constexpr int kBandVertices = 512;
inline constexpr int kMinBandRows = 8;
// Columns per chunk of a row: the run kernel makes its pass per stencil offset over one chunk
// of a row before the next (the force pass alone: 512^2 1.26-1.33x faster than whole-row passes
// when the host's memory is not the limit, no change up to 256 wide; docs/design.md).
// Rows shorter than that go kChunkColumns / nu rows to a pass instead (a 32-wide grid: 8 rows),
// so a pass does more than two vector runs; a vertex's column then says which springs exist.
inline constexpr int kChunkColumns = 256;

template <class T>
struct GridBands {
  using Entry = typename GridStencil<T>::Entry;
  int rows = 1, count = 1, reach = 0, pad = 0, nu = 0;
  int group = 1;                  // rows per pass (short rows; kChunkColumns)
  int stride = 0;                 // a scratch row: pad + group nu
  std::vector<int> column;        // column[k] = k mod nu for the vertices of one pass
  std::vector<Entry> same_row;    // dj == 0, di > 0
  std::vector<Entry> later_rows;  // dj > 0
  // Band b's forces on rows j1 .. j1 + reach - 1 after it: reach * nu per band.
  Vec3Array<T> halo;
  // Band b's same-row springs, one scratch row (stride) per offset: s[pad + i] is the force on
  // the pass's vertex i from the spring (i, i + di), zero where that spring does not exist (pad
  // leading zeros included).
  Vec3Array<T> same_row_force;

  void resize(const GridStencil<T>& g) {
    nu = g.nu;
    same_row.clear();
    later_rows.clear();
    reach = 0;
    pad = 0;
    for (const Entry& e : g.entries) {
      if (!e.first_half) continue;
      if (e.dj == 0) {
        same_row.push_back(e);
        pad = std::max(pad, e.di);
      } else {
        later_rows.push_back(e);
        reach = std::max(reach, e.dj);
      }
    }
    const int wanted = (kBandVertices + g.nu - 1) / std::max(1, g.nu);
    rows = std::max({reach, kMinBandRows, wanted});
    count = std::max(1, g.nv / rows);  // the last band takes the remainder: never shorter
    halo.resize(static_cast<std::size_t>(count) * static_cast<std::size_t>(reach) * g.nu);
    group = std::max(1, kChunkColumns / std::max(1, g.nu));
    stride = pad + group * g.nu;
    column.resize(group > 1 ? static_cast<std::size_t>(group * g.nu) : 0);  // multi-row passes
    for (std::size_t k = 0; k < column.size(); ++k) column[k] = static_cast<int>(k) % g.nu;
    same_row_force.resize(static_cast<std::size_t>(count) * same_row.size() *
                          static_cast<std::size_t>(stride));
  }
  int first_row(int b) const { return b * rows; }
  int end_row(int b, int nv) const { return b + 1 == count ? nv : (b + 1) * rows; }
};

// Rows [j_begin, j_end) of grid g as the range of their vertex indices.
template <class T>
std::pair<std::size_t, std::size_t> grid_rows(const GridStencil<T>& g, int j_begin, int j_end) {
  const auto row = [&](int j) {
    return static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(j) * g.nu;
  };
  return {row(j_begin), row(j_end)};
}

namespace detail {

// The force on a from the spring (a, b): F = (k (len - L) + c (v_b - v_a).d / len) d / len,
// returned as the factor of d; a zero-length spring gets no force. The guard is a select, which
// GCC if-converts (and so vectorises the loops) only under -fno-trapping-math (CMakeLists.txt).
template <class T, bool Damped>
[[gnu::always_inline]] inline T spring_scale(T dx, T dy, T dz, T rvx, T rvy, T rvz, T k, T rest,
                                             T c) {
  const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
  const T inv_len = len > T(0) ? T(1) / len : T(0);
  T scale = k * (len - rest) * inv_len;
  if constexpr (Damped) scale += c * (rvx * dx + rvy * dy + rvz * dz) * inv_len * inv_len;
  return scale;
}

// Runs body(i, live) for i in [lo, hi) in whole vectors: the indices past the last whole run of
// kSimdRun go once more through one run ending at hi, with live false for those already done,
// instead of a scalar remainder loop. A row of 256 under an offset of di = 1 has 255 springs:
// the scalar remainder of 15 cost about as much as the 15 vectors before it.
inline constexpr int kSimdRun = 16;  // AVX-512 floats; two AVX2 vectors

template <class Body>
inline void for_each_lane(int lo, int hi, Body&& body) {
  if (hi - lo < kSimdRun) {
#pragma omp simd
    for (int i = lo; i < hi; ++i) body(i, true);
    return;
  }
  // Runs of a constant length: GCC vectorised a plain loop over [lo, whole) with a prologue and
  // remainder that ran scalar (a tenth of the step in a profile).
  const int whole = lo + (hi - lo) / kSimdRun * kSimdRun;
  for (int run = lo; run < whole; run += kSimdRun) {
#pragma omp simd
    for (int l = 0; l < kSimdRun; ++l) body(run + l, true);
  }
  if (whole == hi) return;
  const int last = hi - kSimdRun;
#pragma omp simd
  for (int l = 0; l < kSimdRun; ++l) body(last + l, last + l >= whole);
}

// The two ends of one stencil offset's springs along a row: end b of spring i is end a shifted
// by `shift` entries. force(i) is the force on a (minus the force on b).
template <class T, bool Damped>
struct SpringEnds {
  const T *ax, *ay, *az, *bx, *by, *bz, *avx, *avy, *avz, *bvx, *bvy, *bvz;
  T k, rest, c;
  SpringEnds(const typename GridStencil<T>::Entry& e, long shift, const T* x[3], const T* v[3])
      : ax(x[0]),
        ay(x[1]),
        az(x[2]),
        bx(x[0] + shift),
        by(x[1] + shift),
        bz(x[2] + shift),
        avx(v[0]),
        avy(v[1]),
        avz(v[2]),
        bvx(v[0] + shift),
        bvy(v[1] + shift),
        bvz(v[2] + shift),
        k(e.stiffness),
        rest(e.rest_length),
        c(e.damping) {}
  // Always inlined: in the library build GCC once kept it out of line in the row passes, so
  // their loops called it per lane instead of vectorising (32^2 step 1.4x slower).
  [[gnu::always_inline]] void force(int i, T& fx, T& fy, T& fz) const {
    const T dx = bx[i] - ax[i], dy = by[i] - ay[i], dz = bz[i] - az[i];
    T rvx = 0, rvy = 0, rvz = 0;
    if constexpr (Damped) {
      rvx = bvx[i] - avx[i];
      rvy = bvy[i] - avy[i];
      rvz = bvz[i] - avz[i];
    }
    const T scale = spring_scale<T, Damped>(dx, dy, dz, rvx, rvy, rvz, k, rest, c);
    fx = scale * dx;
    fy = scale * dy;
    fz = scale * dz;
  }
};

// The springs of offset e from the vertices a in [lo, hi) (indices from x's start) for which
// has(a) holds: fa[a] += F, fb[a + di] -= F.
template <class T, bool Damped, class Has>
void add_offset_run(const typename GridStencil<T>::Entry& e, int lo, int hi, const T* x[3],
                    const T* v[3], T* fa[3], T* fb[3], Has&& has) {
  if (hi <= lo) return;
  const SpringEnds<T, Damped> ends(e, e.shift, x, v);
  T* __restrict fax = fa[0];
  T* __restrict fay = fa[1];
  T* __restrict faz = fa[2];
  T* __restrict fbx = fb[0] + e.di;
  T* __restrict fby = fb[1] + e.di;
  T* __restrict fbz = fb[2] + e.di;
  for_each_lane(lo, hi, [&](int i, bool live) {
    T fx, fy, fz;
    ends.force(i, fx, fy, fz);
    live = live && has(i);
    fx = live ? fx : T(0);  // a select, not 0 * F: a non-finite F must not reach a done vertex
    fy = live ? fy : T(0);
    fz = live ? fz : T(0);
    fax[i] += fx;
    fay[i] += fy;
    faz[i] += fz;
    fbx[i] -= fx;
    fby[i] -= fy;
    fbz[i] -= fz;
  });
}

// Springs of row j to row j + e.dj from the vertices a in columns [c0, c1): f[a] += F on row j,
// dst[b] -= F on the target row (in f, or in the halo when the target row lies after the band).
template <class T, bool Damped>
void add_later_row_springs(const typename GridStencil<T>::Entry& e, int nu, int c0, int c1,
                           const T* x[3], const T* v[3], T* fa[3], T* fb[3]) {
  add_offset_run<T, Damped>(e, std::max(c0, -e.di), std::min(c1, nu - e.di), x, v, fa, fb,
                            [](int) { return true; });
}

// Springs within row j, for the vertices of columns [c0, c1) (the columns before are done):
// each spring's force once into the band's scratch row, then both ends from it in one pass
// (f[i] += s[i] - s[i - di]), which has no dependence between iterations.
template <class T, bool Damped>
void add_same_row_springs(const GridBands<T>& bands, Vec3Array<T>& scratch, std::size_t base,
                          int nu, int c0, int c1, const T* x[3], const T* v[3], T* f[3]) {
  const int pad = bands.pad;
  const auto stride = static_cast<std::size_t>(bands.stride);
  for (std::size_t q = 0; q < bands.same_row.size(); ++q) {
    const auto& e = bands.same_row[q];
    const SpringEnds<T, Damped> ends(e, e.di, x, v);
    T* __restrict sx = scratch.x.data() + base + q * stride + pad;
    T* __restrict sy = scratch.y.data() + base + q * stride + pad;
    T* __restrict sz = scratch.z.data() + base + q * stride + pad;
    const int hi = std::min(c1, nu - e.di);
    // Writing a spring's force twice writes the same bits: no mask needed.
    for_each_lane(c0, hi, [&](int i, bool) { ends.force(i, sx[i], sy[i], sz[i]); });
    for (int i = std::max(c0, hi); i < c1; ++i) sx[i] = sy[i] = sz[i] = T(0);
    T* __restrict fx = f[0];
    T* __restrict fy = f[1];
    T* __restrict fz = f[2];
    const int di = e.di;
#pragma omp simd
    for (int i = c0; i < c1; ++i) {
      fx[i] += sx[i] - sx[i - di];
      fy[i] += sy[i] - sy[i - di];
      fz[i] += sz[i] - sz[i - di];
    }
  }
}

// The same two for a pass over n vertices of whole rows (rows shorter than kChunkColumns): a
// spring exists where the vertex's column plus di lies in the row. The lanes stop short of the
// pass's last di vertices (no spring there), so nothing past the last row is read.
template <class T, bool Damped>
void add_same_row_pass(const GridBands<T>& bands, Vec3Array<T>& scratch, std::size_t base, int n,
                       const T* x[3], const T* v[3], T* f[3]) {
  const auto stride = static_cast<std::size_t>(bands.stride);
  const int* __restrict col = bands.column.data();
  for (std::size_t q = 0; q < bands.same_row.size(); ++q) {
    const auto& e = bands.same_row[q];
    const SpringEnds<T, Damped> ends(e, e.di, x, v);
    T* __restrict sx = scratch.x.data() + base + q * stride + bands.pad;
    T* __restrict sy = scratch.y.data() + base + q * stride + bands.pad;
    T* __restrict sz = scratch.z.data() + base + q * stride + bands.pad;
    const int di = e.di, last = bands.nu - di, hi = std::max(0, n - di);
    for_each_lane(0, hi, [&](int i, bool) {
      T fx, fy, fz;
      ends.force(i, fx, fy, fz);
      const bool live = col[i] < last;
      sx[i] = live ? fx : T(0);
      sy[i] = live ? fy : T(0);
      sz[i] = live ? fz : T(0);
    });
    for (int i = hi; i < n; ++i) sx[i] = sy[i] = sz[i] = T(0);
    T* __restrict fx = f[0];
    T* __restrict fy = f[1];
    T* __restrict fz = f[2];
#pragma omp simd
    for (int i = 0; i < n; ++i) {
      fx[i] += sx[i] - sx[i - di];
      fy[i] += sy[i] - sy[i - di];
      fz[i] += sz[i] - sz[i - di];
    }
  }
}

template <class T, bool Damped>
void add_later_row_pass(const typename GridStencil<T>::Entry& e, const GridBands<T>& bands, int n,
                        const T* x[3], const T* v[3], T* fa[3], T* fb[3]) {
  const int* __restrict col = bands.column.data();
  const int di = e.di, nu = bands.nu;
  add_offset_run<T, Damped>(e, std::max(0, -di), n - std::max(0, di), x, v, fa, fb,
                            [&](int i) { return col[i] + di >= 0 && col[i] + di < nu; });
}

// Rows [j, je) of a band ending at j1 in one pass per stencil offset (short rows).
template <class T, bool Damped>
void add_row_group(const GridStencil<T>& g, GridBands<T>& bands, const Vec3Array<T>& x,
                   const Vec3Array<T>& v, Vec3Array<T>& f, int j, int je, int j1,
                   std::size_t halo_base, std::size_t scratch_base) {
  const std::size_t nu = static_cast<std::size_t>(g.nu);
  const auto start = [&](int r) { return static_cast<std::size_t>(g.offset) + r * nu; };
  // The three axes of a (x, v, f or the halo) from index k.
  const auto from = [](auto& a, std::size_t k, auto* out) {
    out[0] = a.x.data() + k, out[1] = a.y.data() + k, out[2] = a.z.data() + k;
  };
  const T *xr[3], *vr[3];
  T *fr[3], *dst[3];
  from(x, start(j), xr);
  from(v, start(j), vr);
  from(f, start(j), fr);
  add_same_row_pass<T, Damped>(bands, bands.same_row_force, scratch_base, (je - j) * g.nu, xr, vr,
                               fr);
  for (const auto& e : bands.later_rows) {
    // Rows whose target row exists, and of them those whose target lies inside the band.
    const int jt = std::min(je, g.nv - e.dj), js = std::clamp(j1 - e.dj, j, std::max(j, jt));
    if (js > j) {
      from(f, start(j + e.dj), dst);
      add_later_row_pass<T, Damped>(e, bands, (js - j) * g.nu, xr, vr, fr, dst);
    }
    if (jt > js) {
      const T *xs[3], *vs[3];
      T* fs[3];
      from(x, start(js), xs);
      from(v, start(js), vs);
      from(f, start(js), fs);
      from(bands.halo, halo_base + static_cast<std::size_t>(js + e.dj - j1) * nu, dst);
      add_later_row_pass<T, Damped>(e, bands, (jt - js) * g.nu, xs, vs, fs, dst);
    }
  }
}

}  // namespace detail

// Adds the spring forces of band b's springs to f (rows inside the band) and writes those on
// the rows after it to the band's halo. f on the band's rows must hold their other forces.
template <class T, bool Damped>
void add_band_spring_forces(const GridStencil<T>& g, GridBands<T>& bands, const Vec3Array<T>& x,
                            const Vec3Array<T>& v, Vec3Array<T>& f, int b) {
  const int j0 = bands.first_row(b), j1 = bands.end_row(b, g.nv);
  const std::size_t nu = static_cast<std::size_t>(g.nu);
  const std::size_t halo_base = static_cast<std::size_t>(b) * bands.reach * nu;
  for (int a = 0; a < 3; ++a)
    std::fill_n(bands.halo.axis(a).begin() + static_cast<std::ptrdiff_t>(halo_base),
                static_cast<std::size_t>(bands.reach) * nu, T(0));
  const std::size_t scratch_base =
      static_cast<std::size_t>(b) * bands.same_row.size() * static_cast<std::size_t>(bands.stride);
  auto row_of = [&](Vec3Array<T>& a, std::size_t start, T* out[3]) {
    out[0] = a.x.data() + start;
    out[1] = a.y.data() + start;
    out[2] = a.z.data() + start;
  };
  if (bands.group > 1) {
    for (int j = j0; j < j1; j += bands.group)
      detail::add_row_group<T, Damped>(g, bands, x, v, f, j, std::min(j1, j + bands.group), j1,
                                       halo_base, scratch_base);
    return;
  }
  for (int j = j0; j < j1; ++j) {
    const std::size_t row = static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(j) * nu;
    const T* xr[3] = {x.x.data() + row, x.y.data() + row, x.z.data() + row};
    const T* vr[3] = {v.x.data() + row, v.y.data() + row, v.z.data() + row};
    T* fr[3];
    row_of(f, row, fr);
    // Column chunks: each chunk's stencil passes stay in L1 (a 512-wide row's three rows of x and
    // v alone are 36 KB); ordered chunk by chunk, so the sums stay independent of the threads.
    for (int c0 = 0; c0 < g.nu; c0 += kChunkColumns) {
      const int c1 = std::min(g.nu, c0 + kChunkColumns);
      detail::add_same_row_springs<T, Damped>(bands, bands.same_row_force, scratch_base, g.nu, c0,
                                              c1, xr, vr, fr);
      for (const auto& e : bands.later_rows) {
        const int target = j + e.dj;
        if (target >= g.nv) continue;
        T* dst[3];
        if (target < j1)
          row_of(f, row + static_cast<std::size_t>(e.dj) * nu, dst);
        else
          row_of(bands.halo, halo_base + static_cast<std::size_t>(target - j1) * nu, dst);
        detail::add_later_row_springs<T, Damped>(e, g.nu, c0, c1, xr, vr, fr, dst);
      }
    }
  }
}

// The same, with the dampers chosen at run time (the model's has_damping).
template <class T>
void add_band_spring_forces(const GridStencil<T>& g, GridBands<T>& bands, const Vec3Array<T>& x,
                            const Vec3Array<T>& v, Vec3Array<T>& f, int b, bool damped) {
  if (damped)
    add_band_spring_forces<T, true>(g, bands, x, v, f, b);
  else
    add_band_spring_forces<T, false>(g, bands, x, v, f, b);
}

// Adds band b - 1's halo to the first rows of band b (b >= 1), after every band's springs.
template <class T>
void add_band_halo(const GridStencil<T>& g, const GridBands<T>& bands, Vec3Array<T>& f, int b) {
  const std::size_t nu = static_cast<std::size_t>(g.nu);
  const std::size_t halo_base = static_cast<std::size_t>(b - 1) * bands.reach * nu;
  const int j0 = bands.first_row(b);
  for (int r = 0; r < bands.reach && j0 + r < g.nv; ++r) {
    const std::size_t row =
        static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(j0 + r) * nu;
    const std::size_t h = halo_base + static_cast<std::size_t>(r) * nu;
#pragma omp simd
    for (std::size_t i = 0; i < nu; ++i) {
      f.x[row + i] += bands.halo.x[h + i];
      f.y[row + i] += bands.halo.y[h + i];
      f.z[row + i] += bands.halo.z[h + i];
    }
  }
}

}  // namespace clothlab
