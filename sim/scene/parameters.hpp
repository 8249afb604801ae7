// The scene's parameter table: one record per scene-file key (its path, type, range, unit,
// default, group, panel widget and a one-line description). The parser reads every key through
// it, validate_scene checks its ranges, the window's panel builds its editors from it and
// `clothlab params` prints it (the key table in docs/scene-format.md is that output). A new
// parameter is one record in parameters.cpp plus its member in the Scene's structs. See
// docs/scene-format.md.
#pragma once

#include <limits>
#include <span>
#include <string>
#include <string_view>

namespace clothlab {

struct Scene;
class TomlReader;  // sim/scene/toml_reader.hpp

// The tables a scene file has, each read into one struct of scene.hpp (Section::cloth into a
// ClothSpec, Section::wind into a WindSpec, ...). A section may appear under several paths
// (Section::springs is [springs] and cloth.springs; Section::friction is colliders.friction and
// mannequin.friction).
enum class Section {
  top,
  cloth,
  springs,
  forces,
  wind,
  solver,
  trace,
  render,
  light,
  sky,
  pole,
  mesh,
  look,
  camera,
  collider,
  friction,
  motion,
  keyframe,
  music,
  mannequin,
};

enum class ValueKind {
  number,   // a TOML integer or float
  integer,  // a TOML integer
  boolean,
  text,      // a free string (a file name)
  choice,    // one of `choices`
  numbers,   // `count` numbers
  integers,  // `count` integers
  table,     // a sub-table, read into `child`
  tables,    // an array of tables ([[colliders]]), each read into `child`
  special,   // a form of its own, told by `form`
};

// A closed or open interval for a number, or for each element of an array. The default is
// (-inf, inf): finite only.
struct Range {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  double lo = -kInf, hi = kInf;
  bool lo_open = false, hi_open = false;  // true: the bound itself is outside
  bool bounded() const { return lo != -kInf || hi != kInf; }
  bool contains(double x) const {
    return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  }
};

// How the window's panel edits a parameter (none: not in the panel).
enum class Widget { none, input, log_slider, combo, step, substeps };

struct Parameter {
  Section section = Section::top;  // the table the key belongs to
  std::string_view name;           // the key in its table: "cg_tolerance"
  ValueKind kind = ValueKind::number;
  int count = 1;                 // numbers / integers: elements
  Range range;                   // checked by validate_scene; for arrays, on each element
  std::string_view range_text;   // the range in words where "between lo and hi" is not enough
  std::string_view unit;         // "m", "N/m", "s" ("" for a pure number)
  std::string_view fallback;     // the default, as written in a scene file ("" when required)
  std::string_view form;         // special: what the value looks like
  std::string_view choices;      // choice: the valid names, "a, b, c"
  Section child = Section::top;  // table / tables: the section each is read into
  std::string_view only_for;     // integrators it applies to ("implicit_euler"); "" = all
  Widget widget = Widget::none;  // the panel's editor
  Range ui;                      // the panel's slider or clamp range (inside `range`)
  std::string_view description;  // one line
  bool whole_key = false;        // range errors name the array, not its element
  std::string_view required;     // non-empty: the key must be given; the reason, in words
  bool optional = false;         // the member is a std::optional: absent until given (the
                                 // fallback then names the key whose value it takes, if any)

  // The binding to the section's struct (filled by the table's helpers in parameters.cpp).
  // read: the value at reader.node() into the struct; values: the numbers validate_scene checks
  // (at most 3; 0 when the value is absent or not checked); address: the member (panel editors).
  void (*read)(TomlReader& reader, void* object) = nullptr;
  int (*values)(const void* object, double* out) = nullptr;
  void* (*address)(void* object) = nullptr;
  // text values: the string (validate_scene checks it against `choices`).
  const std::string* (*text)(const void* object) = nullptr;
  // choice (and the integrator): the value's place in `choices`, and setting it by place.
  int (*choice_index)(const void* object) = nullptr;
  void (*choose)(void* object, int index) = nullptr;
};

// True when p applies to the integrator named `integrator` (p.only_for lists it, or is empty).
bool applies_to(const Parameter& p, std::string_view integrator);

// The n-th name of p.choices ("" past the end).
std::string_view choice_name(const Parameter& p, int n);

// Every record, in the order of `clothlab params` (by section, then as a file lists them).
std::span<const Parameter> parameters();

// The canonical path of a section ("render.light", "colliders"; "" for the top level) and of a
// record ("render.light.intensity").
std::string section_path(Section section);
std::string parameter_path(const Parameter& p);

// The record of key `name` in `section`, or null.
const Parameter* find_parameter(Section section, std::string_view name);

// The key names of a section, "a, b, c", in table order (for "unknown key" messages).
std::string key_list(Section section);

// The range in words, as validate_scene's messages and the key table say it:
// "> 0", ">= 0", "between 0 and 1, exclusive", "between 1 and 100000".
std::string range_words(const Parameter& p);

// `clothlab params`: the table in Markdown, one row per key (path, type, range, default, unit,
// description), as the key table in docs/scene-format.md holds it.
std::string parameters_markdown();

}  // namespace clothlab
