// Engineering strain of the springs, e = (l - l0) / l0 with l0 a spring's built length (the seed
// rule's rest length), per spring and as the mean over the springs that end at each vertex: the
// strain views' scalar (mode 1's line colours and range, colour by strain).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace clothlab {

class SolverState;

class SpringStrain {
 public:
  // The springs and built lengths of `solver`'s topology (rebuild after a reset that changes it).
  explicit SpringStrain(const SolverState& solver);

  std::size_t vertex_count() const { return inv_degree_.size(); }
  std::size_t spring_count() const { return rest_length_.size(); }

  // Each spring's strain at `xyz` (3 floats per vertex), in SolverState::spring_pairs() order; 0
  // for a spring of zero built length. Allocates nothing once `out` has spring_count().
  void per_spring(const std::vector<float>& xyz, std::vector<float>& out) const;
  // The mean of per_spring()'s values over the springs at each vertex (0 where none ends).
  void per_vertex(const std::vector<float>& spring_strain, std::vector<float>& out) const;

 private:
  std::vector<std::array<int, 2>> springs_;
  std::vector<float> rest_length_;  // per spring, m
  std::vector<float> inv_degree_;   // per vertex, 1 / springs ending there (0 for none)
};

}  // namespace clothlab
