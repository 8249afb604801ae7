// Vertex block descent's grid path: the same Newton step per vertex as
// sim/integrators/descent/vbd.cpp, spring for spring (vbd_common.hpp), on cloths whose springs are
// a stencil of offsets (di, dj) with |di|, |dj| <= 2 on a regular grid (the row_sweep kernel's
// GridStencil, as for XPBD's grid path, xpbd_grid.hpp).
//
// Colours: vertex (i, j) takes colour 3 (j mod 3) + (i mod 3). Two vertices of a colour differ by
// a multiple of 3 along each axis, which no offset of the stencil is, so no two share a spring:
// 9 colours (the greedy colouring of the neighbour-list path takes 11 on the seed stencil).
//
// Layout: the vertices of a colour sit 3 apart in a row, which no vector load reaches. So every
// row is stored as three sub-rows, i = 3 m + c at entry m of sub-row c: a colour's vertices of a
// row are one contiguous sub-row, and the neighbour (i + di, j + dj) of them all is the
// contiguous sub-row (c + di) mod 3 of row j + dj, shifted by floor((c + di) / 3). A vertex sums
// its springs offset by offset over chunks of a sub-row, each offset one vectorised loop;
// springs past the grid's side are masked. A colour's rows update in parallel (no two share a
// vertex), so the result is the same bits on any thread count.
#pragma once

#include <memory>
#include <vector>

#include "sim/integrators/integrator.hpp"

namespace clothlab {

// true when the grid path can run the model: every cloth is a row_sweep grid whose stencil
// reaches at most 2 vertices along each axis.
template <class T>
bool vbd_grid_applies(const Model<T>& m);

template <class T>
std::unique_ptr<Integrator<T>> make_vbd_grid(const Model<T>& m, const SolverSpec& spec);

// The grid path's colour of every vertex of the model (3 (j mod 3) + (i mod 3) per cloth). With
// these colours the neighbour-list path visits the vertices in the grid path's order.
template <class T>
std::vector<int> vbd_grid_colours(const Model<T>& grid_model);

// The neighbour-list path with the given colour per vertex instead of its greedy colouring.
template <class T>
std::unique_ptr<Integrator<T>> make_vbd_in_order(const Model<T>& m, const SolverSpec& spec,
                                                 std::vector<int> colours);

}  // namespace clothlab
