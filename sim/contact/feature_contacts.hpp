// Contacts between a collider's sharp features (sim/contact/sharp_features.hpp: a box's corners
// and edges, a mesh's vertices and creases) and the cloth's triangles, after the vertex and edge
// response of every substep (Bridson, Fedkiw & Anderson 2002, section 7: point-triangle
// proximity and, for a point that crossed the triangle's plane during the substep, its collision;
// the point is the collider's, which does not move in response). A corner between two rows of
// vertices pokes through the triangles there, which the vertices' own contacts never see.
//  - The side: where the feature was at the start of the substep, by the sign of its distance
//    from the triangle's plane then (the cloth on the far side of a thin part stays there; its
//    outward direction decides only a feature that started exactly on the plane).
//  - A contact: the feature within the thickness of the triangle on that side, or on the other
//    side with its projection inside the triangle (it crossed the plane through the triangle).
//    The closest point of the triangle X = w0 a + w1 b + w2 c moves along the normal n of that
//    side (or straight away from the feature, where X lies on the triangle's edge on that side).
//  - The velocity: an inelastic impulse on the velocity of X relative to the collider's surface
//    at the feature, then Coulomb friction with the collider's coefficients (as the vertices'
//    response), split over the three vertices by w_i / m_i so that X gets exactly that change;
//    the position: X moved out to the thickness the same way (a pinned vertex does not move).
// A feature inside another collider's shell (a crate's corner on the floor) touches nothing: the
// cloth cannot be there, and pushing it there would fight the other collider. Serial over the
// triangles in their order (neighbouring triangles share vertices, Gauss-Seidel), so the result
// is the same for any thread count; a triangle is tested only when one of its vertices lies near
// a feature (a grid over the features, built once) and its box meets the collider's.
#pragma once

#include <vector>

#include "sim/contact/collider.hpp"
#include "sim/contact/sharp_features.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T>
class FeatureContacts {
 public:
  FeatureContacts() = default;
  // `edge`: the cloth's longest edge at rest (the features lie at most half of it apart along
  // an edge, so a triangle across a collider's edge always has one under it).
  FeatureContacts(const std::vector<Collider>& colliders, const Model<T>& m, double edge);

  bool empty() const { return empty_; }

  // After a substep from the positions `start` to s.pos, the colliders' poses in `sweeps`: moves
  // the triangles that some feature touches, each to the thickness from it. Returns the
  // contacts.
  int respond(const std::vector<Collider>& colliders, const std::vector<ColliderSweep>& sweeps,
              const Model<T>& m, const Vec3Array<T>& start, State<T>& s, int threads);
  // The vertices the last respond() moved, each once per contact that moved it.
  const std::vector<std::int32_t>& moved() const { return moved_; }

 private:
  struct Feature {  // one feature over the substep, world frame
    Eigen::Vector3d start, end, outward;
  };
  // One feature against triangle t: true if it moved it. `reach`: the thickness and how far the
  // triangle and the feature moved this substep; start_normal(): the triangle's unit normal at
  // `start`, computed once per triangle on first use (its normal now is taken here, since an
  // earlier feature may have moved it). is_buried() says whether the feature lies in another
  // collider's shell (asked only for a contact).
  template <class StartNormal, class Buried>
  bool touch(const Collider& collider, const ColliderPose& pose, const Feature& f, double reach,
             const std::array<int, 3>& t, StartNormal&& start_normal, const Model<T>& m,
             const Vec3Array<T>& start, State<T>& s, Buried&& is_buried) const;

  // Marks the vertices near some feature of collider c (all of them when the cloth moved more
  // than a grid cell this substep); returns the largest vertex move.
  double mark_near(const SharpFeatures& f, const ColliderPose& pose, const Vec3Array<T>& start,
                   const State<T>& s, int threads);

  std::vector<SharpFeatures> features_;  // per collider (empty for smooth shapes)
  std::vector<char> near_;               // per vertex, for the collider at hand
  std::vector<double> block_move_;       // per block of vertices: its largest move
  std::vector<std::int32_t> moved_;      // the vertices the last respond() moved (repeats kept)
  bool empty_ = true;
};

extern template class FeatureContacts<float>;
extern template class FeatureContacts<double>;

}  // namespace clothlab
