// SceneError: every problem with a scene file or a --set override. what() is one line that a
// user can act on: "scenes/x.toml:12:3: solver.dt: must be > 0 (got -1)", or for an override
// "--set solver.dt=-1: solver.dt: must be > 0 (got -1)". `clothlab` prints it and exits 2.
#pragma once

#include <charconv>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/scene/scene.hpp"

namespace clothlab {

class SceneError : public std::runtime_error {
 public:
  // key: the full key path ("cloth[1].mass"); empty for file-level problems (syntax, missing).
  SceneError(SourceLoc where, std::string key_path, std::string message)
      : std::runtime_error(compose(where, key_path, message)),
        loc(std::move(where)),
        key(std::move(key_path)),
        detail(std::move(message)) {}

  SourceLoc loc;
  std::string key;
  std::string detail;  // the message without location and key

 private:
  static std::string compose(const SourceLoc& where, const std::string& key_path,
                             const std::string& message) {
    std::string text = where.file;
    if (where.line > 0) {
      text += ':' + std::to_string(where.line);
      if (where.column > 0) text += ':' + std::to_string(where.column);
    }
    if (!text.empty()) text += ": ";
    if (!key_path.empty()) text += key_path + ": ";
    return text + message;
  }
};

// Shortest text that reads back as the same double ("-1", "0.001", "inf"): used in messages so
// that "got ..." shows exactly the value the user wrote.
inline std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace clothlab
