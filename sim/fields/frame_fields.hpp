// One frame's fields as the views read them. The application fills a FrameFields once per frame
// from the solver, with only what that frame's views ask for (a FieldRequest), and hands it to
// every pass, probe and legend: the renderer reads this snapshot and the solver's const state,
// never the mutable solver, and no field is copied out or computed twice in a frame
// (docs/design.md, "One field snapshot per frame").
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "sim/fields/contact_gaps.hpp"
#include "sim/fields/spring_strain.hpp"
#include "sim/forces/force_source.hpp"

namespace clothlab {

class DeviceCloth;
class Solver;
class SolverState;

// What a frame needs beyond the positions (which it always gets).
struct FieldRequest {
  std::array<bool, kAllForceSources.size()> forces{};  // per ForceSource, kAllForceSources order
  bool velocities = false;
  bool normals = false;        // on the CPU (always there for a CPU solver: the cloth draws them)
  bool spring_strain = false;  // each spring's strain
  bool vertex_strain = false;  // the mean strain of the springs at each vertex
  bool contact_gaps = false;   // how near each vertex comes to other cloth (ContactGaps)

  void add_force(ForceSource source) { forces[static_cast<std::size_t>(source)] = true; }
};

struct FrameFields {
  double time = 0.0;  // s, the solver's clock
  std::size_t vertices = 0;
  std::vector<float> positions;   // 3 floats per vertex
  std::vector<float> normals;     // unit area-weighted, 3 per vertex; on a device: when requested
  std::vector<float> velocities;  // 3 per vertex, when requested
  std::array<std::vector<float>, kAllForceSources.size()> forces;  // 3 per vertex, requested ones
  std::vector<float> spring_strain;  // per spring (SolverState::spring_pairs() order)
  std::vector<float> vertex_strain;  // per vertex
  // Per vertex, when requested: its gap to other cloth (m), at most contact_range (twice the
  // solver's self_thickness); NaN where an edge crosses a triangle (sim/fields/contact_gaps.hpp).
  std::vector<float> contact_gap;
  double contact_range = 0.0;
  // Per vertex, m: the distance from the window's live reference run (tune/live_reference.hpp),
  // handed in by the window (set_reference_distance), never computed from the solver.
  std::vector<float> reference_distance;
  // The GPU backend's buffers, whose normals are up to date with `positions`; null on the CPU.
  const DeviceCloth* device = nullptr;

  bool has_force(ForceSource source) const {
    return vertices > 0 && force(source).size() == 3 * vertices;
  }
  const std::vector<float>& force(ForceSource source) const {
    return forces[static_cast<std::size_t>(source)];
  }
};

// Takes the snapshots of one solver. A field not requested is left empty (its memory kept). It
// allocates only when a field is first asked for or the vertex count changes: a frame that
// keeps its request reuses every buffer.
class FieldSnapshot {
 public:
  // Fills fields() from `solver`'s current state. The solver computes what is derived from the
  // state (force fields, normals) and is otherwise unchanged: its positions, velocities and
  // clock stay as they were.
  const FrameFields& take(Solver& solver, const FieldRequest& request);
  const FrameFields& fields() const { return fields_; }
  // The live reference's distance of each vertex for this frame: `distance` when it has one per
  // vertex, else zeros (before the first comparison). Allocates only when the count changes.
  void set_reference_distance(const std::vector<float>& distance);
  // Forgets the springs' topology: call when the solver was rebuilt with other springs.
  void forget_topology() {
    strain_.reset();
    gaps_.reset();
  }

 private:
  void take_strain(const SolverState& solver, const FieldRequest& request);
  void take_contact_gaps(const Solver& solver, const FieldRequest& request);

  FrameFields fields_;
  std::optional<SpringStrain> strain_;  // built on the first strain request
  std::optional<ContactGaps> gaps_;     // built on the first contact-gap request
  std::vector<float> spring_scratch_;   // per-spring strain when only the vertex mean is asked
};

}  // namespace clothlab
