// TomlReader: reads TOML values into a Scene through the parameter table (parameters.hpp). It
// checks keys and types, records where each value came from and turns every problem into a
// SceneError naming the file, line, column and key path (or the --set argument). Ranges are
// validate_scene's. The scene parser subclasses it for the load steps that follow a table.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sim/scene/overrides.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene.hpp"
#include "sim/scene/scene_error.hpp"

namespace clothlab {

class TomlReader {
 public:
  TomlReader(const OverrideOrigins& origins, Scene& scene) : origins_(origins), scene_(scene) {}
  virtual ~TomlReader() = default;

  Scene& scene() { return scene_; }

  // The value a record's read function is called for, and its full key path.
  const toml::node& node() const { return *node_; }
  const std::string& key() const { return key_; }

  // Checks t's keys against `section`'s records, then reads each record present (in table
  // order) into `object`, the section's struct; finally calls finished().
  void read_section(const toml::table& t, const std::string& prefix, Section section, void* object);

  // Called after a section's values are read: the parser's load steps (OBJ files, music, the
  // dance) hang here.
  virtual void finished(Section section, const toml::table& t, const std::string& prefix,
                        void* object) {}

  // --- locations and errors ---
  SourceLoc loc(const std::string& key, const toml::node& node) const;
  void note(const std::string& key, const toml::node& node);
  [[noreturn]] void fail(const std::string& key, const toml::node& node,
                         const std::string& message) const;
  // A key that should not be there: points at the key itself rather than at its value.
  [[noreturn]] void fail_key(const std::string& path, const toml::key& name, const toml::node& node,
                             const std::string& message) const;
  void check_keys(const toml::table& t, const std::string& prefix, Section section) const;

  // --- typed values ---
  double number(const toml::node& node, const std::string& key) const;
  std::int64_t integer(const toml::node& node, const std::string& key) const;
  int small_integer(const toml::node& node, const std::string& key) const;
  std::string text(const toml::node& node, const std::string& key) const;
  bool boolean(const toml::node& node, const std::string& key) const;
  const toml::table& table(const toml::node& node, const std::string& key) const;
  const toml::array& array(const toml::node& node, const std::string& key,
                           std::optional<std::size_t> size = std::nullopt,
                           std::string_view what = "") const;
  // [i, j] pairs, and [c, i, j] triples for trace vertices.
  std::vector<int> index_tuple(const toml::node& node, const std::string& key, std::size_t min,
                               std::size_t max, std::string_view form) const;

  template <std::size_t N>
  std::array<double, N> numbers(const toml::node& node, const std::string& key) const {
    const toml::array& a = array(node, key, N, " (numbers)");
    std::array<double, N> out{};
    for (std::size_t n = 0; n < N; ++n)
      out[n] = number(*a.get(n), key + "[" + std::to_string(n) + "]");
    return out;
  }

  template <std::size_t N>
  std::array<int, N> integers(const toml::node& node, const std::string& key) const {
    const toml::array& a = array(node, key, N, " (integers)");
    std::array<int, N> out{};
    for (std::size_t n = 0; n < N; ++n)
      out[n] = small_integer(*a.get(n), key + "[" + std::to_string(n) + "]");
    return out;
  }

  // A name from a fixed table (enum value and its scene-file spelling).
  template <class E, std::size_t N>
  E choice(const toml::node& node, const std::string& key,
           const std::array<std::pair<E, const char*>, N>& names, std::string_view what) const {
    const std::string name = text(node, key);
    std::string valid;
    for (const auto& [value, spelling] : names) {
      if (name == spelling) return value;
      valid += (valid.empty() ? "" : ", ") + std::string(spelling);
    }
    fail(key, node, "unknown " + std::string(what) + " \"" + name + "\" (valid: " + valid + ")");
  }

  // Reads each table of an array of tables (`[[colliders]]`) into a new element of `out`,
  // whose `key` member names it ("colliders[2]").
  template <class Spec>
  void read_tables(const toml::node& node, const std::string& key, std::string_view what,
                   Section section, std::vector<Spec>& out) {
    const toml::array& a = array(node, key, std::nullopt, what);
    for (std::size_t n = 0; n < a.size(); ++n) {
      const std::string k = key + "[" + std::to_string(n) + "]";
      note(k, *a.get(n));
      Spec spec;
      if constexpr (requires { spec.key; }) spec.key = k;
      read_section(table(*a.get(n), k), k, section, &spec);
      out.push_back(std::move(spec));
    }
  }

 private:
  const OverrideOrigins& origins_;
  Scene& scene_;
  const toml::node* node_ = nullptr;
  std::string key_;
};

// "string \"x\"", "integer 3", "float 16.0", ...: what a value is, for "expected ..., got ..."
std::string describe(const toml::node& node);

}  // namespace clothlab
