// SceneSource::load_to_run: a Simulation of a scene with solver.tolerance steps with the setting
// that `clothlab tune` chose for it, as `clothlab trace` does (docs/tuning.md, "A tolerance in
// the scene").
#include <stdexcept>

#include "python/bindings/scene_source.hpp"
#include "sim/scene/scene_error.hpp"
#include "tune/tolerance.hpp"

namespace clothlab::py_bindings {

Scene SceneSource::load_to_run(std::string& said) const {
  const Scene scene = load();
  if (!(scene.solver.tolerance > 0.0)) return scene;
  const std::string key = "solver.tolerance";
  const auto at = scene.locations.find(key);
  const SourceLoc where = at != scene.locations.end() ? at->second : SourceLoc{name, 0, 0};
  const tune::SceneReader read = [this](const std::vector<std::string>& extra) {
    SceneSource s = *this;
    s.overrides.insert(s.overrides.end(), extra.begin(), extra.end());
    return s.load();
  };
  tune::TolerancePick p;
  try {
    p = tune::resolve_tolerance(read, tune::cache_file(text, overrides), scene.solver.tolerance,
                                nullptr);
  } catch (const std::invalid_argument& e) {
    throw SceneError(where, key, e.what());
  } catch (const std::runtime_error& e) {
    throw SceneError(where, key, std::string("the scene cannot be tuned: ") + e.what());
  }
  said = "solver.tolerance: " + p.why + (p.cached ? " (from the cache)" : "");
  SceneSource chosen = *this;
  chosen.overrides.insert(chosen.overrides.end(), p.setting.overrides.begin(),
                          p.setting.overrides.end());
  return chosen.load();
}

}  // namespace clothlab::py_bindings
