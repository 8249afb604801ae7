#include "sim/contact/kinematic_pins.hpp"

#include <cmath>

namespace clothlab {

template <class T>
KinematicPins<T>::KinematicPins(const Scene& scene, const Model<T>& m) {
  for (const ColliderSpec& spec : scene.colliders) colliders_.push_back(pose_only_collider(spec));
  std::vector<ColliderPose> start;  // each collider's pose at t = 0
  for (const Collider& c : colliders_) start.push_back(c.pose(0.0));
  for (std::size_t c = 0; c < scene.cloths.size() && c < m.cloths.size(); ++c) {
    const ClothSpec& cloth = scene.cloths[c];
    const ClothRange& r = m.cloths[c];
    for (const auto& pin : cloth.pins) {
      const int v = r.offset + pin[0] + pin[1] * r.nu;
      const auto i = static_cast<std::size_t>(v);
      const Eigen::Vector3d x(double(m.rest_positions.x[i]), double(m.rest_positions.y[i]),
                              double(m.rest_positions.z[i]));
      // The listed collider whose centre is nearest (the first of equals).
      int collider = -1;
      double nearest = INFINITY;
      for (const int k : cloth.pins_follow) {
        const double d = (start[std::size_t(k)].centre - x).norm();
        if (d < nearest) nearest = d, collider = k;
      }
      if (collider < 0) continue;
      pins_.push_back({v, collider, start[std::size_t(collider)].to_local(x)});
    }
  }
}

template <class T>
void KinematicPins<T>::drive(const Model<T>& m, State<T>& s, double t, double h) const {
  for (const Pin& p : pins_) {
    const auto i = static_cast<std::size_t>(p.vertex);
    if (m.inv_mass[i] != T(0)) continue;  // let go (a drop)
    const Eigen::Vector3d to = colliders_[std::size_t(p.collider)].pose(t + h).to_world(p.local);
    for (int a = 0; a < 3; ++a)
      s.vel.axis(a)[i] = static_cast<T>((to[a] - double(s.pos.axis(a)[i])) / h);
  }
}

template <class T>
void KinematicPins<T>::place(const Model<T>& m, State<T>& s, double t) const {
  for (const Pin& p : pins_) {
    const auto i = static_cast<std::size_t>(p.vertex);
    if (m.inv_mass[i] != T(0)) continue;
    const ColliderPose pose = colliders_[std::size_t(p.collider)].pose(t);
    const Eigen::Vector3d x = pose.to_world(p.local), v = pose.surface_velocity(x);
    for (int a = 0; a < 3; ++a) {
      s.pos.axis(a)[i] = static_cast<T>(x[a]);
      s.vel.axis(a)[i] = static_cast<T>(v[a]);
    }
  }
}

template class KinematicPins<float>;
template class KinematicPins<double>;

}  // namespace clothlab
