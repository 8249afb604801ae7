#include "sim/fields/spring_strain.hpp"

#include <algorithm>
#include <cmath>

#include "sim/solver.hpp"

namespace clothlab {
namespace {

float distance(const float* xyz, int a, int b) {
  const float* p = xyz + 3 * std::size_t(a);
  const float* q = xyz + 3 * std::size_t(b);
  const float d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

}  // namespace

SpringStrain::SpringStrain(const SolverState& solver)
    : springs_(solver.spring_pairs()),
      rest_length_(springs_.size()),
      inv_degree_(solver.vertex_count(), 0.0f) {
  std::vector<float> rest(3 * solver.vertex_count());
  solver.copy_rest_positions(rest.data());
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const auto [a, b] = springs_[s];
    rest_length_[s] = distance(rest.data(), a, b);
    inv_degree_[std::size_t(a)] += 1.0f;
    inv_degree_[std::size_t(b)] += 1.0f;
  }
  for (float& d : inv_degree_) d = d > 0.0f ? 1.0f / d : 0.0f;
}

void SpringStrain::per_spring(const std::vector<float>& xyz, std::vector<float>& out) const {
  out.resize(springs_.size());
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const float l0 = rest_length_[s];
    out[s] = l0 > 0.0f ? (distance(xyz.data(), springs_[s][0], springs_[s][1]) - l0) / l0 : 0.0f;
  }
}

void SpringStrain::per_vertex(const std::vector<float>& spring_strain,
                              std::vector<float>& out) const {
  out.assign(inv_degree_.size(), 0.0f);
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    out[std::size_t(springs_[s][0])] += spring_strain[s];
    out[std::size_t(springs_[s][1])] += spring_strain[s];
  }
  for (std::size_t v = 0; v < out.size(); ++v) out[v] *= inv_degree_[v];
}

}  // namespace clothlab
