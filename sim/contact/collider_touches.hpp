// Which vertices the colliders held at the end of the last substep, and along which normal
// (docs/contact.md section 7, "Pushes against the colliders"). The colliders' response
// (sim/contact/contact_response.hpp) writes it; triangle contact's pushes, which run after it at
// a pass's end, read it so that they do not drive a vertex resting on a collider into it.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace clothlab {

// Cloth thicknesses beyond a collider's shell within which the response holds a vertex it left
// alone (ContactResponse's hold_reach): a push moves a vertex by at most a pair's depth, under a
// thickness, but a vertex takes pushes from the pairs on both its sides. With one thickness the
// landed pile's closest layers came 0.84 of it apart; with none (only the vertices the response
// corrected) its layer on the floor moved at 0.5 m/s at rest, pushed in and put back each pass.
inline constexpr double kHoldReach = 2.0;

struct ColliderTouches {
  std::vector<std::uint64_t> stamp;          // per vertex: the response that last held it
  std::vector<std::array<float, 3>> normal;  // per vertex: the collider's outward normal then
  std::uint64_t now = 0;                     // the last response's stamp (0: none yet)

  void resize(std::size_t n) {
    stamp.assign(n, 0);
    normal.assign(n, {0.0f, 0.0f, 0.0f});
  }
  // The last response held vertex i against a collider with outward normal `n`.
  void hold(std::size_t i, const Eigen::Vector3d& n) {
    stamp[i] = now;
    normal[i] = {float(n.x()), float(n.y()), float(n.z())};
  }
  bool held(std::size_t i) const { return now != 0 && stamp[i] == now; }
  Eigen::Vector3d normal_of(std::size_t i) const {
    return {double(normal[i][0]), double(normal[i][1]), double(normal[i][2])};
  }
};

// A pair's push moves vertex k by w_k inv_k c (c = (depth n + friction) / W, W = sum w_k^2
// inv_k, Mueller et al. 2007 eq. 2). A vertex the colliders hold, whose move would point into
// its collider (more than half of it along -normal), is as heavy as the collider there: its
// inverse mass becomes 0 and the other vertices take the whole push, as a contact solved
// together with the collider's would give. Returns the new W; when less than a quarter of W is
// left (the pair's free side weighs almost nothing in it), the pushes would grow past four times
// their size, and the inverse masses and W stay as they were.
inline double hold_against_colliders(const ColliderTouches& touches,
                                     const std::array<std::int32_t, 4>& v,
                                     const std::array<double, 4>& w, const Eigen::Vector3d& c,
                                     std::array<double, 4>& inv, double W) {
  std::array<double, 4> held = inv;
  double left = W;
  const double length = c.norm();
  for (std::size_t k = 0; k < 4; ++k) {
    const auto i = std::size_t(v[k]);
    if (held[k] == 0.0 || w[k] == 0.0 || !touches.held(i)) continue;
    const double into = -w[k] * c.dot(touches.normal_of(i));  // along -normal, per unit inv
    if (into <= 0.5 * std::abs(w[k]) * length) continue;
    left -= w[k] * w[k] * held[k];
    held[k] = 0.0;
  }
  if (left == W || !(left >= 0.25 * W)) return W;
  inv = held;
  return left;
}

}  // namespace clothlab
