#include "vis/render/scalar_field.hpp"

#include <algorithm>
#include <cmath>

#include "sim/solver.hpp"

namespace clothlab::vis {
namespace {

struct FieldInfo {
  ScalarField field;
  std::string_view name, unit, title;
};
constexpr std::array<FieldInfo, 5> kFields{{
    {ScalarField::none, "none", "", ""},
    {ScalarField::force, "force", "N", "|force|"},
    {ScalarField::speed, "speed", "m/s", "|velocity|"},
    {ScalarField::strain, "strain", "", "strain (l-l0)/l0"},
    {ScalarField::height, "height", "m", "height"},
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

ScalarFieldSampler::ScalarFieldSampler(const SolverState& solver)
    : springs_(solver.spring_pairs()),
      rest_length_(springs_.size()),
      inv_degree_(solver.vertex_count(), 0.0f),
      xyz_(3 * solver.vertex_count()) {
  solver.copy_rest_positions(xyz_.data());
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const auto [a, b] = springs_[s];
    float d[3];
    for (int k = 0; k < 3; ++k) d[k] = xyz_[3 * std::size_t(b) + k] - xyz_[3 * std::size_t(a) + k];
    rest_length_[s] = length3(d);
    inv_degree_[std::size_t(a)] += 1.0f;
    inv_degree_[std::size_t(b)] += 1.0f;
  }
  for (float& d : inv_degree_) d = d > 0.0f ? 1.0f / d : 0.0f;
}

void ScalarFieldSampler::compute(SolverState& solver, ScalarField field, ForceSource source,
                                 std::vector<float>& out) {
  const std::size_t n = solver.vertex_count();
  out.resize(n);
  switch (field) {
    case ScalarField::none:
      std::fill(out.begin(), out.end(), 0.0f);
      return;
    case ScalarField::force:
      solver.update_force_field(source);
      for (std::size_t v = 0; v < n; ++v) {
        const Vec3d f = solver.force(static_cast<int>(v));
        out[v] = static_cast<float>(std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
      }
      return;
    case ScalarField::speed:
      solver.copy_velocities(xyz_.data());
      for (std::size_t v = 0; v < n; ++v) out[v] = length3(&xyz_[3 * v]);
      return;
    case ScalarField::height:
      solver.copy_positions(xyz_.data());
      for (std::size_t v = 0; v < n; ++v) out[v] = xyz_[3 * v + 1];
      return;
    case ScalarField::strain:
      solver.copy_positions(xyz_.data());
      std::fill(out.begin(), out.end(), 0.0f);
      for (std::size_t s = 0; s < springs_.size(); ++s) {
        const auto [a, b] = springs_[s];
        float d[3];
        for (int k = 0; k < 3; ++k)
          d[k] = xyz_[3 * std::size_t(b) + k] - xyz_[3 * std::size_t(a) + k];
        const float strain =
            rest_length_[s] > 0.0f ? (length3(d) - rest_length_[s]) / rest_length_[s] : 0.0f;
        out[std::size_t(a)] += strain;
        out[std::size_t(b)] += strain;
      }
      for (std::size_t v = 0; v < n; ++v) out[v] *= inv_degree_[v];
      return;
  }
}

}  // namespace clothlab::vis
