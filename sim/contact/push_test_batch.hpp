// Triangle contact's proximity test (does a pair need a push: closer than the thickness now, or
// on the other side than at the pass's start; triangle_contact.cpp, needs_push) for a batch of
// pairs of one kind, one vector lane a pair (docs/contact.md section 7, "The proximity test in
// vector lanes"). The closest points follow the same region tests as
// sim/contact/primitive_distance.hpp (Ericson 2005, sections 5.1.5 and 5.1.9), every region
// computed and the answer selected, without a branch. Its sums run in another order than the
// scalar test's, so it answers only where the scalar test's answer cannot differ: a pair within
// a tolerance of either bound, or whose closest points are ill-conditioned (a sliver triangle,
// nearly parallel edges, a degenerate side), is `unsure` and left to the scalar test. The flags
// are then the scalar test's, bit for bit, and the traces the same bytes.
#pragma once

#include <cstdint>

namespace clothlab {

enum class PushVerdict : std::uint8_t { apart, push, unsure };

struct PushTestBatch {
  static constexpr int kLanes = 4;
  // Coordinate c (0-2) of the pair's vertex k (0-3) at the pass's end (x1) and start (x0):
  // x1[3 k + c][lane]. The point and the triangle, or edge p and edge q.
  alignas(32) double x1[12][kLanes];
  alignas(32) double x0[12][kLanes];
  std::uint32_t pair[kLanes];  // the caller's index of each lane's pair
  int count = 0;
};

// verdict[lane] for the first batch.count lanes: point-triangle pairs, or edge-edge pairs.
void point_triangle_push_tests(const PushTestBatch& batch, double thickness, PushVerdict* verdict);
void edge_edge_push_tests(const PushTestBatch& batch, double thickness, PushVerdict* verdict);

}  // namespace clothlab
