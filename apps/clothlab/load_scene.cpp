// Scene loading shared by the subcommands: bad input is reported the same way everywhere.
#include <cstdio>

#include "apps/clothlab/commands.hpp"
#include "apps/clothlab/memory_check.hpp"
#include "load/scene_load.hpp"

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

}  // namespace clothlab::app
