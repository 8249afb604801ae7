// XPBD's grid path (xpbd_grid.hpp): the constraint update of xpbd.cpp (Macklin, Mueller &
// Chentanez 2016, eq. (26) multiplied through by k h^2) in batches of one stencil offset and one
// parity class, band by band. The sweeps move each vertex's displacement d over the substep, not
// its position: a spring's vector is (x0_a - x0_b) + (d_a - d_b) with x0 the substep's start, so
// the corrections round at the displacement's scale, and the velocity is d / h. Summed into a
// float position near 1 m each correction would round at 6e-8 m, and the velocity (x - x0) / h
// took every rounding over h: from about 160 substeps a frame that noise, not the method, set the
// error (docs/solver.md, "Displacements, not positions, in float").
#include "sim/integrators/constraints/xpbd_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <utility>

#include "sim/core/parallel.hpp"
#include "sim/integrators/constraints/coarse_stretch.hpp"
#include "sim/integrators/constraints/tethers.hpp"

namespace clothlab {
namespace {

// Vertices per band: a band's positions, displacements and inverse masses (28 bytes a
// vertex) stay in a core's L2 while its 20 batches pass over it.
constexpr int kXpbdBandVertices = 4096;
constexpr int kXpbdMinBandRows = 4;

// One offset of the stencil with its spring: class of the spring from (i, j) is
// (index / step) % 2 with index j and step dj when dj > 0, else i and di.
template <class T>
struct StencilOffset {
  int di = 0, dj = 0;
  T stiffness = 0, rest = 0, damping = 0;
  int step() const { return dj > 0 ? dj : di; }
};

template <class T>
struct BandedPart {
  int offset = 0, nu = 0, nv = 0, reach = 0, rows = 1, bands = 1;
  std::vector<StencilOffset<T>> offsets;  // first half of the stencil, in stencil order
  // Same-row offsets o: in_class[2 o + cls][i] = 1 where spring (i, i + di) is of class cls (a
  // mask the vector loop loads: floor(i / di) has no vector instruction).
  std::vector<AlignedVector<T>> in_class;
  int band_begin(int b) const { return b * rows; }
  int band_end(int b) const { return b + 1 == bands ? nv : (b + 1) * rows; }
  int band_of(int j) const { return std::min(bands - 1, j / rows); }
};

template <class T>
BandedPart<T> banded_part(const GridStencil<T>& g) {
  BandedPart<T> p;
  p.offset = g.offset;
  p.nu = g.nu;
  p.nv = g.nv;
  for (const auto& e : g.entries) {
    if (!e.first_half) continue;
    p.offsets.push_back({e.di, e.dj, e.stiffness, e.rest_length, e.damping});
    p.reach = std::max(p.reach, e.dj);
    for (int cls = 0; cls < 2; ++cls) {
      AlignedVector<T> mask;
      if (e.dj == 0)
        for (int i = 0; i < g.nu; ++i) mask.push_back((i / e.di) % 2 == cls ? T(1) : T(0));
      p.in_class.push_back(std::move(mask));
    }
  }
  const int wanted = (kXpbdBandVertices + g.nu - 1) / std::max(1, g.nu);
  p.rows = std::max({wanted, kXpbdMinBandRows, p.reach + 1});
  p.bands = std::max(1, g.nv / p.rows);
  return p;
}

// The constants of one spring of a batch for the substep h.
template <class T>
struct SpringConstants {
  T kh2, ch, rest;
};

// Everything one spring update needs of its two ends: their displacements this substep (x, y, z;
// the update moves them) and their positions at its start (qx, qy, qz).
template <class T>
struct EndView {
  T *x, *y, *z;
  const T *qx, *qy, *qz, *w;
};

// The update of spring (a, b): dlambda and the unit vector n from b to a; zero where the
// spring has no length (no direction, so no correction).
template <class T>
[[gnu::always_inline]] inline T spring_update(T dx, T dy, T dz, T mx, T my, T mz, T wab, T lam,
                                              SpringConstants<T> s, T& nx, T& ny, T& nz) {
  const T len = std::sqrt(dx * dx + dy * dy + dz * dz);
  const T inv_len = len > T(0) ? T(1) / len : T(0);
  nx = dx * inv_len;
  ny = dy * inv_len;
  nz = dz * inv_len;
  const T stretch = len > T(0) ? len - s.rest : T(0);
  // grad C . (d_a - d_b): the relative displacement along the spring this substep.
  const T moved = nx * mx + ny * my + nz * mz;
  return (-s.kh2 * stretch - lam - s.ch * moved) / ((s.kh2 + s.ch) * wab + T(1));
}

// Springs (a + i, b + i), i in [0, count): a and b are runs in two different rows, so no lane
// touches another's vertex. Keep: lambda is stored for a later sweep (sweeps > 1); First: the
// stored lambda is 0 (the substep's first sweep).
template <class T, bool First, bool Keep>
void run_pairs(const EndView<T>& a, const EndView<T>& b, T* __restrict lambda, int count,
               SpringConstants<T> s) {
  T* __restrict ax = a.x;
  T* __restrict ay = a.y;
  T* __restrict az = a.z;
  T* __restrict bx = b.x;
  T* __restrict by = b.y;
  T* __restrict bz = b.z;
  const T* __restrict aqx = a.qx;
  const T* __restrict aqy = a.qy;
  const T* __restrict aqz = a.qz;
  const T* __restrict bqx = b.qx;
  const T* __restrict bqy = b.qy;
  const T* __restrict bqz = b.qz;
  const T* __restrict aw = a.w;
  const T* __restrict bw = b.w;
#pragma omp simd
  for (int i = 0; i < count; ++i) {
    const T mx = ax[i] - bx[i], my = ay[i] - by[i], mz = az[i] - bz[i];
    const T lam = First ? T(0) : lambda[i];
    const T wa = aw[i], wb = bw[i];
    T nx, ny, nz;
    const T dl = spring_update((aqx[i] - bqx[i]) + mx, (aqy[i] - bqy[i]) + my,
                               (aqz[i] - bqz[i]) + mz, mx, my, mz, wa + wb, lam, s, nx, ny, nz);
    if constexpr (Keep) lambda[i] = lam + dl;
    const T da = wa * dl, db = wb * dl;
    ax[i] += da * nx;
    ay[i] += da * ny;
    az[i] += da * nz;
    bx[i] -= db * nx;
    by[i] -= db * ny;
    bz[i] -= db * nz;
  }
}

// Four scratch rows (dl, nx, ny, nz) of `pad` leading zeros and then one entry per column:
// row(r)[i] is spring i's, row(r)[i - di] for i < di one of the zeros (pad >= every di).
template <class T>
struct RowScratch {
  T* data;
  std::size_t pad, stride;
  T* row(int r) const { return data + static_cast<std::size_t>(r) * stride + pad; }
};

// One row's springs (i, i + di) of one class (in_class[i] != 0): their updates go into a
// scratch row first (zero for the other class), then every vertex takes the update of the
// spring it starts (+) and the one it ends (-) in one contiguous pass. A vertex belongs to at
// most one spring of the class, so the other term is an exact zero.
template <class T, bool First, bool Keep>
void run_row(const EndView<T>& r, int nu, int di, const T* __restrict in_class,
             T* __restrict lambda, const RowScratch<T>& scratch, SpringConstants<T> s) {
  T* __restrict dls = scratch.row(0);
  T* __restrict nxs = scratch.row(1);
  T* __restrict nys = scratch.row(2);
  T* __restrict nzs = scratch.row(3);
  const int count = nu - di;
  // The row's arrays as locals: read through `r` inside the loop, GCC reloads the pointers after
  // every store and does not vectorise it.
  const T* __restrict x = r.x;
  const T* __restrict y = r.y;
  const T* __restrict z = r.z;
  const T* __restrict qx = r.qx;
  const T* __restrict qy = r.qy;
  const T* __restrict qz = r.qz;
  const T* __restrict w = r.w;
#pragma omp simd
  for (int i = 0; i < count; ++i) {
    const int k = i + di;
    const T mx = x[i] - x[k], my = y[i] - y[k], mz = z[i] - z[k];
    const T lam = First ? T(0) : lambda[i];
    T nx, ny, nz;
    const T dl = spring_update((qx[i] - qx[k]) + mx, (qy[i] - qy[k]) + my, (qz[i] - qz[k]) + mz, mx,
                               my, mz, w[i] + w[k], lam, s, nx, ny, nz);
    const bool live = in_class[i] != T(0);
    if constexpr (Keep) lambda[i] = live ? lam + dl : lambda[i];  // the other class keeps its own
    dls[i] = live ? dl : T(0);
    nxs[i] = live ? nx : T(0);
    nys[i] = live ? ny : T(0);
    nzs[i] = live ? nz : T(0);
  }
  for (int i = count; i < nu; ++i) dls[i] = nxs[i] = nys[i] = nzs[i] = T(0);
  T* __restrict ox = r.x;
  T* __restrict oy = r.y;
  T* __restrict oz = r.z;
#pragma omp simd
  for (int i = 0; i < nu; ++i) {
    const T da = w[i] * dls[i], db = w[i] * dls[i - di];
    ox[i] += da * nxs[i] - db * nxs[i - di];
    oy[i] += da * nys[i] - db * nys[i - di];
    oz[i] += da * nzs[i] - db * nzs[i - di];
  }
}

template <class T>
class XpbdGrid final : public Integrator<T> {
 public:
  XpbdGrid(const Model<T>& m, const SolverSpec& spec);

  void step(const System<T>& sys, State<T>& s, double t, T h) override;

  SolveStats last_stats() const override { return {sweeps_, 0.0, true}; }

 private:
  struct BandRef {
    int cloth, band;
  };

  // The prediction (xpbd.cpp: v += h f / m with drag implicit, d = h v) of even
  // band b and the odd band after it: the rows its sweep touches (its own and `reach` rows of
  // the next) and the rest of that odd band, which no other even band touches.
  void predict_rows(const Model<T>& m, State<T>& s, int c, int b, T h);

  // Every batch of band b of cloth c: offsets in stencil order, class 0 then class 1.
  template <bool First>
  void sweep_band(State<T>& s, int c, int b, T h, const RowScratch<T>& scratch);

  EndView<T> view(State<T>& s, std::size_t i);

  // Vertices [b, e): x = x0 + d, kept in landed_ (the coarse levels and tethers then move x).
  void land(State<T>& s, std::size_t b, std::size_t e);
  // Vertices [b, e): landed (unless the coarse levels needed it before), the tethers
  // (tethers.hpp), then v = (d + x - landed) / h: what they moved added to d, rounded once.
  void finish(const Model<T>& m, State<T>& s, T h, std::size_t b, std::size_t e);

  int sweeps_;
  Tethers<T> tethers_;
  CoarseStretch<T> coarse_;
  bool slack_;  // solver.stretch_slack: the two above allow the slack of stretch_slack.hpp
  std::vector<BandedPart<T>> parts_;
  std::vector<std::size_t> lambda_start_;
  std::vector<BandRef> bands_[2];  // phase 0: even bands of every cloth, phase 1: odd
  AlignedVector<T> lambda_;        // sweeps > 1: per offset, per start vertex
  AlignedVector<T> scratch_;
  std::size_t scratch_pad_ = 0, scratch_stride_ = 0;  // RowScratch per band
  Vec3Array<T> disp_;                                 // the substep's displacements d
  Vec3Array<T> landed_;                               // x0 + d, as rounded
  Vec3Array<T> f_;
  const T* inv_mass_ = nullptr;  // the model's, set by step()
};

template <class T>
inline XpbdGrid<T>::XpbdGrid(const Model<T>& m, const SolverSpec& spec)
    : sweeps_(spec.iterations > 0 ? spec.iterations : 1),
      tethers_(spec.tethers ? Tethers<T>(m) : Tethers<T>()),
      coarse_(spec.coarse_stretch ? CoarseStretch<T>(m) : CoarseStretch<T>()),
      slack_(spec.stretch_slack) {
  std::size_t lambda_size = 0;
  int max_nu = 0;
  for (const GridStencil<T>& g : m.grids) {
    parts_.push_back(banded_part(g));
    lambda_start_.push_back(lambda_size);
    lambda_size += parts_.back().offsets.size() * static_cast<std::size_t>(g.nu) * g.nv;
    max_nu = std::max(max_nu, g.nu);
  }
  for (int phase = 0; phase < 2; ++phase)
    for (std::size_t c = 0; c < parts_.size(); ++c)
      for (int b = phase; b < parts_[c].bands; b += 2)
        bands_[phase].push_back({static_cast<int>(c), b});
  if (sweeps_ > 1) lambda_.assign(lambda_size, T(0));
  // One scratch block per band of the larger phase: bands of a phase run at the same time.
  for (const BandedPart<T>& p : parts_)
    for (const StencilOffset<T>& o : p.offsets)
      if (o.dj == 0) scratch_pad_ = std::max(scratch_pad_, static_cast<std::size_t>(o.di));
  scratch_stride_ = scratch_pad_ + static_cast<std::size_t>(max_nu);
  scratch_.assign(4 * scratch_stride_ * std::max(bands_[0].size(), bands_[1].size()), T(0));
  disp_.resize(m.n);
  landed_.resize(m.n);
  if (wind_acts(m)) f_.resize(m.n);
}

template <class T>
inline void XpbdGrid<T>::step(const System<T>& sys, State<T>& s, double t, T h) {
  const Model<T>& m = sys.model;
  if (!f_.x.empty()) compute_external_forces(m, t, s.pos, s.vel, f_, sys.workspace, sys.threads);
  const int threads = sys.threads;
  inv_mass_ = m.inv_mass.data();
  // Pins do not move in the sweep (inverse mass 0), so their positions are final already.
  if (!tethers_.empty()) tethers_.gather_pins(s.pos, m.inv_mass.data());
  if (slack_ && !tethers_.empty()) tethers_.set_substep(double(h));
  if (slack_ && !coarse_.empty()) coarse_.set_substep(double(h));
  const long blocks = static_cast<long>(block_count(m.n));
  run_team(threads, [&] {
    for (int sweep = 0; sweep < sweeps_; ++sweep) {
      for (int phase = 0; phase < 2; ++phase) {
        const auto& list = bands_[phase];
        const long count = static_cast<long>(list.size());
#pragma omp for schedule(static)
        for (long k = 0; k < count; ++k) {
          const auto [c, b] = list[static_cast<std::size_t>(k)];
          if (sweep == 0 && phase == 0) predict_rows(m, s, c, b, h);
          const RowScratch<T> scratch{
              scratch_.data() + 4 * static_cast<std::size_t>(k) * scratch_stride_, scratch_pad_,
              scratch_stride_};
          if (sweep == 0) {
            sweep_band<true>(s, c, b, h, scratch);
          } else {
            sweep_band<false>(s, c, b, h, scratch);
          }
        }
      }
    }
    // After the last phase's barrier the fine displacements are final; the coarse levels
    // correct the positions they make (their loops end in barriers).
    if (!coarse_.empty()) {
#pragma omp for schedule(static)
      for (long k = 0; k < blocks; ++k) {
        const std::size_t b = static_cast<std::size_t>(k) * kBlockSize;
        land(s, b, std::min(m.n, b + kBlockSize));
      }
      coarse_.apply(s.pos, m.inv_mass.data());
    }
#pragma omp for schedule(static)
    for (long k = 0; k < blocks; ++k) {
      const std::size_t b = static_cast<std::size_t>(k) * kBlockSize;
      finish(m, s, h, b, std::min(m.n, b + kBlockSize));
    }
  });
}

template <class T>
inline void XpbdGrid<T>::predict_rows(const Model<T>& m, State<T>& s, int c, int b, T h) {
  const BandedPart<T>& p = parts_[static_cast<std::size_t>(c)];
  const int j1 = b + 1 < p.bands ? p.band_end(b + 1) : p.nv;
  const std::size_t begin =
      static_cast<std::size_t>(p.offset) + static_cast<std::size_t>(p.band_begin(b)) * p.nu;
  const std::size_t end = static_cast<std::size_t>(p.offset) + static_cast<std::size_t>(j1) * p.nu;
  const T* __restrict inv_m = m.inv_mass.data();
  const T* __restrict mass = m.mass.data();
  const T drag = m.drag;
  const bool wind = !f_.x.empty();
  for (int a = 0; a < 3; ++a) {
    const T* __restrict v = s.vel.axis(a).data();
    T* __restrict d = disp_.axis(a).data();
    const T g = m.gravity[a];
    const T* __restrict f = wind ? f_.axis(a).data() : nullptr;
#pragma omp simd
    for (std::size_t i = begin; i < end; ++i) {
      // f holds -drag v (with the wind); adding it back and dividing makes the drag implicit.
      const T push = wind ? f[i] + drag * v[i] : mass[i] * g;
      const T hw = h * inv_m[i];
      const T v_new = inv_m[i] > T(0) ? (v[i] + hw * push) / (T(1) + hw * drag) : T(0);
      d[i] = h * v_new;
    }
  }
}

template <class T>
template <bool First>
inline void XpbdGrid<T>::sweep_band(State<T>& s, int c, int b, T h, const RowScratch<T>& scratch) {
  const BandedPart<T>& p = parts_[static_cast<std::size_t>(c)];
  const int j0 = p.band_begin(b), j1 = p.band_end(b);
  for (std::size_t o = 0; o < p.offsets.size(); ++o) {
    const StencilOffset<T>& off = p.offsets[o];
    const SpringConstants<T> k{off.stiffness * h * h, off.damping * h, off.rest};
    T* lambda = lambda_.empty() ? nullptr
                                : lambda_.data() + lambda_start_[static_cast<std::size_t>(c)] +
                                      o * static_cast<std::size_t>(p.nu) * p.nv;
    for (int cls = 0; cls < 2; ++cls) {
      for (int j = j0; j < j1; ++j) {
        // dj > 0: the class is the row's; dj = 0: every row holds both classes.
        if (off.dj > 0 && ((j / off.dj) % 2 != cls || j + off.dj >= p.nv)) continue;
        const std::size_t row = static_cast<std::size_t>(j) * p.nu;
        T* lam = lambda ? lambda + row : nullptr;
        if (off.dj == 0) {
          const EndView<T> r = view(s, p.offset + row);
          const T* mask = p.in_class[2 * o + static_cast<std::size_t>(cls)].data();
          if (lambda_.empty()) {
            run_row<T, true, false>(r, p.nu, off.di, mask, lam, scratch, k);
          } else {
            run_row<T, First, true>(r, p.nu, off.di, mask, lam, scratch, k);
          }
          continue;
        }
        // Springs from column i to i + di exist for i in [max(0, -di), nu - max(0, di)).
        const int lo = std::max(0, -off.di), hi = p.nu - std::max(0, off.di);
        if (hi <= lo) continue;
        const std::size_t a = p.offset + row + static_cast<std::size_t>(lo);
        const std::size_t bb = a + static_cast<std::size_t>(off.dj) * p.nu +
                               static_cast<std::size_t>(static_cast<long>(off.di));
        if (lam) lam += lo;
        if (lambda_.empty()) {
          run_pairs<T, true, false>(view(s, a), view(s, bb), lam, hi - lo, k);
        } else {
          run_pairs<T, First, true>(view(s, a), view(s, bb), lam, hi - lo, k);
        }
      }
    }
  }
}

template <class T>
inline EndView<T> XpbdGrid<T>::view(State<T>& s, std::size_t i) {
  return {disp_.x.data() + i, disp_.y.data() + i, disp_.z.data() + i, s.pos.x.data() + i,
          s.pos.y.data() + i, s.pos.z.data() + i, inv_mass_ + i};
}

template <class T>
inline void XpbdGrid<T>::land(State<T>& s, std::size_t b, std::size_t e) {
  for (int a = 0; a < 3; ++a) {
    T* __restrict x = s.pos.axis(a).data();
    const T* __restrict d = disp_.axis(a).data();
    T* __restrict landed = landed_.axis(a).data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) landed[i] = x[i] = x[i] + d[i];
  }
}

template <class T>
inline void XpbdGrid<T>::finish(const Model<T>& m, State<T>& s, T h, std::size_t b, std::size_t e) {
  if (coarse_.empty()) land(s, b, e);
  if (!tethers_.empty()) tethers_.project(s.pos, m.inv_mass.data(), b, e);
  const T inv_h = T(1) / h;
  for (int a = 0; a < 3; ++a) {
    const T* __restrict x = s.pos.axis(a).data();
    const T* __restrict d = disp_.axis(a).data();
    const T* __restrict landed = landed_.axis(a).data();
    T* __restrict v = s.vel.axis(a).data();
#pragma omp simd
    for (std::size_t i = b; i < e; ++i) v[i] = (d[i] + (x[i] - landed[i])) * inv_h;
  }
}

}  // namespace

template <class T>
bool xpbd_grid_applies(const Model<T>& m) {
  return m.kernel == SpringKernel::row_sweep && !m.grids.empty() &&
         m.grids.size() == m.cloths.size();
}

template <class T>
std::unique_ptr<Integrator<T>> make_xpbd_grid(const Model<T>& m, const SolverSpec& spec) {
  return std::make_unique<XpbdGrid<T>>(m, spec);
}

template <class T>
std::vector<int> xpbd_grid_colours(const Model<T>& grid_model,
                                   const std::vector<std::array<int, 2>>& ends) {
  std::vector<BandedPart<T>> parts;
  int batches = 0;
  for (const GridStencil<T>& g : grid_model.grids) {
    parts.push_back(banded_part(g));
    batches = std::max(batches, 2 * static_cast<int>(parts.back().offsets.size()));
  }
  std::vector<int> colours;
  colours.reserve(ends.size());
  for (const auto& [a, b] : ends) {
    int colour = -1;
    for (const BandedPart<T>& p : parts) {
      if (a < p.offset || a >= p.offset + p.nu * p.nv) continue;
      const int ia = (a - p.offset) % p.nu, ja = (a - p.offset) / p.nu;
      const int ib = (b - p.offset) % p.nu, jb = (b - p.offset) / p.nu;
      for (std::size_t o = 0; o < p.offsets.size(); ++o) {
        const StencilOffset<T>& off = p.offsets[o];
        if (ib - ia != off.di || jb - ja != off.dj) continue;
        const int cls = ((off.dj > 0 ? ja : ia) / off.step()) % 2;
        colour = (p.band_of(ja) % 2) * batches + 2 * static_cast<int>(o) + cls;
      }
    }
    colours.push_back(colour);
  }
  return colours;
}

template bool xpbd_grid_applies<float>(const Model<float>&);
template bool xpbd_grid_applies<double>(const Model<double>&);
CLOTHLAB_INSTANTIATE_FACTORY(make_xpbd_grid)
template std::vector<int> xpbd_grid_colours<float>(const Model<float>&,
                                                   const std::vector<std::array<int, 2>>&);
template std::vector<int> xpbd_grid_colours<double>(const Model<double>&,
                                                    const std::vector<std::array<int, 2>>&);

}  // namespace clothlab
