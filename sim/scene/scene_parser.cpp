// Scene parser: TOML text -> (apply --set overrides, overrides.cpp) -> read through the parameter
// table (TomlReader, parameters.cpp) -> validate_scene_data. Plain data: the files a scene names
// are read afterwards by the load step (load/scene_load.hpp). The TOML layer (toml++) checks
// syntax; the reader checks keys and types and records where each value came from; validate.cpp
// checks ranges. Errors are SceneError, never a crash.
#include "sim/scene/scene_parser.hpp"

#include "sim/scene/overrides.hpp"
#include "sim/scene/parameter_keys.hpp"
#include "sim/scene/toml_reader.hpp"

#include <toml++/toml.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {

namespace {

// The reader with what follows a table: a mesh cloth sits where its OBJ puts it unless an
// origin is given, and a wind table turns the wind on. Files the scene names are read later, by
// the load step (load/scene_load.hpp).
class SceneReader : public TomlReader {
 public:
  using TomlReader::TomlReader;

  void finished(Section section, const toml::table& t, const std::string& key,
                void* object) override {
    if (section == Section::cloth) {
      auto& cloth = *static_cast<ClothSpec*>(object);
      if (cloth.shape == "mesh" && !t.contains(key_of<&ClothSpec::origin>()))
        cloth.origin = {0.0, 0.0, 0.0};
    } else if (section == Section::wind) {
      static_cast<WindSpec*>(object)->enabled = true;
    }
  }
};

}  // namespace

Scene parse_scene_string(std::string_view toml_text, const std::string& name,
                         const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml_text, name);
  } catch (const toml::parse_error& error) {
    const toml::source_position at = error.source().begin;
    throw SceneError(SourceLoc{name, static_cast<int>(at.line), static_cast<int>(at.column)}, "",
                     "TOML syntax error: " + std::string(error.description()));
  }
  OverrideOrigins origins;
  apply_overrides(root, overrides, origins);

  Scene scene;
  scene.file = name;
  SceneReader(origins, scene).read_section(root, "", Section::top, &scene);
  validate_scene_data(scene);
  return scene;
}

std::string read_scene_text(const std::string& path) {
  const SourceLoc loc{path, 0, 0};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw SceneError(loc, "", "is a directory, not a scene file");
  // A device or pipe (/dev/zero, /dev/urandom) would be read forever; a scene is a few
  // kilobytes, so one beyond kMaxSceneBytes is not a scene.
  constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw SceneError(loc, "", "is not a regular file (a device, pipe or socket), not a scene file");
  if (const auto bytes = std::filesystem::file_size(path, ec); !ec && bytes > kMaxSceneBytes)
    throw SceneError(loc, "",
                     std::to_string(bytes) + " bytes; a scene file may have at most " +
                         std::to_string(kMaxSceneBytes) + " (16 MiB)");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw SceneError(loc, "", std::string("cannot open scene file (") + std::strerror(errno) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw SceneError(loc, "", "cannot read scene file");
  return text.str();
}

Scene parse_scene_file(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_scene_string(read_scene_text(path), path, overrides);
}

}  // namespace clothlab
