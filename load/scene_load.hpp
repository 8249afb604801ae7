// The load step between reading a scene and building its solver (scene/ -> load/ -> sim/): the
// files a scene names are read (OBJ meshes for cloths, colliders and scenery; the music, which
// is analysed), the mannequin's dance is built on the music's beats and its parts appended to
// the colliders, pins_follow names are resolved to those parts, and the loaded scene is
// validated. Every problem is a SceneError naming the scene file, line and key. This is the only
// place that reads files a scene names, so the parser stays plain data and sim/ links no audio.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "sim/scene/scene.hpp"
#include "sim/scene/scene_error.hpp"

namespace clothlab {

// Fills the scene's loaded parts (ClothSpec::mesh, ColliderSpec::mesh, MeshSpec::obj,
// MusicSpec::track, MannequinSpec::motion and the mannequin's colliders), then validate_scene.
void load_scene_files(Scene& scene);

// parse_scene_file / parse_scene_string, then load_scene_files: what every command reads.
Scene read_scene_file(const std::string& path, const std::vector<std::string>& overrides = {});
Scene read_scene_string(std::string_view toml_text, const std::string& name,
                        const std::vector<std::string>& overrides = {});

}  // namespace clothlab
