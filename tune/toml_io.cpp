#include "tune/toml_io.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "sim/core/temp_files.hpp"

namespace clothlab::tune::toml_io {

std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "\"%.17e\"", v);
  return text;
}

std::string exact_list(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + exact(values[i]);
  return out + "]";
}

double number(const toml::node_view<const toml::node>& n) {
  const std::optional<std::string> text = n.value<std::string>();
  return text ? std::strtod(text->c_str(), nullptr) : NAN;
}

std::vector<double> numbers(const toml::node_view<const toml::node>& n) {
  std::vector<double> out;
  if (const toml::array* a = n.as_array())
    for (const toml::node& v : *a) out.push_back(number(toml::node_view<const toml::node>(v)));
  return out;
}

void write_setting(std::ostream& out, const Setting& s) {
  toml::array set;
  for (const std::string& line : s.overrides) set.push_back(line);
  out << "family = " << toml::value<std::string>(s.family)
      << "\nlabel = " << toml::value<std::string>(s.label) << "\nset = " << set << "\n";
}

Setting setting_from(const toml::table& t) {
  Setting s{t["family"].value_or(std::string()), t["label"].value_or(std::string()), {}};
  if (const toml::array* set = t["set"].as_array())
    for (const toml::node& n : *set) s.overrides.push_back(n.value_or(std::string()));
  return s;
}

void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& body) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  const TempFileGuard temp(path + ".tmp." + std::to_string(::getpid()));
  {
    std::ofstream out(temp.path());
    body(out);
    if (!out) throw std::runtime_error("cannot write " + temp.path());
  }
  std::error_code ec;
  std::filesystem::rename(temp.path(), path, ec);
  if (ec) {
    std::filesystem::remove(temp.path());
    throw std::runtime_error("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace clothlab::tune::toml_io
