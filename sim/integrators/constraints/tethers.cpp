#include "sim/integrators/constraints/tethers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace clothlab {

template <class T>
double static_strain(const Model<T>& m, std::size_t c) {
  if (c >= m.grids.size()) return std::numeric_limits<double>::infinity();
  const ClothRange& r = m.cloths[c];
  double mass = 0.0;
  for (int v = r.offset; v < r.offset + r.nu * r.nv; ++v)
    mass += m.mass[static_cast<std::size_t>(v)];
  const double g = std::hypot(double(m.gravity[0]), double(m.gravity[1]), double(m.gravity[2]));
  double spring = std::numeric_limits<double>::infinity();  // the weakest structural k L
  bool any = false;
  for (const auto& e : m.grids[c].entries) {
    if (!e.first_half || !((e.di == 1 && e.dj == 0) || (e.di == 0 && e.dj == 1))) continue;
    spring = std::min(spring, double(e.stiffness) * double(e.rest_length));
    any = true;
  }
  if (!any || !(spring > 0.0)) return std::numeric_limits<double>::infinity();
  return mass * g / double(std::max(1, std::min(r.nu, r.nv))) / spring;
}

template <class T>
ClothSlack cloth_slack(const Model<T>& m, std::size_t c) {
  return {static_strain(m, c), std::max(m.cloths[c].nu, m.cloths[c].nv)};
}

template <class T>
double rest_distance(const Model<T>& m, std::size_t i, std::size_t j) {
  double s = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double d = double(m.rest_positions.axis(a)[i]) - double(m.rest_positions.axis(a)[j]);
    s += d * d;
  }
  return std::sqrt(s);
}

template <class T>
bool stretch_limited(const Model<T>& m, std::size_t c) {
  const ClothRange& r = m.cloths[c];
  return !r.mesh && !r.wrap_u && static_strain(m, c) < kTetherMaxStrain;
}

template <class T>
Tethers<T>::Tethers(const Model<T>& m) : n_(m.n) {
  // The pins of each flat grid cloth stiff enough for tethers (tubes and meshes have a curved or
  // no rest layout, where the straight rest distance is not the geodesic one), as indices into
  // pins_ (the model's pins).
  std::vector<std::vector<std::int32_t>> cloth_pins(m.cloths.size());
  for (std::size_t c = 0; c < m.cloths.size(); ++c) {
    const ClothRange& r = m.cloths[c];
    if (!stretch_limited(m, c)) continue;
    for (std::size_t k = 0; k < m.pinned.size(); ++k)
      if (m.pinned[k] >= r.offset && m.pinned[k] < r.offset + r.nu * r.nv)
        cloth_pins[c].push_back(static_cast<std::int32_t>(k));
  }
  for (const auto& pins : cloth_pins)
    slots_ = std::max(slots_, std::min<int>(kTetherSlots, static_cast<int>(pins.size())));
  if (slots_ == 0) return;
  pins_ = m.pinned;
  pin_pos_.resize(pins_.size());
  pin_held_.assign(pins_.size(), T(0));
  pin_.assign(static_cast<std::size_t>(slots_) * n_, 0);
  rest_.assign(static_cast<std::size_t>(slots_) * n_, std::numeric_limits<T>::max());
  std::vector<std::pair<double, std::int32_t>> nearest;
  for (std::size_t c = 0; c < m.cloths.size(); ++c) {
    const ClothRange& r = m.cloths[c];
    if (cloth_pins[c].empty()) continue;
    Span span;
    span.begin = static_cast<std::size_t>(r.offset);
    span.end = span.begin + static_cast<std::size_t>(r.nu) * static_cast<std::size_t>(r.nv);
    span.slack = cloth_slack(m, c);
    span.shared = cloth_pins[c].size() <= static_cast<std::size_t>(kTetherSlots);
    span.slots = std::min<int>(kTetherSlots, static_cast<int>(cloth_pins[c].size()));
    for (int s = 0; s < span.slots && span.shared; ++s) span.pin[s] = cloth_pins[c][s];
    for (std::size_t i = span.begin; i < span.end; ++i) {
      nearest.clear();
      for (std::int32_t k : cloth_pins[c])
        nearest.push_back({rest_distance(m, i, static_cast<std::size_t>(pins_[k])), k});
      // Shared: slot s is pin s; else the nearest pins first.
      if (!span.shared)
        std::partial_sort(nearest.begin(), nearest.begin() + span.slots, nearest.end());
      for (int s = 0; s < span.slots; ++s) {
        const std::size_t slot = static_cast<std::size_t>(s) * n_ + i;
        pin_[slot] = nearest[static_cast<std::size_t>(s)].second;
        rest_[slot] = static_cast<T>(nearest[static_cast<std::size_t>(s)].first);
      }
    }
    spans_.push_back(span);
  }
}

template <class T>
void Tethers<T>::gather_pins(const Vec3Array<T>& x, const T* inv_mass) {
  for (std::size_t k = 0; k < pins_.size(); ++k) {
    const auto p = static_cast<std::size_t>(pins_[k]);
    for (int a = 0; a < 3; ++a) pin_pos_.axis(a)[k] = x.axis(a)[p];
    pin_held_[k] = inv_mass[p] == T(0) ? T(1) : T(0);
  }
}

template <class T>
void Tethers<T>::set_substep(double h) {
  for (Span& span : spans_) span.scale = static_cast<T>(span.slack.scale(h));
}

template <class T>
void Tethers<T>::project(Vec3Array<T>& x, const T* inv_mass, std::size_t b, std::size_t e) const {
  for (const Span& span : spans_) {
    const std::size_t lo = std::max(b, span.begin), hi = std::min(e, span.end);
    if (lo >= hi) continue;
    for (int s = 0; s < span.slots; ++s) project_slot(x, inv_mass, span, s, lo, hi);
  }
}

// Vertex i's pin position comes from one broadcast (shared) or a gather through pin_.
template <class T>
void Tethers<T>::project_slot(Vec3Array<T>& x, const T* inv_mass, const Span& span, int s,
                              std::size_t lo, std::size_t hi) const {
  T* __restrict px = x.x.data();
  T* __restrict py = x.y.data();
  T* __restrict pz = x.z.data();
  const T* __restrict rest = rest_.data() + static_cast<std::size_t>(s) * n_;
  const T scale = span.scale;
  // The tether pulls vertex i back onto the sphere of its rest distance (times the slack's scale)
  // around the pin; selects, so a vertex it does not hold keeps its bits.
  const auto pull = [&](std::size_t i, T ax, T ay, T az, bool live) {
    const T dx = px[i] - ax, dy = py[i] - ay, dz = pz[i] - az;
    const T d = std::sqrt(dx * dx + dy * dy + dz * dz);
    const T limit = rest[i] * scale;
    const bool held = live && d > limit && inv_mass[i] > T(0);
    const T f = held ? limit / d : T(1);
    px[i] = held ? ax + dx * f : px[i];
    py[i] = held ? ay + dy * f : py[i];
    pz[i] = held ? az + dz * f : pz[i];
  };
  if (span.shared) {
    const auto k = static_cast<std::size_t>(span.pin[s]);
    const T ax = pin_pos_.x[k], ay = pin_pos_.y[k], az = pin_pos_.z[k];
    const bool live = pin_held_[k] != T(0);
#pragma omp simd
    for (std::size_t i = lo; i < hi; ++i) pull(i, ax, ay, az, live);
    return;
  }
  const std::int32_t* __restrict pin = pin_.data() + static_cast<std::size_t>(s) * n_;
  const T* __restrict qx = pin_pos_.x.data();
  const T* __restrict qy = pin_pos_.y.data();
  const T* __restrict qz = pin_pos_.z.data();
  const T* __restrict held = pin_held_.data();
#pragma omp simd
  for (std::size_t i = lo; i < hi; ++i)
    pull(i, qx[pin[i]], qy[pin[i]], qz[pin[i]], held[pin[i]] != T(0));
}

template double static_strain<float>(const Model<float>&, std::size_t);
template double static_strain<double>(const Model<double>&, std::size_t);
template ClothSlack cloth_slack<float>(const Model<float>&, std::size_t);
template ClothSlack cloth_slack<double>(const Model<double>&, std::size_t);
template double rest_distance<float>(const Model<float>&, std::size_t, std::size_t);
template double rest_distance<double>(const Model<double>&, std::size_t, std::size_t);
template bool stretch_limited<float>(const Model<float>&, std::size_t);
template bool stretch_limited<double>(const Model<double>&, std::size_t);
template class Tethers<float>;
template class Tethers<double>;

}  // namespace clothlab
