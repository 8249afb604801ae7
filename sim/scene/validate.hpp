// Range and consistency checks on a Scene, whether parsed or built in code. The ranges are the
// parameter table's (parameters.hpp); the rules between values (a tube's ring count, orthogonal
// axes, pins inside the grid, increasing keyframe times, ...) are this file's.
#pragma once

#include <limits>
#include <string>

#include "sim/scene/parameters.hpp"
#include "sim/scene/scene.hpp"
#include "sim/scene/scene_error.hpp"

namespace clothlab {

// Every number a scene gives must be at most this in magnitude: the largest float, since the
// float solver reads each value in its precision and a finite double beyond it (1e39) would be
// inf there. The double solver takes the same limit, so a scene means the same in both.
inline constexpr double kMaxSceneMagnitude = std::numeric_limits<float>::max();

// Throws SceneError for the first bad value, located through Scene::locations (a key with no
// recorded location is reported at its nearest recorded parent, else at Scene::file). The scene
// must be loaded (load/scene_load.hpp) or built in code with its meshes.
void validate_scene(const Scene& scene);

// The checks that need nothing the load step reads: what the parser runs. A mesh cloth's pins and
// traced vertices, meshes and pins_follow wait for validate_scene after the load.
void validate_scene_data(const Scene& scene);

// Where key's value came from, or its nearest recorded parent's, else the scene file.
SourceLoc location_of(const Scene& scene, std::string key);

}  // namespace clothlab
