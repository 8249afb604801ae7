#include "sim/model/model.hpp"

#include <algorithm>

#include "sim/cloth/grid_cloth.hpp"

namespace clothlab {
namespace {

struct Link {
  int other;
  double rest, stiffness, damping;
};

// Per-vertex link lists sorted by neighbour index: a fixed gather order per vertex.
std::vector<std::vector<Link>> links_per_vertex(std::size_t n, const std::vector<Spring>& springs,
                                                const std::vector<double>& damping) {
  std::vector<std::vector<Link>> links(n);
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const Spring& sp = springs[s];
    links[static_cast<std::size_t>(sp.a)].push_back(
        {sp.b, sp.rest_length, sp.stiffness, damping[s]});
    links[static_cast<std::size_t>(sp.b)].push_back(
        {sp.a, sp.rest_length, sp.stiffness, damping[s]});
  }
  for (auto& l : links) {
    std::sort(l.begin(), l.end(), [](const Link& x, const Link& y) { return x.other < y.other; });
  }
  return links;
}

template <class T>
void fill_neighbour_table(Model<T>& m, const std::vector<double>& damping) {
  const auto links = links_per_vertex(m.n, m.springs, damping);
  std::size_t slots = 0;
  for (const auto& l : links) slots = std::max(slots, l.size());
  m.slots = static_cast<int>(slots);
  const std::size_t size = slots * m.n;
  m.neighbour.assign(size, 0);
  m.stiffness.assign(size, T(0));
  m.rest_length.assign(size, T(0));
  m.damping.assign(size, T(0));
  for (std::size_t i = 0; i < m.n; ++i) {
    for (std::size_t s = 0; s < slots; ++s) {
      const std::size_t e = s * m.n + i;
      if (s < links[i].size()) {
        const Link& l = links[i][s];
        m.neighbour[e] = l.other;
        m.stiffness[e] = static_cast<T>(l.stiffness);
        m.rest_length[e] = static_cast<T>(l.rest);
        m.damping[e] = static_cast<T>(l.damping);
        m.has_damping = m.has_damping || l.damping != 0.0;
      } else {
        m.neighbour[e] = static_cast<std::int32_t>(i);
      }
    }
  }
}

template <class T>
void fill_incident_triangles(Model<T>& m) {
  m.incident_offset.assign(m.n + 1, 0);
  for (const auto& t : m.triangles)
    for (int v : t) ++m.incident_offset[static_cast<std::size_t>(v) + 1];
  for (std::size_t i = 0; i < m.n; ++i) m.incident_offset[i + 1] += m.incident_offset[i];
  m.incident_triangle.assign(static_cast<std::size_t>(m.incident_offset[m.n]), 0);
  std::vector<int> fill(m.incident_offset.begin(), m.incident_offset.end() - 1);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int v : m.triangles[t])
      m.incident_triangle[static_cast<std::size_t>(fill[v]++)] = static_cast<int>(t);
}

}  // namespace

template <class T>
Model<T> build_model(const Scene& scene) {
  Model<T> m;
  std::vector<double> spring_damping;
  std::vector<Vec3d> positions;
  std::vector<double> masses;
  for (std::size_t c = 0; c < scene.cloths.size(); ++c) {
    const GridCloth g = build_grid_cloth(scene.cloths[c]);
    const SpringSpec& spec = scene.springs_of(c);
    const int offset = static_cast<int>(positions.size());
    m.cloths.push_back({offset, g.nu, g.nv});
    positions.insert(positions.end(), g.positions.begin(), g.positions.end());
    masses.insert(masses.end(), g.positions.size(), g.vertex_mass);
    for (int p : g.pinned) m.pinned.push_back(offset + p);
    for (Spring s : seed_springs_grid(g, spec.stiffness)) {
      s.a += offset;
      s.b += offset;
      m.springs.push_back(s);
      spring_damping.push_back(spec.damping);
    }
    for (auto t : g.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }

  m.n = positions.size();
  m.mass.resize(m.n);
  m.inv_mass.resize(m.n);
  m.rest_positions.resize(m.n);
  for (std::size_t i = 0; i < m.n; ++i) {
    m.mass[i] = static_cast<T>(masses[i]);
    m.inv_mass[i] = static_cast<T>(1.0 / masses[i]);
    m.rest_positions.set(i, static_cast<T>(positions[i][0]), static_cast<T>(positions[i][1]),
                         static_cast<T>(positions[i][2]));
  }
  for (int p : m.pinned) m.inv_mass[static_cast<std::size_t>(p)] = T(0);

  fill_neighbour_table(m, spring_damping);
  fill_incident_triangles(m);
  for (int a = 0; a < 3; ++a) m.gravity[a] = static_cast<T>(scene.forces.gravity[a]);
  m.drag = static_cast<T>(scene.forces.drag);
  m.wind = scene.forces.wind;
  return m;
}

template Model<float> build_model<float>(const Scene&);
template Model<double> build_model<double>(const Scene&);

}  // namespace clothlab
