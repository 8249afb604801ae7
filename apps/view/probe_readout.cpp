#include "apps/view/probe_readout.hpp"

#include <cmath>
#include <cstdio>

namespace clothlab::vis {
namespace {

const char* unit_of(Field field) {
  return field == Field::force ? "N" : field == Field::velocity ? "m/s" : "m";
}

std::string vertex_name(const SolverState& solver, int vertex) {
  const VertexRef ref = solver.vertex_ref(vertex);
  char name[64];
  if (solver.cloths().size() > 1)
    std::snprintf(name, sizeof name, "cloth %d (%d, %d)", ref.cloth, ref.i, ref.j);
  else
    std::snprintf(name, sizeof name, "(%d, %d)", ref.i, ref.j);
  return name;
}

}  // namespace

ProbeReadout probe_readout(Field field, SolverState& solver, const std::optional<ProbeSample>& s,
                           int vertex, bool pinned, int px, int py) {
  const char* name = field_name(field);
  const char* unit = unit_of(field);
  // The frame's snapshot computed the total force for the probe; a source computed after it
  // (the arrows' springs) may have replaced it in the solver since.
  if (field == Field::force && solver.force_field_source() != ForceSource::total)
    solver.update_force_field();
  const Vec3d n = field == Field::force      ? solver.force(vertex)
                  : field == Field::velocity ? solver.velocity(vertex)
                                             : solver.position(vertex);
  const std::string where = vertex_name(solver, vertex);
  double magnitude = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  ProbeReadout r;
  char line[160];
  if (s) {
    const glm::vec3 v = s->value(field);
    magnitude = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    std::snprintf(line, sizeof line, "%s (%s) at pixel (%d, %d)\n", name, unit, px, py);
    r.text = line;
    std::snprintf(line, sizeof line, "  x %+.4e\n  y %+.4e\n  z %+.4e\n  magnitude %.4e %s\n", v.x,
                  v.y, v.z, magnitude, unit);
    r.text += line;
  } else {
    r.text = std::string(name) + " (" + unit + "): pinned vertex hidden or off screen\n";
  }
  std::snprintf(line, sizeof line, "%s vertex %s\n",
                pinned ? "pinned (click off the cloth unpins)" : "nearest", where.c_str());
  r.text += line;
  std::snprintf(line, sizeof line, "  nodal (%+.4e, %+.4e, %+.4e) %s", n[0], n[1], n[2], unit);
  r.text += line;
  std::snprintf(line, sizeof line, "%s %.3e %s at %s%s", name, magnitude, unit, where.c_str(),
                pinned ? " (pinned)" : "");
  r.title = line;
  return r;
}

}  // namespace clothlab::vis
