// The total force on every vertex: springs, gravity, linear drag and wind.
#pragma once

#include "sim/model/model.hpp"

namespace clothlab {

// Scratch space for a force evaluation, allocated once so the step loop never allocates.
template <class T>
struct ForceWorkspace {
  Vec3Array<T> face_cross;  // (b - a) x (c - a) per triangle: twice the area times the normal
  void resize(const Model<T>& m) { face_cross.resize(m.triangles.size()); }
};

// f = F(t, x, v) on all vertices (pinned ones included: their force is the support reaction).
template <class T>
void compute_forces(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                    Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads);

// The wind velocity at time t at position p (design: sim/forces/wind.hpp).
Vec3d wind_velocity(const WindSpec& wind, double t, const Vec3d& p);

}  // namespace clothlab
