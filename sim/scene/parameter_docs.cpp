// Lookups in the parameter table and its text: paths, key lists, ranges in words and the
// Markdown table `clothlab params` prints.
#include <string>

#include "sim/scene/name_list.hpp"
#include "sim/scene/parameters.hpp"
#include "sim/scene/scene_error.hpp"

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

// Records are designated initializers that leave the fields they do not name at their
// defaults; GCC 12's -Wextra warns about every such field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace clothlab {
namespace {

bool has_child(const Parameter& p) {
  return p.kind == ValueKind::table || p.kind == ValueKind::tables ||
         (p.kind == ValueKind::special && p.child != Section::top);
}

std::string type_words(const Parameter& p) {
  switch (p.kind) {
    case ValueKind::number:
      return "number";
    case ValueKind::integer:
      return "integer";
    case ValueKind::boolean:
      return "boolean";
    case ValueKind::text:
      return p.choices.empty() ? "string" : "string: " + std::string(p.choices);
    case ValueKind::choice:
      return "one of " + std::string(p.choices);
    case ValueKind::numbers:
      return std::to_string(p.count) + " numbers";
    case ValueKind::integers:
      return std::to_string(p.count) + " integers";
    case ValueKind::table:
      return "table";
    case ValueKind::tables:
      return "array of tables";
    case ValueKind::special:
      return std::string(p.form) + (p.choices.empty() ? "" : ": " + std::string(p.choices));
  }
  return "";
}

// Markdown cells hold no bare '|'.
std::string cell(std::string text) {
  for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2))
    text.replace(at, 1, "\\|");
  return text;
}

}  // namespace

std::string section_path(Section section) {
  if (section == Section::top) return "";
  for (const Parameter& p : parameters())
    if (has_child(p) && p.child == section) return parameter_path(p);
  return "";
}

std::string parameter_path(const Parameter& p) {
  const std::string parent = section_path(p.section);
  return parent.empty() ? std::string(p.name) : parent + "." + std::string(p.name);
}

const Parameter* find_parameter(Section section, std::string_view name) {
  for (const Parameter& p : parameters())
    if (p.section == section && p.name == name) return &p;
  return nullptr;
}

std::string_view choice_name(const Parameter& p, int n) {
  return list_item(p.choices, n);
}

bool applies_to(const Parameter& p, std::string_view integrator) {
  return p.only_for.empty() || listed(p.only_for, integrator);
}

std::string key_list(Section section) {
  std::string text;
  for (const Parameter& p : parameters())
    if (p.section == section) add_to_list(text, p.name);
  return text;
}

std::string range_words(const Parameter& p) {
  if (!p.range_text.empty()) return std::string(p.range_text);
  const Range& r = p.range;
  if (!r.bounded()) return "";
  const std::string lo = format_number(r.lo), hi = format_number(r.hi);
  if (r.lo != -Range::kInf && r.hi != Range::kInf) {
    if (!r.lo_open && !r.hi_open) return "between " + lo + " and " + hi;
    if (r.lo_open && r.hi_open) return "between " + lo + " and " + hi + ", exclusive";
    return std::string(r.lo_open ? "> " : ">= ") + lo + ", " + (r.hi_open ? "< " : "<= ") + hi;
  }
  if (r.hi == Range::kInf) return std::string(r.lo_open ? "> " : ">= ") + lo;
  return std::string(r.hi_open ? "< " : "<= ") + hi;
}

std::string parameters_markdown() {
  std::string out =
      "| key | type | valid | default | unit | meaning |\n"
      "| --- | --- | --- | --- | --- | --- |\n";
  for (const Parameter& p : parameters()) {
    std::string valid = range_words(p);
    if (!p.only_for.empty())
      valid += std::string(valid.empty() ? "" : "; ") + "only " + std::string(p.only_for);
    if (!p.required.empty()) valid += std::string(valid.empty() ? "" : "; ") + "required";
    out += "| `" + parameter_path(p) + "` | " + cell(type_words(p)) + " | " + cell(valid) + " | " +
           cell(std::string(p.fallback)) + " | " + cell(std::string(p.unit)) + " | " +
           cell(std::string(p.description)) + " |\n";
  }
  return out;
}

}  // namespace clothlab
