#include "sim/scene/toml_reader.hpp"

#include <cmath>
#include <limits>

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {

std::string describe(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return "string \"" + *node.value<std::string>() + "\"";
    case toml::node_type::integer:
      return "integer " + std::to_string(*node.value<std::int64_t>());
    case toml::node_type::floating_point: {
      // "16.0", not "16": the point is what makes it a float.
      std::string text = format_number(*node.value<double>());
      if (text.find_first_not_of("-0123456789") == std::string::npos) text += ".0";
      return "float " + text;
    }
    case toml::node_type::boolean:
      return *node.value<bool>() ? "boolean true" : "boolean false";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date/time";
  }
}

void TomlReader::read_section(const toml::table& t, const std::string& prefix_in, Section section,
                              void* object) {
  // A copy: the prefix is often the caller's key(), which the reads below move on; the caller's
  // node and key are restored at the end, so a reader may keep using them after a nested read.
  const std::string prefix = prefix_in;
  const toml::node* const caller_node = node_;
  const std::string caller_key = key_;
  check_keys(t, prefix, section);
  for (const Parameter& p : parameters()) {
    if (p.section != section) continue;
    const toml::node* value = t.get(p.name);
    if (!value) {
      if (!p.required.empty())
        fail(join_key(prefix, p.name), t, "missing (" + std::string(p.required) + ")");
      continue;
    }
    if (!p.read) continue;  // read by its parent's reader (friction's static and kinetic)
    const std::string key = join_key(prefix, p.name);
    note(key, *value);
    node_ = value;
    key_ = key;
    p.read(*this, object);
  }
  node_ = caller_node;
  key_ = caller_key;
  finished(section, t, prefix, object);
}

SourceLoc TomlReader::loc(const std::string& key, const toml::node& node) const {
  for (std::string k = key; !k.empty();) {
    if (auto it = origins_.find(k); it != origins_.end()) return SourceLoc{it->second, 0, 0};
    const auto cut = k.find_last_of(".[");
    if (cut == std::string::npos) break;
    k.resize(cut);
  }
  const toml::source_position begin = node.source().begin;
  return SourceLoc{scene_.file, static_cast<int>(begin.line), static_cast<int>(begin.column)};
}

void TomlReader::note(const std::string& key, const toml::node& node) {
  scene_.locations[key] = loc(key, node);
}

void TomlReader::fail(const std::string& key, const toml::node& node,
                      const std::string& message) const {
  throw SceneError(loc(key, node), key, message);
}

void TomlReader::fail_key(const std::string& path, const toml::key& name, const toml::node& node,
                          const std::string& message) const {
  SourceLoc where = loc(path, node);
  const toml::source_position begin = name.source().begin;
  if (where.line > 0 && begin.line > 0) {  // line 0: the key came from a --set
    where.line = static_cast<int>(begin.line);
    where.column = static_cast<int>(begin.column);
  }
  throw SceneError(where, path, message);
}

void TomlReader::check_keys(const toml::table& t, const std::string& prefix,
                            Section section) const {
  for (const auto& [name, node] : t) {
    if (find_parameter(section, name.str())) continue;
    const std::string key = join_key(prefix, name.str());
    if (prefix.empty())
      fail_key(key, name, node, "unknown top-level key (valid: " + key_list(section) + ")");
    fail_key(key, name, node,
             "unknown key (valid keys in " + prefix + ": " + key_list(section) + ")");
  }
}

double TomlReader::number(const toml::node& node, const std::string& key) const {
  double value = 0.0;
  if (const auto* i = node.as_integer())
    value = static_cast<double>(i->get());
  else if (const auto* f = node.as_floating_point())
    value = f->get();
  else
    fail(key, node, "expected a number, got " + describe(node));
  if (!std::isfinite(value)) fail(key, node, "must be finite (got " + format_number(value) + ")");
  return value;
}

// Floats are refused where an integer is meant (a resolution of 32.5 is a mistake).
std::int64_t TomlReader::integer(const toml::node& node, const std::string& key) const {
  const auto* i = node.as_integer();
  if (!i) fail(key, node, "expected an integer, got " + describe(node));
  return i->get();
}

int TomlReader::small_integer(const toml::node& node, const std::string& key) const {
  const std::int64_t value = integer(node, key);
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    fail(key, node, "out of range (got " + std::to_string(value) + ")");
  return static_cast<int>(value);
}

std::string TomlReader::text(const toml::node& node, const std::string& key) const {
  const auto* s = node.as_string();
  if (!s) fail(key, node, "expected a string, got " + describe(node));
  return s->get();
}

bool TomlReader::boolean(const toml::node& node, const std::string& key) const {
  const auto* b = node.as_boolean();
  if (!b) fail(key, node, "expected true or false, got " + describe(node));
  return b->get();
}

const toml::table& TomlReader::table(const toml::node& node, const std::string& key) const {
  const auto* t = node.as_table();
  if (!t) fail(key, node, "expected a table, got " + describe(node));
  return *t;
}

const toml::array& TomlReader::array(const toml::node& node, const std::string& key,
                                     std::optional<std::size_t> size, std::string_view what) const {
  const auto* a = node.as_array();
  if (!a) fail(key, node, "expected an array" + std::string(what) + ", got " + describe(node));
  if (size && a->size() != *size)
    fail(key, node,
         "expected " + std::to_string(*size) + " elements" + std::string(what) + ", got " +
             std::to_string(a->size()));
  return *a;
}

std::vector<int> TomlReader::index_tuple(const toml::node& node, const std::string& key,
                                         std::size_t min, std::size_t max,
                                         std::string_view form) const {
  const auto* a = node.as_array();
  if (!a || a->size() < min || a->size() > max)
    fail(key, node,
         "expected " + std::string(form) + ", got " + describe(node) +
             (a ? " of " + std::to_string(a->size()) : std::string()));
  std::vector<int> out;
  for (std::size_t n = 0; n < a->size(); ++n)
    out.push_back(small_integer(*a->get(n), key + "[" + std::to_string(n) + "]"));
  return out;
}

}  // namespace clothlab
