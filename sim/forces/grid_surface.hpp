// The cloth surface (area-weighted vertex normals and vertex areas) of a grid cloth by row
// sweeps. Quad (qi, qj) is split into A = (a, b, c) and B = (a, c, d) with a = (qi, qj),
// b = (qi + 1, qj), c = (qi + 1, qj + 1), d = (qi, qj + 1), as GridCloth triangulates it. Vertex
// (i, j) touches A and B of quad (i, j), A of (i - 1, j), A and B of (i - 1, j - 1) and B of
// (i, j - 1). Quads live in arrays padded by a zero border, so every vertex reads the same six
// neighbours with no index array and no boundary test: both passes stream rows and vectorise.
#pragma once

#include <algorithm>
#include <cmath>

#include "sim/model/model.hpp"

namespace clothlab {

// Per grid cloth: the two triangles of every quad, at padded index (qi + 1) + (qj + 1) * stride.
template <class T>
struct GridFaces {
  int stride = 0;     // nu + 1
  Vec3Array<T> a, b;  // cross products: twice the area times the unit normal
  AlignedVector<T> a_area, b_area;

  void resize(int nu, int nv) {
    stride = nu + 1;
    const auto size = static_cast<std::size_t>(nu + 1) * static_cast<std::size_t>(nv + 1);
    a.resize(size);  // zero: the border stays zero for ever
    b.resize(size);
    a_area.assign(size, T(0));
    b_area.assign(size, T(0));
  }
};

// Faces of quad row qj (0 <= qj < nv - 1).
template <class T>
void grid_face_row(const GridStencil<T>& g, const Vec3Array<T>& x, GridFaces<T>& faces, int qj) {
  const std::size_t base = static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(qj) * g.nu;
  const std::size_t up = base + static_cast<std::size_t>(g.nu);
  const std::size_t out = static_cast<std::size_t>(qj + 1) * faces.stride + 1;
  const T *px = x.x.data(), *py = x.y.data(), *pz = x.z.data();
#pragma omp simd
  for (int qi = 0; qi < g.nu - 1; ++qi) {
    const std::size_t a = base + qi, b = a + 1, d = up + qi, c = d + 1;
    const T abx = px[b] - px[a], aby = py[b] - py[a], abz = pz[b] - pz[a];
    const T acx = px[c] - px[a], acy = py[c] - py[a], acz = pz[c] - pz[a];
    const T adx = px[d] - px[a], ady = py[d] - py[a], adz = pz[d] - pz[a];
    const T ax = aby * acz - abz * acy, ay = abz * acx - abx * acz, az = abx * acy - aby * acx;
    const T bx = acy * adz - acz * ady, by = acz * adx - acx * adz, bz = acx * ady - acy * adx;
    const std::size_t o = out + qi;
    faces.a.x[o] = ax, faces.a.y[o] = ay, faces.a.z[o] = az;
    faces.b.x[o] = bx, faces.b.y[o] = by, faces.b.z[o] = bz;
    faces.a_area[o] = T(0.5) * std::sqrt(ax * ax + ay * ay + az * az);
    faces.b_area[o] = T(0.5) * std::sqrt(bx * bx + by * by + bz * bz);
  }
}

// Unit normals and vertex areas (a third of the surrounding triangles) of vertex row j.
template <class T>
void grid_normal_row(const GridStencil<T>& g, const GridFaces<T>& faces, Vec3Array<T>& normal,
                     AlignedVector<T>& vertex_area, int j) {
  // Quad (qi, qj) at row pointer + qi, for qi from -1: rows j (quads above the vertex row) and
  // j - 1 (below).
  const std::size_t row = static_cast<std::size_t>(j + 1) * faces.stride + 1;
  const std::size_t prev = static_cast<std::size_t>(j) * faces.stride + 1;
  const std::size_t v0 = static_cast<std::size_t>(g.offset) + static_cast<std::size_t>(j) * g.nu;
  const auto sum = [&](const AlignedVector<T>& A, const AlignedVector<T>& B, std::size_t i) {
    return A[row + i] + B[row + i] + A[row + i - 1] + A[prev + i - 1] + B[prev + i - 1] +
           B[prev + i];
  };
#pragma omp simd
  for (int i = 0; i < g.nu; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const T nx = sum(faces.a.x, faces.b.x, k), ny = sum(faces.a.y, faces.b.y, k),
            nz = sum(faces.a.z, faces.b.z, k);
    const T len = std::sqrt(nx * nx + ny * ny + nz * nz);
    const T inv = len > T(0) ? T(1) / len : T(0);
    normal.x[v0 + k] = nx * inv;
    normal.y[v0 + k] = ny * inv;
    normal.z[v0 + k] = nz * inv;
    vertex_area[v0 + k] = sum(faces.a_area, faces.b_area, k) * (T(1) / T(3));
  }
}

}  // namespace clothlab
