// Pins that move with a collider (ClothSpec::pins_follow: a skirt's waistband on a turning body,
// docs/contact.md section 3): each such pinned vertex keeps its place in the collider's frame, x =
// pose(t) * x_local, with the collider's surface velocity. The integrators move a pinned vertex
// by h v and nothing else (XPBD and local/global hold it still), so drive() gives it the velocity
// that carries it to its place at the end of the substep, and place() puts it exactly there.
#pragma once

#include <vector>

#include "sim/contact/collider.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T>
class KinematicPins {
 public:
  KinematicPins(const Scene& scene, const Model<T>& m);

  bool empty() const { return pins_.empty(); }
  // Before the substep from t to t + h.
  void drive(const Model<T>& m, State<T>& s, double t, double h) const;
  // After it, at time t (its end).
  void place(const Model<T>& m, State<T>& s, double t) const;

 private:
  struct Pin {
    int vertex = 0;
    int collider = 0;
    Eigen::Vector3d local = Eigen::Vector3d::Zero();  // in the collider's frame at t = 0
  };
  std::vector<Collider> colliders_;
  std::vector<Pin> pins_;
};

extern template class KinematicPins<float>;
extern template class KinematicPins<double>;

}  // namespace clothlab
