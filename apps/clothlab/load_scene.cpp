// Scene loading shared by the subcommands: bad input is reported the same way everywhere.
#include <cstdio>
#include <iostream>

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

std::optional<Scene> load_scene_to_run(const char* command, const std::string& path,
                                       const std::vector<std::string>& overrides, bool quiet) {
  std::optional<Scene> scene = load_scene(command, path, overrides);
  if (!scene || !(scene->solver.tolerance > 0.0)) return scene;
  try {
    const tune::TolerancePick p = tune::resolve_scene_tolerance(
        tune::file_reader(path, overrides), *scene, path,
        tune::cache_file(read_scene_text(path), overrides), quiet ? nullptr : &std::cerr);
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
