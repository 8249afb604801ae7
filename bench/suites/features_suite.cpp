// `clothlab bench --suite features`: what each optional part of a step costs, as a ratio to the
// bare step (damped springs + gravity), and the check that parts a scene does not use cost
// nothing measurable (under 2 %): among them colliders far from the cloth (the broad phase).
// Configurations are measured round-robin, several rounds, and each ratio is the median over
// rounds, so a slow spell of the machine hits all of them alike.
#include <cmath>
#include <functional>
#include <ostream>

#include "bench/bench_scenes.hpp"
#include "bench/suites/step_timing.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {

namespace {

struct Variant {
  std::string name;
  std::string kind;  // "used": a part switched on; "unused": present in the scene but inactive
  std::function<void(Scene&)> edit;
  std::function<void(Solver&)> per_step;  // work after every step (field export, energy)
};

constexpr double kUnusedLimit = 0.02;  // the most an unused part may cost

ColliderSpec sphere_at(Vec3d centre, double radius) {
  ColliderSpec c;
  c.kind = ColliderKind::sphere;
  c.center = centre;
  c.radius = radius;
  return c;
}

ColliderSpec floor_plane(double height) {
  ColliderSpec c;
  c.kind = ColliderKind::plane;
  c.point = {0.0, height, 0.0};
  return c;
}

// The bench sheet lying on a floor at the collision thickness, unpinned: every vertex is in
// contact every step (the per-vertex cost of a collider).
void lay_flat_on_floor(Scene& s) {
  ClothSpec& c = s.cloths[0];
  c.v_axis = {0.0, 0.0, 1.0};
  c.origin = {-1.0, 0.005, -1.0};
  c.pins.clear();
  s.colliders = {floor_plane(0.0)};
}

}  // namespace

std::vector<Table> features_suite(const SuiteOptions& o) {
  const int res = o.quick ? 32 : 128;
  const int rounds = o.quick ? 2 : 7;
  const double seconds = o.quick ? 0.03 : 0.25;
  // The window draws at 60 Hz; with the bench scene's step, one frame spans this many steps.
  const Scene bare_scene = sheet_scene(res, o.threads, false);
  const long steps_per_frame = std::max(1L, std::lround(1.0 / 60.0 / bare_scene.solver.dt));
  std::vector<float> buffer(3 * static_cast<std::size_t>(res) * res);
  long counter = 0;
  // What the window does once per displayed frame while something shows fields.
  auto export_fields = [&](Solver& s) {
    s.update_force_field();
    s.copy_normals(buffer.data());
    s.copy_velocities(buffer.data());
  };

  const std::vector<Variant> variants = {
      {"bare step", "reference", [](Scene&) {}, nullptr},
      {"+ drag", "used", [](Scene& s) { s.forces.drag = 0.001; }, nullptr},
      {"+ steady wind", "used",
       [](Scene& s) {
         s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.0, 7, 1.0, 1.0};
       },
       nullptr},
      {"+ gusty wind", "used",
       [](Scene& s) {
         s.forces.wind = {true, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
       },
       nullptr},
      {"+ field export every frame (forces, normals, velocities)", "used", [](Scene&) {},
       [&](Solver& s) {
         if (++counter % steps_per_frame == 0) export_fields(s);
       }},
      {"+ field export every step", "used", [](Scene&) {}, export_fields},
      {"+ energy every step (a trace with energy)", "used", [](Scene&) {},
       [](Solver& s) { (void)s.energy(); }},
      {"wind table present, enabled = false", "unused",
       [](Scene& s) {
         s.forces.wind = {false, {3.0, 0.0, 1.0}, 0.5, 7, 1.0, 1.0};
       },
       nullptr},
      {"wind enabled but calm (velocity 0, gust 0)", "unused",
       [](Scene& s) {
         s.forces.wind = {true, {0.0, 0.0, 0.0}, 0.0, 7, 1.0, 1.0};
       },
       nullptr},
      {"drag = 0 written out", "unused", [](Scene& s) { s.forces.drag = 0.0; }, nullptr},
      {"+ a sphere the sheet hangs against", "used",
       [](Scene& s) {
         s.colliders = {sphere_at({0.0, 1.4, 0.25}, 0.3)};
       },
       nullptr},
      {"sheet lying flat on a floor plane (every vertex in contact)", "used",
       [](Scene& s) { lay_flat_on_floor(s); }, nullptr},
      {"the same flat sheet without the floor (its reference)", "reference",
       [](Scene& s) {
         lay_flat_on_floor(s);
         s.colliders.clear();
         s.forces.gravity = {0.0, 0.0, 0.0};  // it would fall away: no contact, same springs
       },
       nullptr},
      {"floor plane 0.5 m below the sheet (every shipped scene has one)", "unused",
       [](Scene& s) { s.colliders = {floor_plane(0.0)}; }, nullptr},
      {"a sphere 5 m away", "unused",
       [](Scene& s) {
         s.colliders = {sphere_at({5.0, 1.5, 0.0}, 0.3)};
       },
       nullptr},
      {"ten spheres 5 m away", "unused",
       [](Scene& s) {
         for (int k = 0; k < 10; ++k) s.colliders.push_back(sphere_at({5.0, 0.3 * k, 0.0}, 0.1));
       },
       nullptr},
  };

  std::vector<std::vector<double>> ratios(variants.size());
  std::vector<double> bare_ns;
  for (int round = 0; round < rounds; ++round) {
    double bare = NAN;
    for (std::size_t v = 0; v < variants.size(); ++v) {
      Scene scene = bare_scene;
      variants[v].edit(scene);
      auto solver = make_solver(scene);
      counter = 0;
      const double t = variants[v].per_step
                           ? seconds_per_step(*solver, seconds, variants[v].per_step)
                           : seconds_per_step(*solver, seconds);
      if (v == 0) {
        bare = t;
        bare_ns.push_back(1e9 * t);
      }
      ratios[v].push_back(t / bare);
    }
    if (o.log) *o.log << "features: round " << round + 1 << " of " << rounds << " done\n";
  }

  Table table;
  table.title = "Feature costs: " + std::to_string(res) + "x" + std::to_string(res) +
                " bench sheet, symplectic Euler, float, " + std::to_string(o.threads) +
                " thread(s); bare step " + fixed(median(bare_ns) * 1e-3, 1) +
                " us; field export per frame = every " + std::to_string(steps_per_frame) +
                " steps; median of " + std::to_string(rounds) + " rounds";
  table.columns = {"configuration", "kind", "cost / bare step", "extra", "verdict"};
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const double r = median(ratios[v]);
    std::string verdict = "-";
    if (variants[v].kind == "unused")
      verdict = r - 1.0 <= kUnusedLimit ? "ok (< 2 %)" : "FAIL (costs " + pct(r - 1.0) + ")";
    table.add({variants[v].name, variants[v].kind, fixed(r, 3), pct(r - 1.0), verdict});
  }
  // A collider's cost per vertex in contact: the flat sheet on its floor against the same sheet
  // without it.
  auto ratio_of = [&](const std::string& prefix) -> double {
    for (std::size_t v = 0; v < variants.size(); ++v)
      if (variants[v].name.rfind(prefix, 0) == 0) return median(ratios[v]);
    return NAN;
  };
  const double contact_ns = (ratio_of("sheet lying flat") - ratio_of("the same flat sheet")) *
                            median(bare_ns) / (double(res) * res);
  table.add({"collision response per vertex in contact, per collider", "used", "-",
             fixed(contact_ns, 1) + " ns", "-"});
  return {table};
}

}  // namespace clothlab::bench
