// The benchmark scene: the default hanging sheet (2 m, 1 kg, 800 N/m, two corners pinned) at any
// square resolution. Damping is the default sheet's (0.05 N*s/m at 32 x 32) scaled with the
// vertex mass, so every grid has the same damping rate c / m; a fixed c would make fine grids
// unstable (dt^2 w^2 + 2 dt gamma < 4, docs/design.md). dt is half the symplectic Euler limit
// 0.654 sqrt(m / k0): the cost of a step does not depend on dt, but the run stays physical.
#pragma once

#include <cmath>

#include "sim/scene/scene.hpp"

namespace clothlab::bench {

inline Scene sheet_scene(int res, int threads, bool full_physics) {
  Scene s;
  ClothSpec c;
  c.size = {2.0, 2.0};
  c.resolution = {res, res};
  c.origin = {-1.0, 2.5, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.mass = 1.0;
  c.pins = {{0, 0}, {res - 1, 0}};
  s.cloths.push_back(c);
  s.springs.stiffness = 800.0;
  s.springs.damping = 0.05 * (32.0 * 32.0) / (res * res);
  if (full_physics) {  // the default scene's drag and gusty wind
    s.forces.drag = 0.001;
    s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
  }
  s.solver.dt = 0.5 * 0.654 * std::sqrt(c.mass / (res * res) / s.springs.stiffness);
  s.solver.threads = threads;
  s.solver.integrator = IntegratorKind::symplectic_euler;
  return s;
}

}  // namespace clothlab::bench
