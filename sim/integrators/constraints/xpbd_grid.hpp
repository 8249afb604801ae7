// XPBD's grid path: the same constraint update as sim/integrators/constraints/xpbd.cpp, spring for
// spring, on cloths whose springs are a stencil of offsets (di, dj) on a regular grid (the
// row_sweep kernel's GridStencil), laid out and ordered so that every loop runs over contiguous
// memory.
//
// Batches: every spring of one offset joins (i, j) and (i + di, j + dj). Split by the parity of
// floor(j / dj) (dj > 0) or floor(i / di) (dj = 0), the springs of one class share no vertex, so
// a class is one Gauss-Seidel colour: for dj > 0 a row's springs are two contiguous runs (row j
// and row j + dj) and vectorise as they are; for dj = 0 a row's class is computed over the whole
// row into a scratch row and applied in a second contiguous pass. The seed stencil's 10 offsets
// give 20 batches, the minimum (a vertex has 20 springs). Fratarcangeli & Pall 2018 use the same
// red-black idea on quad grids.
//
// Bands: rows are cut into bands that depend on the grid alone; a band runs all its batches
// back to back while its rows sit in the core's cache. A band's springs reach at most `reach`
// rows into the next band, so the even bands run in parallel first, then the odd ones: no two
// bands of a phase share a vertex and the result is the same bits on any thread count. The
// sweep order is therefore (phase, batch): xpbd_grid_colours() gives it for the neighbour-list
// path, which the tests compare against.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "sim/integrators/integrator.hpp"

namespace clothlab {

// true when the grid path can run the model: every cloth is a grid of the row_sweep kernel.
template <class T>
bool xpbd_grid_applies(const Model<T>& m);

template <class T>
std::unique_ptr<Integrator<T>> make_xpbd_grid(const Model<T>& m, const SolverSpec& spec);

// The grid path's sweep order as colours of `ends` (springs (a, b), a < b, of a model built from
// the same scene with the neighbour-list kernel): colour = phase * batches + batch. With these
// colours the neighbour-list path sweeps in the grid path's order (the tests' reference).
template <class T>
std::vector<int> xpbd_grid_colours(const Model<T>& grid_model,
                                   const std::vector<std::array<int, 2>>& ends);

// The neighbour-list path with the given colour per spring of spring_list(m) instead of its own
// greedy colouring.
template <class T>
std::unique_ptr<Integrator<T>> make_xpbd_in_order(const Model<T>& m, const SolverSpec& spec,
                                                  std::vector<int> colours);

}  // namespace clothlab
