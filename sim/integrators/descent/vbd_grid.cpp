// Vertex block descent's grid path (vbd_grid.hpp): vbd.cpp's iteration (Chen et al. 2024,
// Algorithm 1, with Chebyshev acceleration) over three sub-rows per grid row.
#include "sim/integrators/descent/vbd_grid.hpp"

#include <array>
#include <cstddef>
#include <cstdlib>
#include <utility>

#include "sim/core/parallel.hpp"
#include "sim/integrators/descent/chebyshev.hpp"
#include "sim/integrators/descent/vbd_common.hpp"

namespace clothlab {
namespace {

// Vertices one vectorised loop takes at once (two AVX vectors of float). A sub-row starts after
// kChunk zeros (the neighbour shifted by -1 of its first vertex is one of them) and ends in
// zeros up to a whole chunk and one more chunk (the neighbour shifted by +1 of its last chunk).
constexpr int kChunk = 16;
constexpr int kColours = 9;

constexpr int round_up(int n, int k) {
  return (n + k - 1) / k * k;
}

template <class T>
struct ColouredPart {
  int offset = 0, nu = 0, nv = 0, stride = 0;
  std::size_t base = 0;                                 // the part's first entry in the planes
  std::vector<typename GridStencil<T>::Entry> springs;  // every entry, both signs
  // valid[((di + 2) * 3 + c) * stride + kChunk + m] = 1 where vertex 3 m + c of a row has a
  // neighbour at column 3 m + c + di (0 past the row's end and in the padding).
  AlignedVector<T> valid;

  // Vertices i = 3 m + c of a row.
  int count(int c) const { return c < nu ? (nu - c + 2) / 3 : 0; }
  std::size_t entry(int j, int c, int m) const {
    return base + (static_cast<std::size_t>(j) * 3 + static_cast<std::size_t>(c)) * stride +
           static_cast<std::size_t>(kChunk + m);
  }
  const T* valid_row(int di, int c) const {
    return valid.data() + static_cast<std::size_t>((di + 2) * 3 + c) * stride + kChunk;
  }
};

template <class T>
ColouredPart<T> coloured_part(const GridStencil<T>& g, std::size_t base) {
  ColouredPart<T> p;
  p.offset = g.offset;
  p.nu = g.nu;
  p.nv = g.nv;
  p.stride = kChunk + round_up(p.count(0), kChunk) + kChunk;
  p.base = base;
  p.springs = g.entries;
  p.valid.assign(static_cast<std::size_t>(15 * p.stride), T(0));
  for (int di = -2; di <= 2; ++di)
    for (int c = 0; c < 3; ++c)
      for (int m = 0; m < p.count(c); ++m) {
        const int i = 3 * m + c + di;
        const std::size_t at = static_cast<std::size_t>(((di + 2) * 3 + c) * p.stride + kChunk + m);
        p.valid[at] = i >= 0 && i < p.nu ? T(1) : T(0);
      }
  return p;
}

// Three planes (x, y, z) of the sub-row layout.
template <class T>
struct Planes {
  std::array<AlignedVector<T>, 3> axis;
  void assign(std::size_t n) {
    for (auto& a : axis) a.assign(n, T(0));
  }
};

template <class T>
class VbdGrid final : public Integrator<T> {
 public:
  VbdGrid(const Model<T>& m, const SolverSpec& spec);

  void step(const System<T>& sys, State<T>& s, double t, T h) override;

  void invalidate() override { warm_ = false; }
  void state_corrected() override {}  // the last velocity still predicts the next acceleration
  SolveStats last_stats() const override { return {iterations_, 0.0, true}; }

 private:
  struct Row {
    int part = 0, j = 0;
  };

  // x_n, the inertial target and the initial guess of row r's vertices (vbd_start()).
  void predict_row(const Model<T>& m, const State<T>& s, Row r, T h, bool warm);

  // One Newton step for each vertex of sub-row c of row r (vbd.cpp's descend()), a chunk at a
  // time: the block's inertia, then its springs offset by offset, then the step.
  void descend_row(Row r, int c, T h);

  // A chunk's blocks (g, H) and its vertices' displacements this step.
  struct Chunk {
    alignas(64) T gx[kChunk], gy[kChunk], gz[kChunk];
    alignas(64) T hxx[kChunk], hxy[kChunk], hxz[kChunk], hyy[kChunk], hyz[kChunk], hzz[kChunk];
    alignas(64) T dx[kChunk], dy[kChunk], dz[kChunk];
    VbdBlock<T> block(int l) const {
      return {gx[l], gy[l], gz[l], hxx[l], hxy[l], hxz[l], hyy[l], hyz[l], hzz[l]};
    }
    void store(int l, const VbdBlock<T>& b) {
      gx[l] = b.gx, gy[l] = b.gy, gz[l] = b.gz;
      hxx[l] = b.hxx, hxy[l] = b.hxy, hxz[l] = b.hxz, hyy[l] = b.hyy, hyz[l] = b.hyz,
      hzz[l] = b.hzz;
    }
  };

  // The inertial term: g = w (x - t), H = w I, with w = m + h drag.
  void begin_chunk(std::size_t self, T h, Chunk& k) const;

  // One offset's springs of a chunk: vertex self + l to vertex other + l, where valid[l] != 0.
  void add_springs(std::size_t self, std::size_t other, const T* __restrict valid, T kh2, T ch,
                   T rest, Chunk& k) const;

  // x -= H^-1 g for the chunk's free vertices.
  void end_chunk(std::size_t self, const Chunk& k);

  // vbd.cpp's accelerate() over row r's three sub-rows: pinned vertices and the padding hold
  // x = x^(k-2), so the extrapolation leaves them.
  void accelerate_row(Row r, T omega, int it);

  // x_(n+1) = x, v_(n+1) = (x - x_n) / h for row r's free vertices; remembers v_n.
  void finish_row(const Model<T>& m, State<T>& s, Row r, T h);

  int iterations_;
  Chebyshev chebyshev_;
  T drag_ = 0;
  bool warm_ = false;
  std::vector<ColouredPart<T>> parts_;
  std::vector<Row> rows_;                               // every row of every part
  std::array<std::vector<Row>, kColours> colour_rows_;  // colour 3 (j % 3) + c: rows j
  Planes<T> x_, start_, target_, older_, previous_;     // sub-row layout (ColouredPart::entry)
  AlignedVector<T> mass_, free_;                        // sub-row layout; free_: 1 or 0
  Vec3Array<T> f_, last_vel_;                           // the model's vertex order
};

template <class T>
inline VbdGrid<T>::VbdGrid(const Model<T>& m, const SolverSpec& spec)
    : iterations_(spec.iterations > 0 ? spec.iterations : kVbdDefaultIterations),
      chebyshev_(chebyshev_of(spec.chebyshev_rho, kVbdChebyshevRho, kVbdChebyshevDelay)),
      drag_(m.drag) {
  std::size_t size = 0;
  for (std::size_t c = 0; c < m.grids.size(); ++c) {
    parts_.push_back(coloured_part(m.grids[c], size));
    const ColouredPart<T>& p = parts_.back();
    size += static_cast<std::size_t>(p.nv) * 3 * static_cast<std::size_t>(p.stride);
    for (int j = 0; j < p.nv; ++j) {
      rows_.push_back({static_cast<int>(c), j});
      for (int ci = 0; ci < 3; ++ci) colour_rows_[3 * (j % 3) + ci].push_back(rows_.back());
    }
  }
  for (Planes<T>* planes : {&x_, &start_, &target_, &older_, &previous_}) planes->assign(size);
  mass_.assign(size, T(0));
  free_.assign(size, T(0));
  for (const ColouredPart<T>& p : parts_)
    for (int j = 0; j < p.nv; ++j)
      for (int i = 0; i < p.nu; ++i) {
        const std::size_t g = static_cast<std::size_t>(p.offset + j * p.nu + i);
        mass_[p.entry(j, i % 3, i / 3)] = m.mass[g];
        free_[p.entry(j, i % 3, i / 3)] = m.inv_mass[g] != T(0) ? T(1) : T(0);
      }
  f_.resize(m.n);
  last_vel_.resize(m.n);
}

template <class T>
inline void VbdGrid<T>::step(const System<T>& sys, State<T>& s, double t, T h) {
  const Model<T>& m = sys.model;
  compute_external_forces(m, t, s.pos, s.vel, f_, sys.workspace, sys.threads);
  const bool warm = warm_;
  const long rows = static_cast<long>(rows_.size());
  run_team(sys.threads, [&] {
#pragma omp for schedule(static)
    for (long r = 0; r < rows; ++r) predict_row(m, s, rows_[static_cast<std::size_t>(r)], h, warm);
    T omega = 1;
    for (int it = 0; it < iterations_; ++it) {
      for (int c = 0; c < kColours; ++c) {
        const std::vector<Row>& items = colour_rows_[static_cast<std::size_t>(c)];
#pragma omp for schedule(static)
        for (long r = 0; r < static_cast<long>(items.size()); ++r)
          descend_row(items[static_cast<std::size_t>(r)], c % 3, h);
      }
      omega = static_cast<T>(chebyshev_weight(chebyshev_, it, double(omega)));
#pragma omp for schedule(static)
      for (long r = 0; r < rows; ++r) accelerate_row(rows_[static_cast<std::size_t>(r)], omega, it);
    }
#pragma omp for schedule(static)
    for (long r = 0; r < rows; ++r) finish_row(m, s, rows_[static_cast<std::size_t>(r)], h);
  });
  warm_ = true;
}

template <class T>
inline void VbdGrid<T>::predict_row(const Model<T>& m, const State<T>& s, Row r, T h, bool warm) {
  const ColouredPart<T>& p = parts_[static_cast<std::size_t>(r.part)];
  for (int i = 0; i < p.nu; ++i) {
    const std::size_t g = static_cast<std::size_t>(p.offset + r.j * p.nu + i);
    const std::size_t q = p.entry(r.j, i % 3, i / 3);
    const VbdStart<T> v = vbd_start(m, g, s, f_, last_vel_, h, warm);
    for (int a = 0; a < 3; ++a) {
      start_.axis[a][q] = v.start[a];
      target_.axis[a][q] = v.target[a];
      x_.axis[a][q] = previous_.axis[a][q] = v.guess[a];
    }
  }
}

template <class T>
inline void VbdGrid<T>::descend_row(Row r, int c, T h) {
  const ColouredPart<T>& p = parts_[static_cast<std::size_t>(r.part)];
  const int count = p.count(c);
  for (int m0 = 0; m0 < count; m0 += kChunk) {
    Chunk k;
    const std::size_t self = p.entry(r.j, c, m0);
    begin_chunk(self, h, k);
    for (const auto& e : p.springs) {
      const int jn = r.j + e.dj;
      if (jn < 0 || jn >= p.nv) continue;
      const int cn = (c + e.di + 3) % 3;      // c + di lies in [-2, 4]
      const int shift = (c + e.di - cn) / 3;  // floor((c + di) / 3): -1, 0 or 1
      add_springs(self, p.entry(jn, cn, m0 + shift), p.valid_row(e.di, c) + m0, h * h * e.stiffness,
                  h * e.damping, e.rest_length, k);
    }
    end_chunk(self, k);
  }
}

template <class T>
inline void VbdGrid<T>::begin_chunk(std::size_t self, T h, Chunk& k) const {
  const T* __restrict x = x_.axis[0].data() + self;
  const T* __restrict y = x_.axis[1].data() + self;
  const T* __restrict z = x_.axis[2].data() + self;
  const T* __restrict tx = target_.axis[0].data() + self;
  const T* __restrict ty = target_.axis[1].data() + self;
  const T* __restrict tz = target_.axis[2].data() + self;
  const T* __restrict sx = start_.axis[0].data() + self;
  const T* __restrict sy = start_.axis[1].data() + self;
  const T* __restrict sz = start_.axis[2].data() + self;
  const T* __restrict mass = mass_.data() + self;
  const T drag_h = h * drag_;
#pragma omp simd
  for (int l = 0; l < kChunk; ++l) {
    const T w = mass[l] + drag_h;
    k.store(l, vbd_inertia(w, x[l] - tx[l], y[l] - ty[l], z[l] - tz[l]));
    k.dx[l] = x[l] - sx[l], k.dy[l] = y[l] - sy[l], k.dz[l] = z[l] - sz[l];
  }
}

template <class T>
inline void VbdGrid<T>::add_springs(std::size_t self, std::size_t other, const T* __restrict valid,
                                    T kh2, T ch, T rest, Chunk& k) const {
  const T* __restrict x = x_.axis[0].data();
  const T* __restrict y = x_.axis[1].data();
  const T* __restrict z = x_.axis[2].data();
  const T* __restrict sx = start_.axis[0].data() + other;
  const T* __restrict sy = start_.axis[1].data() + other;
  const T* __restrict sz = start_.axis[2].data() + other;
#pragma omp simd
  for (int l = 0; l < kChunk; ++l) {
    const std::size_t a = self + static_cast<std::size_t>(l),
                      b = other + static_cast<std::size_t>(l);
    VbdBlock<T> blk = k.block(l);
    const T on = valid[l];
    vbd_add_spring(x[b] - x[a], y[b] - y[a], z[b] - z[a], k.dx[l] - (x[b] - sx[l]),
                   k.dy[l] - (y[b] - sy[l]), k.dz[l] - (z[b] - sz[l]), on * kh2, on * ch, rest,
                   blk);
    k.store(l, blk);
  }
}

template <class T>
inline void VbdGrid<T>::end_chunk(std::size_t self, const Chunk& k) {
  T* __restrict x = x_.axis[0].data() + self;
  T* __restrict y = x_.axis[1].data() + self;
  T* __restrict z = x_.axis[2].data() + self;
  const T* __restrict free = free_.data() + self;
#pragma omp simd
  for (int l = 0; l < kChunk; ++l) {
    T sx, sy, sz;
    vbd_newton_step(k.block(l), sx, sy, sz);  // zero where H is not positive definite
    const bool move = free[l] != T(0);
    x[l] = move ? x[l] - sx : x[l];
    y[l] = move ? y[l] - sy : y[l];
    z[l] = move ? z[l] - sz : z[l];
  }
}

template <class T>
inline void VbdGrid<T>::accelerate_row(Row r, T omega, int it) {
  const ColouredPart<T>& p = parts_[static_cast<std::size_t>(r.part)];
  const std::size_t begin = p.entry(r.j, 0, -kChunk);
  const std::size_t n = 3 * static_cast<std::size_t>(p.stride);
  for (int a = 0; a < 3; ++a) {
    T* __restrict x = x_.axis[a].data() + begin;
    T* __restrict older = older_.axis[a].data() + begin;
    T* __restrict previous = previous_.axis[a].data() + begin;
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i) {
      if (it >= 1) x[i] = omega * (x[i] - older[i]) + older[i];
      older[i] = previous[i];
      previous[i] = x[i];
    }
  }
}

template <class T>
inline void VbdGrid<T>::finish_row(const Model<T>& m, State<T>& s, Row r, T h) {
  const ColouredPart<T>& p = parts_[static_cast<std::size_t>(r.part)];
  const T inv_h = T(1) / h;
  for (int a = 0; a < 3; ++a) {
    T* __restrict pos = s.pos.axis(a).data();
    T* __restrict vel = s.vel.axis(a).data();
    T* __restrict last = last_vel_.axis(a).data();
    const T* __restrict x = x_.axis[a].data();
    const T* __restrict x0 = start_.axis[a].data();
    for (int i = 0; i < p.nu; ++i) {
      const std::size_t g = static_cast<std::size_t>(p.offset + r.j * p.nu + i);
      const std::size_t q = p.entry(r.j, i % 3, i / 3);
      last[g] = vel[g];
      if (m.inv_mass[g] == T(0)) continue;
      vel[g] = (x[q] - x0[q]) * inv_h;
      pos[g] = x[q];
    }
  }
}

}  // namespace

template <class T>
bool vbd_grid_applies(const Model<T>& m) {
  if (m.kernel != SpringKernel::row_sweep || m.grids.empty() || m.grids.size() != m.cloths.size())
    return false;
  for (const GridStencil<T>& g : m.grids)
    for (const auto& e : g.entries)
      if (std::abs(e.di) > 2 || std::abs(e.dj) > 2) return false;
  return true;
}

template <class T>
std::unique_ptr<Integrator<T>> make_vbd_grid(const Model<T>& m, const SolverSpec& spec) {
  return std::make_unique<VbdGrid<T>>(m, spec);
}

template <class T>
std::vector<int> vbd_grid_colours(const Model<T>& grid_model) {
  std::vector<int> colours(grid_model.n, 0);
  for (const GridStencil<T>& g : grid_model.grids)
    for (int j = 0; j < g.nv; ++j)
      for (int i = 0; i < g.nu; ++i)
        colours[static_cast<std::size_t>(g.offset + j * g.nu + i)] = 3 * (j % 3) + i % 3;
  return colours;
}

template bool vbd_grid_applies<float>(const Model<float>&);
template bool vbd_grid_applies<double>(const Model<double>&);
CLOTHLAB_INSTANTIATE_FACTORY(make_vbd_grid)
template std::vector<int> vbd_grid_colours<float>(const Model<float>&);
template std::vector<int> vbd_grid_colours<double>(const Model<double>&);

}  // namespace clothlab
