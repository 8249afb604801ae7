// The total force on every vertex: springs, gravity, linear drag and wind.
#pragma once

#include "sim/forces/force_source.hpp"
#include "sim/forces/grid_spring_forces.hpp"
#include "sim/forces/grid_surface.hpp"
#include "sim/model/model.hpp"

namespace clothlab {

// Scratch space for a force evaluation, allocated once so the step loop never allocates.
template <class T>
struct ForceWorkspace {
  // Per triangle, plus one zero dummy at the end for the padded incidence table.
  Vec3Array<T> face_cross;     // (b - a) x (c - a): twice the area times the normal
  AlignedVector<T> face_area;  // m^2
  // Per vertex: unit area-weighted normal and a third of the surrounding area (m^2).
  Vec3Array<T> normal;
  AlignedVector<T> vertex_area;
  AlignedVector<T> gust_factor;          // the wind's (1 + gust g) at each vertex
  std::vector<GridFaces<T>> grid_faces;  // row-sweep kernel: per grid cloth
  std::vector<GridBands<T>> grid_bands;  // row-sweep kernel: per grid cloth
  void resize(const Model<T>& m) {
    grid_faces.resize(m.grids.size());
    grid_bands.resize(m.grids.size());
    for (std::size_t c = 0; c < m.grids.size(); ++c) {
      grid_faces[c].resize(m.grids[c].nu, m.grids[c].nv);
      grid_bands[c].resize(m.grids[c]);
    }
    face_cross.resize(m.triangles.size() + 1);
    face_area.assign(m.triangles.size() + 1, T(0));
    normal.resize(m.n);
    vertex_area.assign(m.n, T(0));
    gust_factor.assign(m.n, T(0));
  }
};

// Whether the wind exerts a force on the model: enabled, not calm, and a surface to act on.
template <class T>
bool wind_acts(const Model<T>& m);

// f = F(t, x, v) on all vertices (pinned ones included: their force is the support reaction).
template <class T>
void compute_forces(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                    Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads);

// f = gravity + drag + wind only (no springs): the external force of the constraint and
// local/global integrators, which treat the springs themselves.
template <class T>
void compute_external_forces(const Model<T>& m, double t, const Vec3Array<T>& x,
                             const Vec3Array<T>& v, Vec3Array<T>& f, ForceWorkspace<T>& ws,
                             int threads);

// f = one source of F(t, x, v) alone, on all vertices (pinned ones included): total is
// compute_forces; springs the spring kernel of the model (Hooke plus along-spring damping);
// gravity m_i g; drag -drag v_i; wind the wind force (zero when the wind is off or calm).
// springs + gravity + drag + wind equals total up to round-off. For inspection (force display,
// probes, traces), not the step loop; allocates nothing once ws is sized.
template <class T>
void compute_force_source(const Model<T>& m, double t, const Vec3Array<T>& x, const Vec3Array<T>& v,
                          Vec3Array<T>& f, ForceWorkspace<T>& ws, int threads, ForceSource source);

// Fills ws.normal (unit, area-weighted) and ws.vertex_area for the positions x; used by the wind
// force and by renderers (Solver::copy_normals), so both see the same surface.
template <class T>
void compute_surface(const Model<T>& m, const Vec3Array<T>& x, ForceWorkspace<T>& ws, int threads);

// The same over the model's triangle list, whatever the kernel: the general path, and the
// reference the grid sweep is tested against.
template <class T>
void compute_surface_from_triangles(const Model<T>& m, const Vec3Array<T>& x, ForceWorkspace<T>& ws,
                                    int threads);

}  // namespace clothlab
