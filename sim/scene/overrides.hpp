// --set key.path=value overrides, applied to the parsed TOML tree before it is read into a Scene,
// so an overridden value goes through exactly the same type and range checks as the file's.
#pragma once

#include <toml++/toml.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace clothlab {

// Key paths whose value came from a --set argument, mapped to that argument ("--set k=v").
using OverrideOrigins = std::map<std::string, std::string>;

// Applies each "key.path=value" to root in order (later ones win) and records where each
// overridden key came from. Throws SceneError naming the argument on a malformed override.
void apply_overrides(toml::table& root, const std::vector<std::string>& overrides,
                     OverrideOrigins& origins);

inline std::string join_key(const std::string& prefix, std::string_view name) {
  return prefix.empty() ? std::string(name) : prefix + "." + std::string(name);
}

}  // namespace clothlab
