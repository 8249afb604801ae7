// Reading a scene file (TOML, version 1; see docs/design.md) into a Scene.
// Every problem -- unreadable file, TOML syntax, unknown key, wrong type, value out of range --
// is a SceneError naming the file, line, column and key path (or the --set argument).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/scene/validate.hpp"

namespace clothlab {

// overrides: "key.path=value" strings from --set, applied to the parsed TOML before it is read,
// so they pass exactly the same checks as values in the file. The value is TOML ("0.002",
// "[1, 2]", "{ velocity = [1, 0, 0] }"); text that is not TOML is taken as a string, so
// "solver.integrator=rk4" works unquoted. Paths may index arrays: "cloth[1].mass".
Scene parse_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});

// The text of a scene file, refused (SceneError naming the file) when it is a directory, a device
// or pipe, beyond 16 MiB or unreadable: what parse_scene_file parses.
std::string read_scene_text(const std::string& path);

// The same for scene text held in memory; name stands in for the file name in messages.
Scene parse_scene_string(std::string_view toml_text, const std::string& name,
                         const std::vector<std::string>& overrides = {});

}  // namespace clothlab
