// `clothlab bench --suite features`: what each optional part of a step costs, as a ratio to the
// bare step (damped springs + gravity), and the check that parts a scene does not use cost
// nothing measurable (under 2 %): among them colliders far from the cloth (the broad phase).
// Configurations are measured round-robin, several rounds, and each ratio is the median over
// rounds, so a slow spell of the machine hits all of them alike.
#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "bench/bench_scenes.hpp"
#include "bench/suites/step_timing.hpp"
#include "bench/suites/suites.hpp"
#include "sim/solver.hpp"

namespace clothlab::bench {

namespace {

struct FeatureVariant {
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

// What the window does once per displayed frame while something shows fields: every
// `steps_per_frame` steps (per_frame) or every step.
struct FieldExport {
  long steps_per_frame = 1;
  long counter = 0;
  std::vector<float> buffer;
  void operator()(Solver& s) {
    s.update_force_field();
    s.copy_normals(buffer.data());
    s.copy_velocities(buffer.data());
  }
  void per_frame(Solver& s) {
    if (++counter % steps_per_frame == 0) (*this)(s);
  }
};

ColliderSpec far_sphere(int k) {
  return sphere_at({5.0, 0.3 * k, 0.0}, 0.1);
}

// The parts a scene may use ("used"), the references they are measured against, and parts that
// are present but inactive ("unused", which must cost nothing).
std::vector<FeatureVariant> feature_variants(FieldExport& fields) {
  auto none = [](Scene&) {};
  auto wind = [](bool enabled, Vec3d velocity, double gust) {
    return [=](Scene& s) { s.forces.wind = {enabled, velocity, gust, 7, 1.0, 1.0}; };
  };
  return {
      {"bare step", "reference", none, nullptr},
      {"+ drag", "used", [](Scene& s) { s.forces.drag = 0.001; }, nullptr},
      {"+ steady wind", "used", wind(true, {3.0, 0.0, 1.0}, 0.0), nullptr},
      {"+ gusty wind", "used", wind(true, {3.0, 0.0, 1.0}, 0.5), nullptr},
      {"+ field export every frame (forces, normals, velocities)", "used", none,
       [&fields](Solver& s) { fields.per_frame(s); }},
      {"+ field export every step", "used", none, [&fields](Solver& s) { fields(s); }},
      {"+ energy every step (a trace with energy)", "used", none,
       [](Solver& s) { (void)s.energy(); }},
      {"wind table present, enabled = false", "unused", wind(false, {3.0, 0.0, 1.0}, 0.5), nullptr},
      {"wind enabled but calm (velocity 0, gust 0)", "unused", wind(true, {0.0, 0.0, 0.0}, 0.0),
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
         for (int k = 0; k < 10; ++k) s.colliders.push_back(far_sphere(k));
       },
       nullptr},
  };
}

// Per variant, its cost over the bare step's in each round (round-robin); the bare step's ns.
struct RoundResults {
  std::vector<std::vector<double>> ratios;
  std::vector<double> bare_ns;
};

RoundResults measure_rounds(const std::vector<FeatureVariant>& variants, const Scene& bare_scene,
                            FieldExport& fields, int rounds, double seconds, std::ostream* log) {
  RoundResults out;
  out.ratios.resize(variants.size());
  for (int round = 0; round < rounds; ++round) {
    double bare = NAN;
    for (std::size_t v = 0; v < variants.size(); ++v) {
      Scene scene = bare_scene;
      variants[v].edit(scene);
      auto solver = make_solver(scene);
      fields.counter = 0;
      const double t = variants[v].per_step
                           ? seconds_per_step(*solver, seconds, variants[v].per_step)
                           : seconds_per_step(*solver, seconds);
      if (v == 0) {
        bare = t;
        out.bare_ns.push_back(1e9 * t);
      }
      out.ratios[v].push_back(t / bare);
    }
    if (log) *log << "features: round " << round + 1 << " of " << rounds << " done\n";
  }
  return out;
}

// The table's rows, and a collider's cost per vertex in contact: the flat sheet on its floor
// against the same sheet without it.
void add_feature_rows(Table& table, const std::vector<FeatureVariant>& variants,
                      const RoundResults& r, int res) {
  for (std::size_t v = 0; v < variants.size(); ++v) {
    const double ratio = median(r.ratios[v]);
    std::string verdict = "-";
    if (variants[v].kind == "unused")
      verdict =
          ratio - 1.0 <= kUnusedLimit ? "ok (< 2 %)" : "FAIL (costs " + pct(ratio - 1.0) + ")";
    table.add({variants[v].name, variants[v].kind, fixed(ratio, 3), pct(ratio - 1.0), verdict});
  }
  auto ratio_of = [&](const std::string& prefix) -> double {
    for (std::size_t v = 0; v < variants.size(); ++v)
      if (variants[v].name.rfind(prefix, 0) == 0) return median(r.ratios[v]);
    return NAN;
  };
  const double contact_ns = (ratio_of("sheet lying flat") - ratio_of("the same flat sheet")) *
                            median(r.bare_ns) / (double(res) * res);
  table.add({"collision response per vertex in contact, per collider", "used", "-",
             fixed(contact_ns, 1) + " ns", "-"});
}

}  // namespace

std::vector<Table> features_suite(const SuiteOptions& o) {
  const int res = o.quick ? 32 : 128;
  const int rounds = o.quick ? 2 : 7;
  const double seconds = o.quick ? 0.03 : 0.25;
  const Scene bare_scene = sheet_scene(res, o.threads, false);
  // The window draws at 60 Hz; with the bench scene's step, one frame spans this many steps.
  FieldExport fields;
  fields.steps_per_frame = std::max(1L, std::lround(1.0 / 60.0 / bare_scene.solver.dt));
  fields.buffer.resize(3 * static_cast<std::size_t>(res) * res);
  const std::vector<FeatureVariant> variants = feature_variants(fields);
  const RoundResults results = measure_rounds(variants, bare_scene, fields, rounds, seconds, o.log);

  Table table;
  table.title = "Feature costs: " + std::to_string(res) + "x" + std::to_string(res) +
                " bench sheet, symplectic Euler, float, " + std::to_string(o.threads) +
                " thread(s); bare step " + fixed(median(results.bare_ns) * 1e-3, 1) +
                " us; field export per frame = every " + std::to_string(fields.steps_per_frame) +
                " steps; median of " + std::to_string(rounds) + " rounds";
  table.note = quick_note(o.quick,
                          "a 32x32 sheet instead of 128x128, 2 rounds instead of 7, "
                          "0.03 s per measurement instead of 0.25 s (noisier)");
  table.columns = {"configuration", "kind", "cost / bare step", "extra", "verdict"};
  add_feature_rows(table, variants, results, res);
  return {table};
}

}  // namespace clothlab::bench
