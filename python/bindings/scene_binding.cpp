// clothlab.Scene: a scene file's text plus the overrides set on it, checked by the same parser,
// parameter table and load step as the command line (so errors carry its messages).
#include <pybind11/stl.h>

#include <toml++/toml.h>
#include <cmath>
#include <cstdio>

#include "load/scene_load.hpp"
#include "python/bindings/bindings.hpp"
#include "sim/core/quoted_string.hpp"
#include "sim/scene/overrides.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene_parser.hpp"

namespace py = pybind11;

namespace clothlab::py_bindings {

Scene SceneSource::load() const {
  return read_scene_string(text, name, overrides);
}

namespace {

// A float as TOML writes it, exactly (17 significant digits), always a float ("2.0", not "2").
std::string float_literal(double d) {
  if (std::isnan(d)) return "nan";
  if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

// A Python value as the TOML text of an override: bool, int, float, str, a sequence of those (an
// array) or a dict (an inline table). numpy scalars and arrays work through __index__,
// __float__ and iteration.
std::string toml_literal(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(v)) return quoted_string(v.cast<std::string>());
  if (py::isinstance<py::int_>(v)) return py::str(v).cast<std::string>();
  if (py::isinstance<py::float_>(v)) return float_literal(v.cast<double>());
  if (py::isinstance<py::dict>(v)) {
    std::string out = "{ ";
    bool first = true;
    for (const auto& [key, value] : v.cast<py::dict>()) {
      if (!first) out += ", ";
      first = false;
      out += quoted_string(py::str(key).cast<std::string>()) + " = " + toml_literal(value);
    }
    return out + " }";
  }
  if (py::hasattr(v, "dtype") && py::hasattr(v, "item") && py::len(v.attr("shape")) == 0)
    return toml_literal(v.attr("item")());  // a numpy scalar
  if (py::hasattr(v, "__index__")) return py::str(py::int_(py::reinterpret_borrow<py::object>(v)));
  if (py::isinstance<py::iterable>(v)) {
    std::string out = "[";
    bool first = true;
    for (const auto& item : v) {
      if (!first) out += ", ";
      first = false;
      out += toml_literal(item);
    }
    return out + "]";
  }
  if (py::hasattr(v, "__float__"))
    return float_literal(py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>());
  throw py::type_error("clothlab.Scene.set: cannot write a " +
                       py::str(py::type::of(v).attr("__name__")).cast<std::string>() +
                       " as a scene value (use a number, bool, str, list or dict)");
}

py::object to_python(const toml::node& node) {
  if (const auto* v = node.as_integer()) return py::int_(v->get());
  if (const auto* v = node.as_floating_point()) return py::float_(v->get());
  if (const auto* v = node.as_boolean()) return py::bool_(v->get());
  if (const auto* v = node.as_string()) return py::str(v->get());
  if (const auto* a = node.as_array()) {
    py::list out;
    for (const toml::node& item : *a) out.append(to_python(item));
    return out;
  }
  if (const auto* t = node.as_table()) {
    py::dict out;
    for (const auto& [key, value] : *t) out[py::str(std::string(key.str()))] = to_python(value);
    return out;
  }
  return py::none();
}

// "cloth[1].mass" -> "cloth.mass": the parameter table's path of a key.
std::string table_path(const std::string& key) {
  std::string out;
  int depth = 0;
  for (const char c : key) {
    if (c == '[') ++depth;
    if (depth == 0) out += c;
    if (c == ']') --depth;
  }
  return out;
}

// The value at `key` after the overrides: as the file or an override gives it, else the
// parameter table's default (None for a key without one). Unknown keys raise SceneError.
py::object get_value(const SceneSource& s, const std::string& key) {
  toml::table root = toml::parse(s.text, s.name);
  OverrideOrigins origins;
  apply_overrides(root, s.overrides, origins);
  if (const toml::node_view<toml::node> node = root.at_path(key)) return to_python(*node.node());
  const std::string path = table_path(key);
  for (const Parameter& p : parameters()) {
    if (parameter_path(p) != path) continue;
    if (p.fallback.empty()) return py::none();
    try {
      const toml::table parsed = toml::parse("v = " + std::string(p.fallback));
      return to_python(*parsed.get("v"));
    } catch (const toml::parse_error&) {
      return py::str(std::string(p.fallback));  // a default in words ("the cloth's size")
    }
  }
  throw SceneError({s.name, 0, 0}, key, "unknown key");
}

// The file read once, with the command line's checks and messages (the files it names too).
SceneSource from_file(const std::string& path) {
  SceneSource s{read_scene_text(path), path, {}};
  (void)s.load();
  return s;
}

SceneSource from_toml(const std::string& text) {
  SceneSource s{text, "<string>", {}};
  (void)s.load();
  return s;
}

// Appends the overrides and keeps them only when the scene still loads (read once for all).
void add_overrides(SceneSource& s, const std::vector<std::string>& added) {
  const std::size_t before = s.overrides.size();
  s.overrides.insert(s.overrides.end(), added.begin(), added.end());
  try {
    (void)s.load();
  } catch (...) {
    s.overrides.resize(before);
    throw;
  }
}

void set_value(SceneSource& s, const std::string& key, const py::handle& value) {
  add_overrides(s, {key + "=" + toml_literal(value)});
}

void update_values(SceneSource& s, const py::dict& values) {
  std::vector<std::string> added;
  for (const auto& [key, value] : values)
    added.push_back(py::str(key).cast<std::string>() + "=" + toml_literal(value));
  add_overrides(s, added);
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<SceneSource>(m, "Scene",
                          "A scene: its TOML text, the file it came from and the overrides set on "
                          "it. Build with Scene.from_file or Scene.from_toml.")
      .def_static("from_file", &from_file, py::arg("path"),
                  "Reads and checks a scene file (raises SceneError as `clothlab check` reports).")
      .def_static("from_toml", &from_toml, py::arg("text"), "A scene from TOML text.")
      .def("set", &set_value, py::arg("key"), py::arg("value"),
           "Sets key.path (as --set does) to a number, bool, str, list or dict; a bad key or "
           "value raises SceneError and leaves the scene unchanged.")
      .def("update", &update_values, py::arg("values"),
           "set() for each key.path: value of a dict, the scene read once for all of them; a "
           "bad one raises SceneError and leaves the scene unchanged.")
      .def("override", &add_overrides, py::arg("lines"),
           "Applies command-line --set lines, each \"key.path=value\" with the value as TOML (or "
           "a bare word), e.g. the `set` column of clothlab.tune's table split at spaces.")
      .def("get", &get_value, py::arg("key"),
           "The value at key.path: the file's or an override's, else the default.")
      .def("copy", [](const SceneSource& s) { return s; })
      .def("__copy__", [](const SceneSource& s) { return s; })
      .def("__deepcopy__", [](const SceneSource& s, py::dict) { return s; })
      .def_readonly("text", &SceneSource::text, "The TOML text as read.")
      .def_readonly("name", &SceneSource::name, "The scene file, or '<string>'.")
      .def_readonly("overrides", &SceneSource::overrides, "The key.path=value overrides, in order.")
      .def("__repr__",
           [](const SceneSource& s) {
             return "clothlab.Scene(" + s.name + ", " + std::to_string(s.overrides.size()) +
                    " override(s))";
           })
      .def(py::pickle(
          [](const SceneSource& s) { return py::make_tuple(s.text, s.name, s.overrides); },
          [](const py::tuple& t) {
            return SceneSource{t[0].cast<std::string>(), t[1].cast<std::string>(),
                               t[2].cast<std::vector<std::string>>()};
          }));
}

}  // namespace clothlab::py_bindings
