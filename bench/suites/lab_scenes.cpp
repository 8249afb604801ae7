#include "bench/suites/lab_scenes.hpp"

#include "sim/scene/parameter_keys.hpp"

namespace clothlab::bench {

namespace {

Scene with_solver(Scene s, IntegratorKind integrator, double dt) {
  s.solver.integrator = integrator;
  s.solver.dt = dt;
  s.solver.threads = 1;
  s.solver.precision = Precision::f64;
  s.forces.gravity = {0.0, -9.81, 0.0};
  return s;
}

}  // namespace

Scene hanging_sheet(const SheetParams& p, IntegratorKind integrator, double dt) {
  Scene s;
  ClothSpec c;
  c.size = {p.size, p.size};
  c.resolution = {p.resolution, p.resolution};
  c.origin = {-0.5 * p.size, 0.0, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, 0.0, 1.0};
  c.mass = p.mass;
  c.pins = {{0, 0}, {p.resolution - 1, 0}};
  c.key = key_of<&Scene::cloths>();
  s.cloths.push_back(c);
  s.springs.stiffness = p.stiffness;
  s.springs.damping = p.damping;
  return with_solver(s, integrator, dt);
}

Scene steady_flag(IntegratorKind integrator, double dt) {
  Scene s;
  ClothSpec c;
  c.size = {1.5, 1.0};
  c.resolution = {24, 16};
  c.origin = {0.0, 2.0, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.mass = 0.2;
  for (int j = 0; j < 16; ++j) c.pins.push_back({0, j});
  c.key = key_of<&Scene::cloths>();
  s.cloths.push_back(c);
  s.springs.stiffness = 1000.0;
  s.springs.damping = 0.05;
  s.forces.wind.enabled = true;
  s.forces.wind.velocity = {6.0, 0.0, 3.0};
  s.forces.wind.gust = 0.0;
  return with_solver(s, integrator, dt);
}

Scene single_spring(IntegratorKind integrator, double dt) {
  Scene s;
  ClothSpec c;
  c.size = {1.0, 0.5};
  c.resolution = {1, 2};
  c.origin = {0.0, 0.0, 0.0};
  c.u_axis = {1.0, 0.0, 0.0};
  c.v_axis = {0.0, -1.0, 0.0};
  c.mass = 0.2;
  c.pins = {{0, 0}};
  c.key = key_of<&Scene::cloths>();
  s.cloths.push_back(c);
  s.springs.stiffness = 100.0;
  s.springs.damping = 0.0;
  return with_solver(s, integrator, dt);
}

}  // namespace clothlab::bench
