#include "load/scene_load.hpp"

#include <filesystem>
#include <stdexcept>
#include <utility>

#include "music/music_track.hpp"
#include "sim/body/body_motion.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/scene/parameter_keys.hpp"
#include "sim/scene/scene_parser.hpp"
#include "sim/scene/validate.hpp"

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {
namespace {

class Loader {
 public:
  explicit Loader(Scene& scene) : scene_(scene) {}

  void run();

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw SceneError(location_of(scene_, key), key, message);
  }

  // A file named in the scene: relative paths are relative to the scene file's folder.
  std::string scene_relative(const std::string& file) const;

  // The OBJ named by `key`.file, read now so that a missing, malformed or empty file is a scene
  // error naming the key.
  std::shared_ptr<const TriangleMesh> obj(const std::string& key, const std::string& file,
                                          double scale, const std::string& what,
                                          const std::string& example = "thing.obj") const;

  // A mesh cloth's OBJ; its vertex count becomes the resolution [n, 1], the layout a mesh cloth
  // has in the solver (sim/model/model.hpp, ClothRange).
  void load_cloth_mesh(ClothSpec& cloth) const;

  // [music]: the file is read and analysed (or the drum track generated).
  void load_music(MusicSpec& m) const;

  // [mannequin]: the dance on the music's beats (or a steady 120 BPM), and each of the figure's
  // primitives appended to the colliders as "mannequin.<part>".
  void build_mannequin(MannequinSpec& m) const;

  // Part i of the mannequin as a collider posed by the dance.
  static ColliderSpec part_collider(const MannequinSpec& m, int i, std::string key);

  // pins_follow = "pelvis": the mannequin part's collider, once the mannequin is built.
  void resolve_follow_names() const;
  void resolve_follow_name(ClothSpec& cloth, std::size_t n) const;

  Scene& scene_;
};

inline void Loader::run() {
  for (ClothSpec& cloth : scene_.cloths)
    if (cloth.shape == "mesh") load_cloth_mesh(cloth);
  for (ColliderSpec& c : scene_.colliders)
    if (c.kind == ColliderKind::mesh) c.mesh = obj(c.key, c.file, c.scale, "a mesh collider");
  for (MeshSpec& m : scene_.render.meshes)
    if (m.kind == MeshKind::obj) m.obj = obj(m.key, m.file, m.scale, "an obj mesh");
  if (scene_.music) load_music(*scene_.music);
  if (scene_.mannequin) build_mannequin(*scene_.mannequin);
  resolve_follow_names();
}

inline std::string Loader::scene_relative(const std::string& file) const {
  std::filesystem::path path(file);
  if (path.is_relative() && scene_.file != "<string>")
    path = std::filesystem::path(scene_.file).parent_path() / path;
  return path.string();
}

inline std::shared_ptr<const TriangleMesh> Loader::obj(const std::string& key,
                                                       const std::string& file, double scale,
                                                       const std::string& what,
                                                       const std::string& example) const {
  const std::string file_key = key + "." + std::string(key_of<&ColliderSpec::file>());
  if (file.empty())
    fail(file_key, "missing (" + what + " needs " + std::string(key_of<&ColliderSpec::file>()) +
                       " = \"" + example + "\")");
  try {
    return std::make_shared<const TriangleMesh>(load_obj(scene_relative(file), scale));
  } catch (const ObjError& e) {
    fail(file_key, e.what());
  }
}

inline void Loader::load_cloth_mesh(ClothSpec& cloth) const {
  cloth.mesh = obj(cloth.key, cloth.file, cloth.scale, "a mesh cloth", "cloth.obj");
  cloth.resolution = {static_cast<int>(cloth.mesh->positions.size()), 1};
}

inline void Loader::load_music(MusicSpec& m) const {
  if (m.file.empty()) {
    m.track = std::make_shared<const MusicTrack>(generated_music(m.tempo, m.seconds));
    return;
  }
  const std::string key =
      section_path(Section::music) + "." + std::string(key_of<&MusicSpec::file>());
  const std::string path = scene_relative(m.file);
  try {
    m.track = std::make_shared<const MusicTrack>(clothlab::load_music(path));
  } catch (const AudioError& e) {
    fail(key, e.what());
  }
  if (m.track->analysis.beats.size() < 2) fail(key, path + ": no beat found in the music");
}

inline void Loader::build_mannequin(MannequinSpec& m) const {
  const std::string key(key_of<&Scene::mannequin>());
  DanceSpec dance;
  dance.settle_seconds = m.settle;
  dance.blend_beats = m.blend_beats;
  dance.amplitude = m.amplitude;
  std::vector<double> beats = constant_tempo_beats(120.0, 3600.0), amplitude;
  if (scene_.music) {
    beats = scene_.music->track->analysis.beats;
    amplitude = beat_amplitudes(scene_.music->track->analysis);
  }
  try {
    m.motion = std::make_shared<const BodyMotion>(
        Dance(make_mannequin(), dance, std::move(beats), std::move(amplitude)),
        Eigen::Vector3d(m.position[0], m.position[1], m.position[2]), m.facing);
  } catch (const std::invalid_argument& e) {
    fail(key, e.what());
  }
  const auto& parts = m.motion->dance().primitives();
  for (std::size_t i = 0; i < parts.size(); ++i)
    scene_.colliders.push_back(part_collider(m, static_cast<int>(i), key + "." + parts[i].name));
}

inline ColliderSpec Loader::part_collider(const MannequinSpec& m, int i, std::string key) {
  const BodyPrimitive& p = m.motion->dance().primitives()[std::size_t(i)];
  ColliderSpec c;
  c.kind = p.shape == BodyShape::sphere ? ColliderKind::sphere
           : p.shape == BodyShape::box  ? ColliderKind::box
                                        : ColliderKind::capsule;
  c.radius = p.shape == BodyShape::box ? 0.1 : p.radius;
  for (int a = 0; a < 3; ++a)
    c.half_extents[a] = p.shape == BodyShape::box ? p.half_extents[a] : 0.1;
  c.a = {0.0, -p.half_length, 0.0};
  c.b = {0.0, p.half_length, 0.0};
  c.static_friction = m.static_friction;
  c.kinetic_friction = m.kinetic_friction;
  c.thickness = m.thickness;
  c.body = m.motion;
  c.body_part = i;
  c.key = std::move(key);
  return c;
}

inline void Loader::resolve_follow_names() const {
  for (ClothSpec& cloth : scene_.cloths)
    for (std::size_t n = 0; n < cloth.pins_follow_names.size(); ++n)
      if (!cloth.pins_follow_names[n].empty()) resolve_follow_name(cloth, n);
}

inline void Loader::resolve_follow_name(ClothSpec& cloth, std::size_t n) const {
  const std::string prefix = std::string(key_of<&Scene::mannequin>()) + ".";
  const std::string& name = cloth.pins_follow_names[n];
  std::string k = cloth.key + "." + std::string(key_of<&ClothSpec::pins_follow>());
  if (cloth.pins_follow_names.size() > 1) k += "[" + std::to_string(n) + "]";
  if (!scene_.mannequin)
    fail(k, "names a mannequin part (\"" + name + "\"), but the scene has no [mannequin]");
  std::string parts;
  for (std::size_t c = 0; c < scene_.colliders.size(); ++c) {
    const ColliderSpec& spec = scene_.colliders[c];
    if (!spec.body) continue;
    const std::string part = spec.key.substr(prefix.size());
    if (part == name) cloth.pins_follow[n] = static_cast<int>(c);
    parts += (parts.empty() ? "" : ", ") + part;
  }
  if (cloth.pins_follow[n] < 0)
    fail(k, "no mannequin part \"" + name + "\" (parts: " + parts + ")");
}

}  // namespace

void load_scene_files(Scene& scene) {
  Loader(scene).run();
  validate_scene(scene);
}

Scene read_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  Scene scene = parse_scene_file(path, overrides);
  load_scene_files(scene);
  return scene;
}

Scene read_scene_string(std::string_view toml_text, const std::string& name,
                        const std::vector<std::string>& overrides) {
  Scene scene = parse_scene_string(toml_text, name, overrides);
  load_scene_files(scene);
  return scene;
}

}  // namespace clothlab
