#include "vis/render/cloth_layout.hpp"

#include <algorithm>

#include "sim/solver.hpp"
#include "vis/textures/planar_uv.hpp"

namespace clothlab::vis {
namespace {

// A tube's seam copies: column 0 once more per row, appended after the solver's vertices so
// these keep their indices (springs, scalars and probes need no mapping). Returns the render
// index of each cloth's row-0 copy.
std::vector<std::size_t> add_seam_copies(ClothLayout& l) {
  std::vector<std::size_t> first_copy(l.cloths.size(), 0);
  for (std::size_t k = 0; k < l.cloths.size(); ++k) {
    const ClothRange& c = l.cloths[k];
    first_copy[k] = l.vertices + l.seam_copies.size();
    if (c.wrap_u)
      for (int j = 0; j < c.nv; ++j) l.seam_copies.push_back(c.offset + j * c.nu);
  }
  return first_copy;
}

// UVs of the grid and tube cloths (mesh cloths: planar, with their spans into `longest`), the
// seam copies' rest positions.
void set_uvs(ClothLayout& l, const std::vector<std::size_t>& first_copy, glm::vec2& longest) {
  const std::size_t rn = l.render_vertices();
  float* fixed = l.fixed.data();
  for (std::size_t k = 0; k < l.cloths.size(); ++k) {
    const ClothRange& c = l.cloths[k];
    if (c.mesh) {
      longest = glm::max(longest, planar_uvs(fixed + 2 * rn, c.offset, c.offset + c.nu, fixed));
      continue;
    }
    const float u_steps = c.wrap_u ? float(c.nu) : float(c.nu - 1);
    for (int j = 0; j < c.nv; ++j) {
      const float v_coord = c.nv > 1 ? float(j) / float(c.nv - 1) : 0.0f;
      for (int i = 0; i < c.nu; ++i) {
        const std::size_t v = static_cast<std::size_t>(c.offset + i + j * c.nu);
        fixed[2 * v] = c.nu > 1 ? float(i) / u_steps : 0.0f;
        fixed[2 * v + 1] = v_coord;
      }
      if (c.wrap_u) {
        const std::size_t copy = first_copy[k] + static_cast<std::size_t>(j);
        fixed[2 * copy] = 1.0f;
        fixed[2 * copy + 1] = v_coord;
      }
    }
  }
  for (std::size_t k = 0; k < l.seam_copies.size(); ++k)
    for (int d = 0; d < 3; ++d)
      fixed[2 * rn + 3 * (l.vertices + k) + d] =
          fixed[2 * rn + 3 * static_cast<std::size_t>(l.seam_copies[k]) + d];
}

// The longest rest extent of cloth c along u and v into `longest` (a tube: round the longer of
// its end rings, the seam's chord included; a frustum's differ).
void measure(const ClothLayout& l, const ClothRange& c, glm::vec2& longest) {
  const std::size_t rn = l.render_vertices();
  auto rest = [&](int i, int j) {
    const std::size_t v = 2 * rn + 3 * static_cast<std::size_t>(c.offset + i + j * c.nu);
    return glm::vec3(l.fixed[v], l.fixed[v + 1], l.fixed[v + 2]);
  };
  if (c.mesh) return;  // planar_uvs gave its spans
  if (c.wrap_u) {
    for (int j : {0, c.nv - 1}) {
      float ring = 0.0f;
      for (int i = 0; i < c.nu; ++i) ring += glm::length(rest((i + 1) % c.nu, j) - rest(i, j));
      longest.x = std::max(longest.x, ring);
    }
  } else {
    longest.x = std::max(longest.x, glm::length(rest(c.nu - 1, 0) - rest(0, 0)));
  }
  longest.y = std::max(longest.y, glm::length(rest(0, c.nv - 1) - rest(0, 0)));
}

// Mode 6's atlas: cloth k of K in its own band of rows, and its scale in atlas units per metre.
void set_atlas(ClothLayout& l, const std::vector<std::size_t>& first_copy, glm::vec2 longest) {
  const std::size_t rn = l.render_vertices();
  const float rows = static_cast<float>(std::max<std::size_t>(1, l.cloths.size()));
  for (std::size_t k = 0; k < l.cloths.size(); ++k) {
    const ClothRange& c = l.cloths[k];
    measure(l, c, longest);
    auto to_atlas = [&](std::size_t at) {
      l.fixed[5 * rn + 2 * at] = l.fixed[2 * at];
      l.fixed[5 * rn + 2 * at + 1] = (l.fixed[2 * at + 1] + float(k)) / rows;
    };
    for (int v = c.offset; v < c.offset + c.nu * c.nv; ++v) to_atlas(static_cast<std::size_t>(v));
    if (c.wrap_u)
      for (int j = 0; j < c.nv; ++j) to_atlas(first_copy[k] + static_cast<std::size_t>(j));
  }
  l.atlas_per_metre = glm::vec2(1.0f / longest.x, 1.0f / (longest.y * rows));
}

// The column of vertex v in its cloth, and the cloth (null when v is in none).
int column_of(const ClothLayout& l, int v, const ClothRange*& cloth) {
  for (const ClothRange& c : l.cloths)
    if (v >= c.offset && v < c.offset + c.nu * c.nv) {
      cloth = &c;
      return (v - c.offset) % c.nu;
    }
  cloth = nullptr;
  return -1;
}

// The solver's triangles; on a tube those of the seam's quads (with a vertex in column nu - 1
// and one in column 0) take column 0's seam copies, at u = 1.
void set_triangles(ClothLayout& l, const std::vector<std::array<int, 3>>& solver_triangles) {
  l.triangles.reserve(3 * solver_triangles.size());
  std::vector<std::uint32_t> seam_copy;  // per solver vertex: its copy, or itself
  if (!l.seam_copies.empty()) {
    seam_copy.resize(l.vertices);
    for (std::size_t v = 0; v < l.vertices; ++v) seam_copy[v] = static_cast<std::uint32_t>(v);
    for (std::size_t k = 0; k < l.seam_copies.size(); ++k)
      seam_copy[static_cast<std::size_t>(l.seam_copies[k])] =
          static_cast<std::uint32_t>(l.vertices + k);
  }
  for (const auto& t : solver_triangles) {
    bool seam = false;
    if (!l.seam_copies.empty()) {
      const ClothRange* c = nullptr;
      bool first = false, last = false;
      for (int v : t) {
        const int i = column_of(l, v, c);
        if (c && c->wrap_u) first |= i == 0, last |= i == c->nu - 1;
      }
      seam = first && last;
    }
    for (int v : t)
      l.triangles.push_back(seam ? seam_copy[static_cast<std::size_t>(v)]
                                 : static_cast<std::uint32_t>(v));
  }
}

}  // namespace

ClothLayout make_cloth_layout(const SolverState& solver) {
  ClothLayout l;
  l.vertices = solver.vertex_count();
  l.cloths = solver.cloths();
  const std::vector<std::size_t> first_copy = add_seam_copies(l);
  const std::size_t rn = l.render_vertices();
  l.fixed.assign(7 * rn, 0.0f);
  solver.copy_rest_positions(l.fixed.data() + 2 * rn);
  glm::vec2 longest(1e-3f);
  set_uvs(l, first_copy, longest);
  set_atlas(l, first_copy, longest);
  const auto& solver_triangles = solver.triangles();
  set_triangles(l, solver_triangles);
  for (const auto& s : solver.spring_pairs())
    for (int v : s) l.lines.push_back(static_cast<std::uint32_t>(v));
  if (std::any_of(l.cloths.begin(), l.cloths.end(), [](const ClothRange& c) { return c.mesh; })) {
    l.mesh_uvs.assign(l.fixed.begin(), l.fixed.begin() + std::ptrdiff_t(2 * l.vertices));
    l.mesh_triangles = solver_triangles;
  }
  return l;
}

}  // namespace clothlab::vis
