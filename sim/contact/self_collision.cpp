#include "sim/contact/self_collision.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/parallel.hpp"
#include "sim/core/vec3_eigen.hpp"

namespace clothlab {
namespace {

using V3 = Eigen::Vector3d;

// A cell coordinate, clamped so that a stray (or non-finite) position still gets a cell and the
// neighbouring cell's coordinate (+1) cannot overflow.
std::int32_t cell_coordinate(double x) {
  constexpr double kLimit = 1 << 30;
  if (!(x > -kLimit)) return -(1 << 30);  // also NaN
  if (!(x < kLimit)) return 1 << 30;
  return static_cast<std::int32_t>(std::floor(x));
}

}  // namespace

// A vertex's own cell and the 13 of its 26 neighbours that come after it (in z, then y, then x):
// the other 13 see this vertex's cell as one of theirs, so each pair of cells is visited once.
template <class T>
const std::array<typename SelfCollision<T>::Cell, 14> SelfCollision<T>::kHalfStencil = {{
    {0, 0, 0},
    {1, 0, 0},
    {-1, 1, 0},
    {0, 1, 0},
    {1, 1, 0},
    {-1, -1, 1},
    {0, -1, 1},
    {1, -1, 1},
    {-1, 0, 1},
    {0, 0, 1},
    {1, 0, 1},
    {-1, 1, 1},
    {0, 1, 1},
    {1, 1, 1},
}};

template <class T>
SelfCollision<T>::SelfCollision(const Model<T>& m, const SolverSpec& spec)
    : thickness_(spec.self_thickness) {
  const std::size_t n = m.n;
  cloth_of_.assign(n, 0);
  for (std::size_t c = 0; c < m.cloths.size(); ++c) {
    const ClothRange& r = m.cloths[c];
    std::fill_n(cloth_of_.begin() + r.offset, std::size_t(r.nu) * std::size_t(r.nv),
                static_cast<std::int32_t>(c));
    if (r.mesh) continue;  // below, from its triangles
    // Half a grid square's diagonal: the widest hole between a layer's vertices.
    const auto at = [&](int i, int j) {
      return load3(m.rest_positions, std::size_t(r.offset + i + j * r.nu));
    };
    const double eu = r.nu > 1 ? (at(1, 0) - at(0, 0)).norm() : 0.0;
    const double ev = r.nv > 1 ? (at(0, 1) - at(0, 0)).norm() : 0.0;
    min_thickness_ = std::max(min_thickness_, 0.5 * std::sqrt(eu * eu + ev * ev));
  }
  // A mesh cloth's widest hole: half the longest side of its largest triangle (on a grid's
  // half-squares that is half the diagonal again).
  for (const auto& t : m.triangles) {
    const ClothRange& r = m.cloths[std::size_t(cloth_of_[std::size_t(t[0])])];
    if (!r.mesh) continue;
    for (int c = 0; c < 3; ++c)
      min_thickness_ =
          std::max(min_thickness_, 0.5 * (load3(m.rest_positions, std::size_t(t[c])) -
                                          load3(m.rest_positions, std::size_t(t[(c + 1) % 3])))
                                             .norm());
  }
  // Every spring-connected pair is skipped: the seed rule joins all pairs closer than its
  // longest spring, so a rest distance up to the longest spring covers them (with a margin for
  // round-off in the rest positions).
  double longest_spring = 0.0;
  const SpringList<T> springs = spring_list(m);
  for (std::size_t k = 0; k < springs.size(); ++k)
    longest_spring = std::max(longest_spring, double(springs.rest_length[k]));
  skip_distance_ = std::max(1.5 * thickness_, longest_spring * (1.0 + 1e-6));

  // Mueller's dense hash: at least two buckets per vertex (a power of two for the mask).
  while ((std::size_t(1) << table_bits_) < 2 * std::max<std::size_t>(n, 1)) ++table_bits_;
  cell_start_.assign((std::size_t(1) << table_bits_) + 1, 0);
  entries_.assign(n, Entry{});
  cell_.assign(n, Cell{});
  bucket_.assign(n, 0);
  block_speed2_.assign(block_count(n), 0.0);
  block_capacity_ = kBlockSize * std::size_t(kPairsPerVertex);
  pairs_.assign(block_count(n) * block_capacity_, Pair{});
  block_pairs_.assign(block_count(n), 0);
  block_dropped_.assign(block_count(n), 0);
}

// Teschner et al. 2003: (x p1 xor y p2 xor z p3) mod table, in unsigned arithmetic; the mod is
// taken as the top bits of a Fibonacci (golden ratio) multiply, which mixes all 32 bits into the
// bucket index (a plain mask would only see the low bits of each coordinate).
template <class T>
std::uint32_t SelfCollision<T>::hash(const Cell& c) const {
  const std::uint32_t h = (std::uint32_t(c.x) * 73856093u) ^ (std::uint32_t(c.y) * 19349663u) ^
                          (std::uint32_t(c.z) * 83492791u);
  return (h * 2654435761u) >> (32 - table_bits_);
}

template <class T>
bool SelfCollision<T>::skipped(std::size_t i, std::size_t j, const Model<T>& m) const {
  if (m.inv_mass[i] == T(0) && m.inv_mass[j] == T(0)) return true;  // neither can move
  if (cloth_of_[i] != cloth_of_[j]) return false;
  const V3 d = load3(m.rest_positions, j) - load3(m.rest_positions, i);
  return d.squaredNorm() < skip_distance_ * skip_distance_;
}

template <class T>
void SelfCollision<T>::find_pairs(const Model<T>& m, const State<T>& s, double dt, int threads) {
  const double radius = query_radius(s, dt, threads);
  stats_ = {};
  stats_.query_radius = radius;
  bucket_vertices(s, 1.0 / radius, threads);
  collect_pairs(m, s, radius, threads);
  for (std::size_t block = 0; block < block_pairs_.size(); ++block) {
    stats_.pairs += block_pairs_[block];
    stats_.dropped += block_dropped_[block];
  }
}

// Two vertices closing at up to 2 vmax meet within the step only if they start closer than
// thickness + 2 vmax dt; the cell is as wide, so every such pair lies in the 27 cells around a
// vertex (visited as the half stencil, each pair of cells once). vmax: the largest speed, per
// block and then over the blocks (a max is exact in any order).
template <class T>
double SelfCollision<T>::query_radius(const State<T>& s, double dt, int threads) {
  for_each_block_indexed(s.vel.size(), threads,
                         [&](std::size_t block, std::size_t b, std::size_t e) {
                           double top = 0.0;
                           for (std::size_t i = b; i < e; ++i)
                             top = std::max(top, load3(s.vel, i).squaredNorm());
                           block_speed2_[block] = top;
                         });
  double speed2 = 0.0;
  for (double v : block_speed2_) speed2 = std::max(speed2, v);
  return thickness_ + 2.0 * std::sqrt(speed2) * dt;
}

// Each vertex's cell and bucket, then a counting sort into buckets, serially in vertex order:
// cell_start_ counts, becomes the end of each bucket by a prefix sum, and walking the vertices
// backwards moves each bucket's end down to its start, leaving every bucket's vertices in
// ascending order.
template <class T>
void SelfCollision<T>::bucket_vertices(const State<T>& s, double inv_cell, int threads) {
  const std::size_t n = s.pos.size();
  for_each_block(n, threads, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const V3 x = load3(s.pos, i) * inv_cell;
      cell_[i] = {cell_coordinate(x.x()), cell_coordinate(x.y()), cell_coordinate(x.z())};
      bucket_[i] = hash(cell_[i]);
    }
  });
  std::fill(cell_start_.begin(), cell_start_.end(), 0);
  for (std::size_t i = 0; i < n; ++i) ++cell_start_[bucket_[i]];
  for (std::size_t h = 1; h < cell_start_.size(); ++h) cell_start_[h] += cell_start_[h - 1];
  for (std::size_t i = n; i-- > 0;)
    entries_[std::size_t(--cell_start_[bucket_[i]])] = {cell_[i], std::int32_t(i), s.pos.x[i],
                                                        s.pos.y[i], s.pos.z[i]};
}

// Each block writes its pairs (in vertex, cell, entry order) into its own slice of the buffer.
template <class T>
void SelfCollision<T>::collect_pairs(const Model<T>& m, const State<T>& s, double radius,
                                     int threads) {
  const double r2 = radius * radius;
  for_each_block_indexed(m.n, threads, [&](std::size_t block, std::size_t b, std::size_t e) {
    Pair* out = pairs_.data() + block * block_capacity_;
    int count = 0, dropped = 0;
    for (std::size_t i = b; i < e; ++i) {
      const V3 xi = load3(s.pos, i);
      const Cell ci = cell_[i];
      for (const Cell& d : kHalfStencil) {
        const Cell c{ci.x + d.x, ci.y + d.y, ci.z + d.z};
        const bool own = d == Cell{};
        const std::uint32_t h = hash(c);
        for (std::int32_t k = cell_start_[h]; k < cell_start_[h + 1]; ++k) {
          const Entry& entry = entries_[std::size_t(k)];
          const auto j = static_cast<std::size_t>(entry.vertex);
          // Only from j's own cell (other cells that share the bucket would report it again),
          // and in i's own cell each pair once (j > i).
          if (!(entry.cell == c) || (own && j <= i)) continue;
          const V3 xj(double(entry.x), double(entry.y), double(entry.z));
          if ((xj - xi).squaredNorm() >= r2 || skipped(i, j, m)) continue;
          if (count < int(block_capacity_))
            out[count++] = {std::int32_t(std::min(i, j)), std::int32_t(std::max(i, j))};
          else
            ++dropped;
        }
      }
    }
    block_pairs_[block] = count;
    block_dropped_[block] = dropped;
  });
}

template <class T>
bool SelfCollision<T>::respond(const Model<T>& m, State<T>& s, double h) {
  stats_.contacts = 0;
  stats_.max_depth = 0.0;
  const double th = thickness_;
  int contacts = 0;
  double depth = 0.0;
  // Serially, in the pair list's order (Gauss-Seidel: a pair sees its neighbours' corrections).
  for_each_pair([&](const Pair& p) {
    const auto i = static_cast<std::size_t>(p.a), j = static_cast<std::size_t>(p.b);
    const double wi = double(m.inv_mass[i]), wj = double(m.inv_mass[j]), w = wi + wj;
    if (w == 0.0) return;
    V3 xi = load3(s.pos, i), xj = load3(s.pos, j);
    const V3 d = xj - xi;
    const double dist2 = d.squaredNorm();
    const V3 vi0 = load3(s.vel, i), vj0 = load3(s.vel, j);
    const V3 rel = vj0 - vi0;
    // Most pairs are apart and not closing: nothing to do (and no square root).
    if (dist2 >= th * th && rel.dot(d) >= 0.0) return;
    const double dist = std::sqrt(dist2);
    // Two vertices on the same spot: any fixed direction parts them.
    const V3 n = dist > 1e-12 ? V3(d / dist) : V3::UnitY();
    const double vn = rel.dot(n);
    const double gap = dist - th;
    // The relative normal velocity may close the gap beyond the thickness within one substep,
    // no more (inelastic; a pair already inside may not close further).
    const double vn_min = -std::max(0.0, gap) / h;
    bool changed = false;
    if (vn < vn_min) {
      const double dvn = vn_min - vn;
      V3 vt = rel - vn * n;
      const double speed = vt.norm();
      // Coulomb: the friction cone of the impulse holds the relative tangential velocity, or
      // takes kFriction dvn from it.
      if (speed <= kFriction * dvn)
        vt.setZero();
      else
        vt *= 1.0 - kFriction * dvn / speed;
      const V3 dv = (vt + vn_min * n) - rel;  // the change of the relative velocity
      store3(s.vel, i, V3(vi0 - (wi / w) * dv));
      store3(s.vel, j, V3(vj0 + (wj / w) * dv));
      changed = true;
    }
    if (gap < 0.0) {
      // Pushed apart to the thickness, by inverse mass; the velocities stay.
      xi -= (wi / w) * (-gap) * n;
      xj += (wj / w) * (-gap) * n;
      store3(s.pos, i, xi);
      store3(s.pos, j, xj);
      depth = std::max(depth, -gap);
      changed = true;
    }
    if (changed) ++contacts;
  });
  stats_.contacts = contacts;
  stats_.max_depth = depth;
  return contacts > 0;
}

template class SelfCollision<float>;
template class SelfCollision<double>;

}  // namespace clothlab
