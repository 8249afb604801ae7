// A double-quoted string as JSON and TOML both read it: quotes and backslashes escaped, control
// characters and DEL as \uXXXX (the bench suites' JSON run records, the Python module's
// scene overrides).
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace clothlab {

inline std::string quoted_string(std::string_view s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
      out += escaped;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

}  // namespace clothlab
