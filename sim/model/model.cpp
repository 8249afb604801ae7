#include "sim/model/model.hpp"

#include <algorithm>

#include "sim/cloth/build_cloth.hpp"
#include "sim/cloth/grid_cloth.hpp"
#include "sim/cloth/mesh_cloth.hpp"
#include "sim/cloth/tube_cloth.hpp"

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
void fill_neighbour_table(Model<T>& m, const std::vector<Spring>& springs,
                          const std::vector<double>& damping) {
  const auto links = links_per_vertex(m.n, springs, damping);
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
      } else {
        m.neighbour[e] = static_cast<std::int32_t>(i);
      }
    }
  }
}

template <class T>
GridStencil<T> grid_stencil(const GridCloth& g, int offset, const SpringSpec& spec) {
  GridStencil<T> st;
  st.offset = offset;
  st.nu = g.nu;
  st.nv = g.nv;
  for (const GridOffset& o : seed_stencil_half(g, SpringStiffness::of(spec))) {
    for (int sign : {-1, 1}) {
      typename GridStencil<T>::Entry e;
      e.di = sign * o.di;
      e.dj = sign * o.dj;
      e.shift = e.di + static_cast<long>(e.dj) * g.nu;
      e.stiffness = static_cast<T>(o.stiffness);
      e.rest_length = static_cast<T>(o.rest_length);
      e.damping = static_cast<T>(spec.damping);
      e.first_half = sign > 0;
      st.entries.push_back(e);
    }
  }
  std::sort(st.entries.begin(), st.entries.end(),
            [](const auto& a, const auto& b) { return a.shift < b.shift; });
  return st;
}

template <class T>
void fill_incident_triangles(Model<T>& m) {
  std::vector<std::vector<std::int32_t>> around(m.n);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int v : m.triangles[t])
      around[static_cast<std::size_t>(v)].push_back(static_cast<std::int32_t>(t));
  std::size_t slots = 0;
  for (const auto& a : around) slots = std::max(slots, a.size());
  m.incident_slots = static_cast<int>(slots);
  const auto dummy = static_cast<std::int32_t>(m.triangles.size());
  m.incident_triangle.assign(slots * m.n, dummy);
  for (std::size_t i = 0; i < m.n; ++i)
    for (std::size_t s = 0; s < around[i].size(); ++s)
      m.incident_triangle[s * m.n + i] = around[i][s];
}

}  // namespace

template <class T>
Model<T> build_model(const Scene& scene, SpringKernel kernel) {
  Model<T> m;
  // The row sweep walks a grid's rows; a tube's springs cross its seam, so a scene with one
  // takes the neighbour list (the kernel for any topology).
  for (const ClothSpec& c : scene.cloths)
    if (c.shape == "tube" || c.shape == "mesh") kernel = SpringKernel::neighbour_list;
  m.kernel = kernel;
  std::vector<Spring> springs;  // neighbour_list only: 24 bytes a spring
  std::vector<double> spring_damping;
  std::vector<Vec3d> positions;
  std::vector<double> masses;
  for (std::size_t c = 0; c < scene.cloths.size(); ++c) {
    const std::string& shape = scene.cloths[c].shape;
    const GridCloth g = build_cloth(scene.cloths[c]);
    const SpringSpec& spec = scene.springs_of(c);
    const int offset = static_cast<int>(positions.size());
    m.cloths.push_back({offset, g.nu, g.nv, g.wrap_u, g.mesh});
    positions.insert(positions.end(), g.positions.begin(), g.positions.end());
    if (g.masses.empty())
      masses.insert(masses.end(), g.positions.size(), g.vertex_mass);
    else
      masses.insert(masses.end(), g.masses.begin(), g.masses.end());
    for (int p : g.pinned) m.pinned.push_back(offset + p);
    m.has_damping = m.has_damping || spec.damping != 0.0;
    const SpringStiffness k = SpringStiffness::of(spec);
    if (kernel == SpringKernel::row_sweep) {
      m.grids.push_back(grid_stencil<T>(g, offset, spec));
      for (const GridOffset& o : seed_stencil_half(g, k))
        m.spring_count +=
            static_cast<std::size_t>(g.nu - std::abs(o.di)) * static_cast<std::size_t>(g.nv - o.dj);
    } else {
      const std::vector<Spring> cloth_springs = shape == "tube"   ? seed_springs_tube(g, k)
                                                : shape == "mesh" ? mesh_springs(g, k)
                                                                  : seed_springs_grid(g, k);
      for (Spring s : cloth_springs) {
        s.a += offset;
        s.b += offset;
        springs.push_back(s);
        spring_damping.push_back(spec.damping);
      }
      m.spring_count = springs.size();
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

  if (kernel == SpringKernel::neighbour_list) fill_neighbour_table(m, springs, spring_damping);
  fill_incident_triangles(m);
  for (int a = 0; a < 3; ++a) m.gravity[a] = static_cast<T>(scene.forces.gravity[a]);
  m.drag = static_cast<T>(scene.forces.drag);
  m.wind = scene.forces.wind;
  return m;
}

template <class T>
SpringList<T> spring_list(const Model<T>& m) {
  SpringList<T> list;
  list.ends.reserve(m.spring_count);
  auto add = [&](int a, int b, T k, T rest, T c) {
    list.ends.push_back({a, b});
    list.stiffness.push_back(k);
    list.rest_length.push_back(rest);
    list.damping.push_back(c);
  };
  for (const GridStencil<T>& g : m.grids) {
    for (int j = 0; j < g.nv; ++j) {
      for (int i = 0; i < g.nu; ++i) {
        for (const auto& e : g.entries) {
          if (!e.first_half || i + e.di < 0 || i + e.di >= g.nu || j + e.dj >= g.nv) continue;
          const int a = g.offset + i + j * g.nu;
          add(a, a + static_cast<int>(e.shift), e.stiffness, e.rest_length, e.damping);
        }
      }
    }
  }
  for (std::size_t i = 0; i < m.n && m.kernel == SpringKernel::neighbour_list; ++i) {
    for (int s = 0; s < m.slots; ++s) {
      const std::size_t k = static_cast<std::size_t>(s) * m.n + i;
      const int j = m.neighbour[k];
      if (static_cast<std::size_t>(j) > i && m.stiffness[k] != T(0))
        add(static_cast<int>(i), j, m.stiffness[k], m.rest_length[k], m.damping[k]);
    }
  }
  return list;
}

template <class T>
std::vector<std::array<int, 2>> spring_pairs(const Model<T>& m) {
  return spring_list(m).ends;
}

template SpringList<float> spring_list<float>(const Model<float>&);
template SpringList<double> spring_list<double>(const Model<double>&);
template std::vector<std::array<int, 2>> spring_pairs<float>(const Model<float>&);
template std::vector<std::array<int, 2>> spring_pairs<double>(const Model<double>&);

template Model<float> build_model<float>(const Scene&, SpringKernel);
template Model<double> build_model<double>(const Scene&, SpringKernel);

}  // namespace clothlab
