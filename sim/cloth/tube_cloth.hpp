// A tube of cloth (cylinder or frustum: a skirt, a sleeve) as a grid whose columns close into
// rings: column nu - 1 is joined to column 0 across the seam by the same spring rule as
// everywhere else, so the seam is exactly as strong as the rest (ClothSpec has the geometry).
#pragma once

#include <vector>

#include "sim/cloth/grid_cloth.hpp"
#include "sim/cloth/seed_springs.hpp"

namespace clothlab {

// Vertex (i, j) on ring j at angle 2 pi i / nu; triangles include the seam's quads (between
// column nu - 1 and column 0); wrap_u is set. `edge` is the smaller of the shortest chord round
// a ring and the spacing along the tube. The spec must have been validated (shape "tube").
GridCloth build_tube_cloth(const ClothSpec& spec);

// The seed rule's 20-neighbour stencil (offsets with di^2 + dj^2 < 8, as on a square grid) with
// the i offsets taken round the ring, so springs cross the seam as they cross any other column;
// each spring's rest length is the distance between its ends as built (a frustum's rings
// differ), and its stiffness c * edge / rest_length with c its class's (seed_springs.hpp). Sorted
// by (a, b), each pair once.
std::vector<Spring> seed_springs_tube(const GridCloth& tube, const SpringStiffness& k);

}  // namespace clothlab
