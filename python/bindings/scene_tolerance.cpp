// SceneSource::load_to_run: a Simulation of a scene with solver.tolerance steps with the setting
// that `clothlab tune` chose for it, as `clothlab trace` does (docs/tuning.md, "A tolerance in
// the scene").
#include "python/bindings/bindings.hpp"
#include "tune/tolerance.hpp"

namespace clothlab::py_bindings {

Scene SceneSource::load_to_run(std::string& said) const {
  const Scene scene = load();
  if (!(scene.solver.tolerance > 0.0)) return scene;
  const tune::TolerancePick p = tune::resolve_scene_tolerance(
      reader_of(*this), scene, name, tune::cache_file(text, overrides), nullptr);
  said = "solver.tolerance: " + p.why + (p.cached ? " (from the cache)" : "");
  SceneSource chosen = *this;
  chosen.overrides.insert(chosen.overrides.end(), p.setting.overrides.begin(),
                          p.setting.overrides.end());
  return chosen.load();
}

}  // namespace clothlab::py_bindings
