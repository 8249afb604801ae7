// Scene loading shared by the subcommands: bad input is reported the same way everywhere.
#include <cstdio>

#include "apps/clothlab/commands.hpp"
#include "load/scene_load.hpp"

namespace clothlab::app {

std::optional<Scene> load_scene(const char* command, const std::string& path,
                                const std::vector<std::string>& overrides) {
  try {
    return read_scene_file(path, overrides);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "clothlab %s: %s\n", command, e.what());
    return std::nullopt;
  }
}

}  // namespace clothlab::app
