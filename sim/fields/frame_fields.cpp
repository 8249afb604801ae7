#include "sim/fields/frame_fields.hpp"

#include "sim/solver.hpp"
#include "sim/step_backend.hpp"

namespace clothlab {
namespace {

// `out` holds `solver`'s force field of `source`, 3 floats per vertex.
void copy_force(SolverState& solver, ForceSource source, std::vector<float>& out) {
  solver.update_force_field(source);
  out.resize(3 * solver.vertex_count());
  for (std::size_t v = 0; v < solver.vertex_count(); ++v) {
    const Vec3d f = solver.force(static_cast<int>(v));
    for (int k = 0; k < 3; ++k) out[3 * v + k] = static_cast<float>(f[k]);
  }
}

}  // namespace

const FrameFields& FieldSnapshot::take(Solver& solver, const FieldRequest& request) {
  FrameFields& f = fields_;
  const std::size_t n = solver.vertex_count();
  f.time = solver.time();
  f.vertices = n;
  f.positions.resize(3 * n);
  solver.copy_positions(f.positions.data());
  DeviceCloth* device = solver.device_cloth();
  f.device = device;
  if (device) device->update_normals();  // drawn from the device's buffers
  if (!device || request.normals) {
    f.normals.resize(3 * n);
    if (device)
      device->read_normals(f.normals.data());
    else
      solver.copy_normals(f.normals.data());
  } else {
    f.normals.clear();
  }
  if (request.velocities) {
    f.velocities.resize(3 * n);
    solver.copy_velocities(f.velocities.data());
  } else {
    f.velocities.clear();
  }
  for (std::size_t s = 0; s < kAllForceSources.size(); ++s) {
    if (request.forces[s])
      copy_force(solver, kAllForceSources[s], f.forces[s]);
    else
      f.forces[s].clear();
  }
  take_strain(solver, request);
  take_contact_gaps(solver, request);
  f.reference_distance.clear();  // this frame's comes from set_reference_distance
  return f;
}

void FieldSnapshot::set_reference_distance(const std::vector<float>& distance) {
  std::vector<float>& d = fields_.reference_distance;
  if (distance.size() == fields_.vertices)
    d.assign(distance.begin(), distance.end());
  else
    d.assign(fields_.vertices, 0.0f);
}

void FieldSnapshot::take_contact_gaps(const Solver& solver, const FieldRequest& request) {
  FrameFields& f = fields_;
  if (!request.contact_gaps) {
    f.contact_gap.clear();
    f.contact_range = 0.0;
    return;
  }
  if (!gaps_ || gaps_->vertex_count() != solver.vertex_count()) gaps_.emplace(solver);
  // Twice the thickness: layers that rest on each other at it show the map's middle.
  f.contact_range = 2.0 * solver.self_thickness();
  gaps_->per_vertex(f.positions, f.contact_range, solver.threads(), f.contact_gap);
}

void FieldSnapshot::take_strain(const SolverState& solver, const FieldRequest& request) {
  FrameFields& f = fields_;
  if (!request.spring_strain && !request.vertex_strain) {
    f.spring_strain.clear();
    f.vertex_strain.clear();
    return;
  }
  if (!strain_ || strain_->vertex_count() != solver.vertex_count()) strain_.emplace(solver);
  std::vector<float>& springs = request.spring_strain ? f.spring_strain : spring_scratch_;
  strain_->per_spring(f.positions, springs);
  if (!request.spring_strain) f.spring_strain.clear();
  if (request.vertex_strain)
    strain_->per_vertex(springs, f.vertex_strain);
  else
    f.vertex_strain.clear();
}

}  // namespace clothlab
