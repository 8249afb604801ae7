// A symmetric 3x3 block stored as its upper triangle, xx xy xz yy yz zz: the Newton matrix's
// diagonal blocks (sim/integrators/newton/newton_matrix.hpp) and the multigrid levels' blocks
// (multigrid_hierarchy.hpp).
#pragma once

namespace clothlab {

// The cofactors of m (the adjugate, symmetric like m) into adj; returns the determinant. The
// inverse is adj / det (in double: in float the h^2 k terms of a block can dwarf the mass).
inline double symmetric3_adjugate(const double m[6], double adj[6]) {
  const double xx = m[0], xy = m[1], xz = m[2], yy = m[3], yz = m[4], zz = m[5];
  adj[0] = yy * zz - yz * yz, adj[1] = xz * yz - xy * zz, adj[2] = xy * yz - xz * yy;
  adj[3] = xx * zz - xz * xz, adj[4] = xy * xz - xx * yz, adj[5] = xx * yy - xy * xy;
  return xx * adj[0] + xy * adj[1] + xz * adj[2];
}

}  // namespace clothlab
