#include "vis/render/scalar_field.hpp"

#include <algorithm>
#include <cmath>

#include "sim/fields/frame_fields.hpp"
#include "vis/render/frame_request.hpp"

namespace clothlab::vis {
namespace {

struct FieldInfo {
  ScalarField field;
  std::string_view name, unit, title;
};
constexpr std::array<FieldInfo, 7> kFields{{
    {ScalarField::none, "none", "", ""},
    {ScalarField::force, "force", "N", "|force|"},
    {ScalarField::speed, "speed", "m/s", "|velocity|"},
    {ScalarField::strain, "strain", "", "strain (l-l0)/l0"},
    {ScalarField::height, "height", "m", "height"},
    {ScalarField::contact, "contact", "m", "gap to cloth (magenta: crossed)"},
    {ScalarField::error, "error", "mm", "distance from the reference"},
}};

const FieldInfo& info(ScalarField field) {
  return kFields[static_cast<std::size_t>(field)];
}

float length3(const float* v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

std::string_view scalar_field_name(ScalarField field) {
  return info(field).name;
}
std::string_view scalar_field_unit(ScalarField field) {
  return info(field).unit;
}
std::string_view scalar_field_title(ScalarField field) {
  return info(field).title;
}
bool scalar_field_signed(ScalarField field) {
  return field == ScalarField::strain;
}

std::optional<ScalarField> parse_scalar_field(std::string_view name) {
  for (const FieldInfo& f : kFields)
    if (f.name == name) return f.field;
  return std::nullopt;
}

void scalar_values(const FrameFields& fields, ScalarField field, ForceSource source,
                   std::vector<float>& out) {
  const std::size_t n = fields.vertices;
  out.resize(n);
  switch (field) {
    case ScalarField::none:
      std::fill(out.begin(), out.end(), 0.0f);
      return;
    case ScalarField::force:
      require_field(fields.force(source), 3 * n, "the coloured force");
      for (std::size_t v = 0; v < n; ++v) out[v] = length3(&fields.force(source)[3 * v]);
      return;
    case ScalarField::speed:
      require_field(fields.velocities, 3 * n, "velocities");
      for (std::size_t v = 0; v < n; ++v) out[v] = length3(&fields.velocities[3 * v]);
      return;
    case ScalarField::height:
      for (std::size_t v = 0; v < n; ++v) out[v] = fields.positions[3 * v + 1];
      return;
    case ScalarField::strain:
      require_field(fields.vertex_strain, n, "the vertices' strain");
      std::copy(fields.vertex_strain.begin(), fields.vertex_strain.end(), out.begin());
      return;
    case ScalarField::contact:
      require_field(fields.contact_gap, n, "the contact gaps");
      std::copy(fields.contact_gap.begin(), fields.contact_gap.end(), out.begin());
      return;
    case ScalarField::error:  // in mm: cloth errors of interest are millimetres to centimetres
      require_field(fields.reference_distance, n, "the distances from the reference");
      for (std::size_t v = 0; v < n; ++v) out[v] = 1e3f * fields.reference_distance[v];
      return;
  }
}

}  // namespace clothlab::vis
