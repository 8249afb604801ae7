// Which nodes of the contact tree are disks of material (docs/contact.md section 7.3): a
// connected patch of triangles with one rim, the topology that normal-cone culling needs
// (Volino & Magnenat-Thalmann 1994). A disk whose normals all lie on one side of an axis and
// whose rim projects onto the plane across that axis without touching itself cannot touch
// itself. Topology does not change as cloth moves, so this is computed once, from the triangles.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sim/contact/surface_features.hpp"
#include "sim/contact/triangle_bvh.hpp"

namespace clothlab {

struct PatchTopology {
  std::vector<std::uint8_t> disk;  // per node: its triangles form a disk
  // Per node: its rim's edges (a disk's only), rim[rim_begin[n] .. rim_begin[n + 1]).
  std::vector<std::int32_t> rim_begin;
  std::vector<std::array<std::int32_t, 2>> rim;
};

// A node is a disk when its triangles are connected, every edge borders at most two of them,
// every rim vertex has exactly two rim edges, and V - E + F = 1 (Euler's formula for a disk).
PatchTopology patch_topology(const TriangleBvh& bvh, const SurfaceFeatures& f,
                             std::size_t vertex_count);

}  // namespace clothlab
