// What a Python Scene holds: the scene's TOML text, the file it came from (relative paths in it,
// OBJ meshes and music, stay relative to that file's folder) and the key.path=value overrides
// set on it, in order. This is all that crosses the network in a sweep: no solver state.
#pragma once

#include <string>
#include <vector>

#include "sim/scene/scene.hpp"

namespace clothlab::py_bindings {

struct SceneSource {
  std::string text;
  std::string name = "<string>";       // the file, or "<string>" for text given in code
  std::vector<std::string> overrides;  // "key.path=value", later ones win

  // The loaded, validated scene (files it names read): what `clothlab trace --set ...` reads.
  // Throws SceneError with the command line's message.
  Scene load() const;
  // load(), then a solver.tolerance resolved as the command line does (tune/tolerance.hpp): the
  // chosen setting's lines added to the overrides; `said` gets the choice in one line.
  Scene load_to_run(std::string& said) const;
};

}  // namespace clothlab::py_bindings
