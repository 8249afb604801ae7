// Grid sheets built by hand for the contact tests (tests/cloth_contact_test.cpp,
// tests/flat_patches_test.cpp): vertices placed by a function of (i, j), two triangles a square.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace clothlab {

struct GridMesh {
  std::vector<std::array<int, 3>> triangles;
  std::vector<Eigen::Vector3d> x;
  std::vector<int> groups;  // per triangle: the grid it came from
};

// Appends an nu x nv grid of vertices placed by place(i, j), two triangles a square, wound alike.
template <class Place>
void add_grid(GridMesh& m, int nu, int nv, int group, Place&& place) {
  const int offset = int(m.x.size());
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) m.x.push_back(place(i, j));
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      const int v = offset + i + j * nu;
      m.triangles.push_back({v, v + 1, v + nu + 1});
      m.triangles.push_back({v, v + nu + 1, v + nu});
      m.groups.insert(m.groups.end(), 2, group);
    }
}

template <class Place>
GridMesh grid_mesh(int nu, int nv, Place&& place) {
  GridMesh m;
  add_grid(m, nu, nv, 0, place);
  return m;
}

}  // namespace clothlab
