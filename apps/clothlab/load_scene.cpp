// Scene loading shared by the subcommands: bad input is reported the same way everywhere.
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/memory_check.hpp"
#include "load/scene_load.hpp"
#include "sim/scene/scene_parser.hpp"
#include "tune/tolerance.hpp"

namespace clothlab::app {

std::optional<Scene> load_scene(const char* command, const std::string& path,
                                const std::vector<std::string>& overrides) {
  try {
    Scene scene = read_scene_file(path, overrides);
    check_memory(scene,
                 available_bytes());  // a scene that will not fit is refused before it is built
    return scene;
  } catch (const SceneError& e) {
    std::fprintf(stderr, "clothlab %s: %s\n", command, e.what());
    return std::nullopt;
  }
}

namespace {

// The tolerance's setting (docs/tuning.md, "A tolerance in the scene"), or a SceneError at the
// key when it cannot be met or the scene cannot be tuned.
tune::TolerancePick pick_setting(const Scene& scene, const std::string& path,
                                 const std::vector<std::string>& overrides, bool quiet) {
  const std::string key = "solver.tolerance";
  const auto at = scene.locations.find(key);
  const SourceLoc where = at != scene.locations.end() ? at->second : SourceLoc{path, 0, 0};
  const std::string cache = tune::cache_file(read_scene_text(path), overrides);
  try {
    return tune::resolve_tolerance(tune::file_reader(path, overrides), cache,
                                   scene.solver.tolerance, quiet ? nullptr : &std::cerr);
  } catch (const std::invalid_argument& e) {
    throw SceneError(where, key, e.what());
  } catch (const std::runtime_error& e) {  // a reference that diverges, a cache not written
    throw SceneError(where, key, std::string("the scene cannot be tuned: ") + e.what());
  }
}

}  // namespace

std::optional<Scene> load_scene_to_run(const char* command, const std::string& path,
                                       const std::vector<std::string>& overrides, bool quiet) {
  std::optional<Scene> scene = load_scene(command, path, overrides);
  if (!scene || !(scene->solver.tolerance > 0.0)) return scene;
  try {
    const tune::TolerancePick p = pick_setting(*scene, path, overrides, quiet);
    if (!quiet)
      std::fprintf(stderr, "clothlab %s: solver.tolerance %.3g mm: %s%s\n", command,
                   1e3 * scene->solver.tolerance, p.why.c_str(),
                   p.cached ? " (from the cache)" : "");
    std::vector<std::string> all = overrides;
    all.insert(all.end(), p.setting.overrides.begin(), p.setting.overrides.end());
    return load_scene(command, path, all);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "clothlab %s: %s\n", command, e.what());
    return std::nullopt;
  }
}

}  // namespace clothlab::app
