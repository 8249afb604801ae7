#include "sim/scene/overrides.hpp"

#include <optional>
#include <utility>

#include "sim/scene/scene_error.hpp"

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {
namespace {

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return std::string(text.substr(first, last - first + 1));
}

struct PathStep {
  std::string name;
  std::optional<std::size_t> index;  // "cloth[1]" -> name "cloth", index 1
};

bool is_bare_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

// One dotted segment: a bare TOML key, optionally followed by one [N].
std::optional<PathStep> parse_step(std::string_view text) {
  PathStep step;
  const auto bracket = text.find('[');
  step.name = std::string(text.substr(0, bracket));
  if (step.name.empty()) return std::nullopt;
  for (char c : step.name)
    if (!is_bare_key_char(c)) return std::nullopt;
  if (bracket == std::string_view::npos) return step;
  const std::string_view digits = text.substr(bracket + 1);
  if (digits.size() < 2 || digits.back() != ']') return std::nullopt;
  std::size_t index = 0;
  for (char c : digits.substr(0, digits.size() - 1)) {
    if (c < '0' || c > '9' || index > 1'000'000'000) return std::nullopt;
    index = index * 10 + static_cast<std::size_t>(c - '0');
  }
  step.index = index;
  return step;
}

std::vector<PathStep> parse_override_path(const std::string& path, const SourceLoc& loc) {
  std::vector<PathStep> steps;
  std::size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const auto segment = std::string_view(path).substr(start, dot - start);
    auto step = parse_step(segment);
    if (!step)
      throw SceneError(loc, path,
                       "malformed key path (expected names like solver.dt or cloth[1].mass)");
    steps.push_back(std::move(*step));
    if (dot == std::string::npos) return steps;
    start = dot + 1;
  }
}

// The value text as TOML ("0.002", "[1, 2]", "{ velocity = [1, 0, 0] }"); anything that does not
// parse as one TOML value is taken as a plain string, so "--set solver.integrator=rk4" works.
toml::table parse_override_value(const std::string& text) {
  try {
    toml::table parsed = toml::parse("v = " + text);
    if (parsed.size() == 1 && parsed.contains("v")) return parsed;
  } catch (const toml::parse_error&) {
    // not TOML: fall through to a string
  }
  toml::table as_string;
  as_string.insert("v", text);
  return as_string;
}

// Records that key (and everything below it) now comes from arg.
void record_origin(OverrideOrigins& origins, const std::string& key, const std::string& arg) {
  for (auto it = origins.lower_bound(key); it != origins.end();) {
    const std::string& k = it->first;
    if (k.compare(0, key.size(), key) != 0) break;
    const bool below = k.size() == key.size() || k[key.size()] == '.' || k[key.size()] == '[';
    it = below ? origins.erase(it) : std::next(it);
  }
  origins[key] = arg;
}

// The path from step n on with step n's index dropped, after `key` (the path up to step n):
// what to write instead of indexing a table that is not an array ("cloth[1].mass" ->
// "cloth.mass").
std::string without_index(const std::string& key, const std::vector<PathStep>& steps,
                          std::size_t n) {
  std::string path = key;
  for (std::size_t m = n + 1; m < steps.size(); ++m) {
    path = join_key(path, steps[m].name);
    if (steps[m].index) path += "[" + std::to_string(*steps[m].index) + "]";
  }
  return path;
}

class OverrideApplier {
 public:
  OverrideApplier(toml::table& root, OverrideOrigins& origins) : root_(root), origins_(origins) {}

  void apply(const std::string& arg) {
    const std::string origin = "--set " + arg;
    const SourceLoc loc{origin, 0, 0};
    const auto eq = arg.find('=');
    if (eq == std::string::npos)
      throw SceneError(loc, "", "expected key.path=value (e.g. solver.dt=0.0005)");
    const std::string path = trim(std::string_view(arg).substr(0, eq));
    if (path.empty()) throw SceneError(loc, "", "empty key path before '='");
    const std::vector<PathStep> steps = parse_override_path(path, loc);
    toml::table value = parse_override_value(trim(std::string_view(arg).substr(eq + 1)));
    assign(steps, std::move(*value.get("v")), origin, loc);
  }

 private:
  // Walks the path, creating missing tables (an unknown key so created is then rejected by the
  // reader's unknown-key check, located at this --set), and stores the value at its end.
  void assign(const std::vector<PathStep>& steps, toml::node&& value, const std::string& origin,
              const SourceLoc& loc) {
    toml::table* table = &root_;
    std::string key;
    for (std::size_t n = 0; n < steps.size(); ++n) {
      const PathStep& step = steps[n];
      const bool last = n + 1 == steps.size();
      key = join_key(key, step.name);
      toml::node* node = table->get(step.name);
      if (!step.index) {
        if (last) {
          table->insert_or_assign(step.name, std::move(value));
          record_origin(origins_, key, origin);
          return;
        }
        if (!node) {
          node = table->insert(step.name, toml::table{}).first->second.as_table();
          record_origin(origins_, key, origin);
        }
        if (node->is_array())
          throw SceneError(loc, key, "is an array; name one element as " + key + "[N]");
        table = node->as_table();
        if (!table) throw SceneError(loc, key, "is a single value, not a table");
        continue;
      }
      toml::array* array = node ? node->as_array() : nullptr;
      if (!array && node && node->is_table())
        throw SceneError(loc, key,
                         "is a single table in this scene, not an array of tables: write " +
                             without_index(key, steps, n) +
                             " (a scene with several writes each as [[" + key + "]])");
      if (!array)
        throw SceneError(loc, key, "is not an array in this scene, so [N] cannot index it");
      const std::size_t index = *step.index;
      if (index >= array->size())
        throw SceneError(loc, key + "[" + std::to_string(index) + "]",
                         "index out of range (" + key + " has " + std::to_string(array->size()) +
                             " element" + (array->size() == 1 ? "" : "s") + ")");
      key += "[" + std::to_string(index) + "]";
      if (last) {
        array->replace(array->cbegin() + static_cast<std::ptrdiff_t>(index), std::move(value));
        record_origin(origins_, key, origin);
        return;
      }
      table = array->get(index)->as_table();
      if (!table) throw SceneError(loc, key, "is not a table");
    }
  }

  toml::table& root_;
  OverrideOrigins& origins_;
};

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& overrides,
                     OverrideOrigins& origins) {
  OverrideApplier applier(root, origins);
  for (const std::string& arg : overrides) applier.apply(arg);
}

}  // namespace clothlab
