#include "sim/divergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/core/parallel.hpp"

namespace clothlab {

VertexRef vertex_ref_of(const std::vector<ClothRange>& cloths, int index) {
  for (std::size_t c = cloths.size(); c-- > 0;) {
    if (index >= cloths[c].offset) {
      const int local = index - cloths[c].offset;
      return {static_cast<int>(c), local % cloths[c].nu, local / cloths[c].nu};
    }
  }
  return {};
}

namespace {

// The spring holding the most elastic energy, 1/2 k (l - L)^2, and the vertex at its first end.
struct MostStretched {
  double energy = -1.0;
  VertexRef vertex;
};
template <class T>
MostStretched most_stretched(const Model<T>& m, const State<T>& s) {
  const SpringList<T> springs = spring_list(m);
  MostStretched out;
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const auto [a, b] = springs.ends[k];
    double l2 = 0.0;
    for (int d = 0; d < 3; ++d) {
      const double x = double(s.pos.axis(d)[b]) - double(s.pos.axis(d)[a]);
      l2 += x * x;
    }
    const double stretch = std::sqrt(l2) - double(springs.rest_length[k]);
    const double energy = 0.5 * double(springs.stiffness[k]) * stretch * stretch;
    if (energy > out.energy) out = {energy, vertex_ref_of(m.cloths, springs.ends[k][0])};
  }
  return out;
}

}  // namespace

std::string Divergence::message() const {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "simulation diverged at step %ld (t = %.6g s): vertex (cloth %d, i %d, j %d), %s",
                step, time, vertex.cloth, vertex.i, vertex.j, quantity.c_str());
  return buf;
}

template <class T>
DivergenceMonitor<T>::DivergenceMonitor(const Model<T>& m, const State<T>& s,
                                        double initial_energy) {
  // Energy scale: initial mechanical energy, the potential energy gravity can release over the
  // cloth's extent plus its free-fall allowance, and the kinetic energy of cloth moving at the
  // wind's peak speed.
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  double total_mass = 0.0;
  for (std::size_t i = 0; i < m.n; ++i) {
    total_mass += m.mass[i];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(s.pos.axis(a)[i]));
      hi[a] = std::max(hi[a], double(s.pos.axis(a)[i]));
    }
  }
  const double extent = std::max(
      1.0, std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                     (hi[2] - lo[2]) * (hi[2] - lo[2])));
  const double g =
      std::sqrt(double(m.gravity[0]) * m.gravity[0] + double(m.gravity[1]) * m.gravity[1] +
                double(m.gravity[2]) * m.gravity[2]);
  const auto& w = m.wind.velocity;
  const double wind_speed =
      m.wind.enabled ? std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * (1.0 + m.wind.gust)
                     : 0.0;
  scale_ = std::abs(initial_energy) + total_mass * g * 10.0 * extent +
           0.5 * total_mass * wind_speed * wind_speed + 1e-9;
}

template <class T>
bool DivergenceMonitor<T>::check(const Model<T>& m, const State<T>& s, long step, double time,
                                 int threads, Divergence& out) {
  const std::size_t blocks = block_count(m.n);
  partials_.resize(2 * blocks);
  for_each_block_indexed(m.n, threads, [&](std::size_t blk, std::size_t b, std::size_t e) {
    // A vector reduction (one chain of dependent double additions was a tenth of a 256^2 step):
    // its order is fixed by the build and the block, not by the thread count, and these sums
    // only decide finite and bounded.
    // Raw pointers: through the vectors' operator[] GCC kept the float instance scalar.
    const T *px = s.pos.x.data(), *py = s.pos.y.data(), *pz = s.pos.z.data();
    const T *vx = s.vel.x.data(), *vy = s.vel.y.data(), *vz = s.vel.z.data();
    const T* mass = m.mass.data();
    double coords = 0.0, kinetic = 0.0;
#pragma omp simd reduction(+ : coords, kinetic)
    for (std::size_t i = b; i < e; ++i) {
      const double x = px[i], y = py[i], z = pz[i], u = vx[i], v = vy[i], w = vz[i];
      coords += x + y + z;
      kinetic += double(mass[i]) * (u * u + v * v + w * w);
    }
    partials_[2 * blk] = coords;
    partials_[2 * blk + 1] = 0.5 * kinetic;
  });
  double coords = 0.0, kinetic = 0.0;
  for (std::size_t blk = 0; blk < blocks; ++blk) {
    coords += partials_[2 * blk];
    kinetic += partials_[2 * blk + 1];
  }
  const double limit = kLimitFactor * scale_;
  if (std::isfinite(coords) && std::isfinite(kinetic) && kinetic <= limit) return false;

  // Slow path: find the culprit.
  out.step = step;
  out.time = time;
  static const char* const kNames[2][3] = {{"position.x", "position.y", "position.z"},
                                           {"velocity.x", "velocity.y", "velocity.z"}};
  for (std::size_t i = 0; i < m.n; ++i) {
    for (int q = 0; q < 2; ++q) {
      const Vec3Array<T>& arr = q == 0 ? s.pos : s.vel;
      for (int a = 0; a < 3; ++a) {
        const double value = arr.axis(a)[i];
        if (std::isfinite(value)) continue;
        out.vertex = vertex_ref_of(m.cloths, static_cast<int>(i));
        out.quantity =
            std::string(kNames[q][a]) + " is " + (std::isnan(value) ? "nan" : "infinite");
        return true;
      }
    }
  }
  std::size_t fastest = 0;
  double best = -1.0;
  for (std::size_t i = 0; i < m.n; ++i) {
    const double speed2 = double(s.vel.x[i]) * s.vel.x[i] + double(s.vel.y[i]) * s.vel.y[i] +
                          double(s.vel.z[i]) * s.vel.z[i];
    if (speed2 > best) best = speed2, fastest = i;
  }
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "kinetic energy %.3g J exceeds %.0f x the scene's energy scale (%.3g J); this "
                "vertex is the fastest at %.3g m/s",
                kinetic, kLimitFactor, scale_, std::sqrt(best));
  out.vertex = vertex_ref_of(m.cloths, static_cast<int>(fastest));
  out.quantity = buf;
  return true;
}

template <class T>
bool DivergenceMonitor<T>::check_energy(const Model<T>& m, const State<T>& s, const Energy& e,
                                        long step, double time, Divergence& out) const {
  const double limit = kLimitFactor * scale_;
  if (std::abs(e.total()) <= limit && e.elastic <= limit) return false;
  const MostStretched most = most_stretched(m, s);
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "%s energy %.3g J (elastic %.3g J) exceeds %.0f x the scene's energy scale "
                "(%.3g J); a spring at this vertex holds %.3g J",
                std::abs(e.total()) > limit ? "total" : "elastic", e.total(), e.elastic,
                kLimitFactor, scale_, std::max(most.energy, 0.0));
  out.step = step;
  out.time = time;
  out.vertex = most.vertex;
  out.quantity = buf;
  return true;
}

template <class T>
void DivergenceMonitor<T>::stuck(const Model<T>& m, const State<T>& s, long step, double time,
                                 const std::string& why, Divergence& out) const {
  out.step = step;
  out.time = time;
  out.vertex = most_stretched(m, s).vertex;
  out.quantity = why;
}

template class DivergenceMonitor<float>;
template class DivergenceMonitor<double>;

}  // namespace clothlab
