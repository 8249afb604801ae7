// Range and consistency checks on a Scene, whether parsed or built in code.
#pragma once

#include "sim/scene/scene.hpp"
#include "sim/scene/scene_error.hpp"

namespace clothlab {

// Throws SceneError for the first bad value, located through Scene::locations (a key with no
// recorded location is reported at its nearest recorded parent, else at Scene::file).
void validate_scene(const Scene& scene);

}  // namespace clothlab
