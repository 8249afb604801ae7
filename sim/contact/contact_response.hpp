// Collision response against the scene's colliders, applied after every integrator substep
// (docs/contact.md section 1; Bridson, Fedkiw & Anderson 2002, section 7):
//  1. Detection in each collider's own frame, along the vertex's path relative to the collider
//     (start of the substep in the collider's start pose, end in its end pose), so a fast thin
//     collider cannot pass a vertex unseen: where the path starts outside the shell (phi >=
//     thickness) it is marched by its signed distance (sphere tracing) to the first point on the
//     shell, and that point's normal - the side the vertex came from - is the contact normal.
//  2. An inelastic normal impulse on the velocity relative to the collider's surface
//     (v_c = v + w x (x - c)): the relative normal velocity may still close the gap the vertex
//     had at the start of the substep (gap / h) but no more; then Coulomb friction on the
//     tangential relative velocity with that impulse dv_n: it sticks while |v_t| <= mu_s dv_n,
//     otherwise it loses mu_k dv_n.
//  3. The vertex's move over the substep is redone with the filtered velocity, x = x0 + h v
//     (the order of Bridson's method: velocity filter before the position update, which keeps a
//     patch that should stick from creeping), and what still lies inside the shell is projected
//     out to phi = thickness along the normal, leaving the velocity alone.
// The same for every integrator (per substep): its own update makes (x, v) and this corrects
// them; Verlet's cached force is then recomputed (Integrator::state_corrected).
// Where a collider is thinner than the cloth's grid edges (a rod between two rows of vertices),
// each edge's midpoint is a contact point too, its correction moving both ends (edges first,
// then the vertices, which leaves no vertex inside a shell). A box's or a mesh's corners and
// edges poke through the triangles between the vertices: they are contact points of their own
// against the triangles, last (sim/contact/feature_contacts.hpp), and each vertex such a contact
// moved is responded to once more.
// Broad phase: per block of vertices, the box around their start and end positions against each
// collider's box over the substep, so a collider far from the cloth costs one box test per block.
// Nothing allocates after construction; every vertex is handled alone, so the result is the same
// for any thread count.
#pragma once

#include <algorithm>
#include <vector>

#include "sim/contact/collider.hpp"
#include "sim/contact/collider_touches.hpp"
#include "sim/contact/contact_stats.hpp"
#include "sim/contact/feature_contacts.hpp"
#include "sim/integrators/integrator.hpp"

namespace clothlab {

template <class T>
class ContactResponse {
 public:
  // hold_reach: how far beyond a collider's shell a vertex the response leaves alone still counts
  // as held in touches() (triangle contact's pushes, up to the cloth's thickness each, must not
  // drive it in); 0: only the vertices it corrects.
  ContactResponse(const std::vector<ColliderSpec>& colliders, const Model<T>& m,
                  double hold_reach = 0.0);

  bool empty() const { return colliders_.empty(); }
  const std::vector<Collider>& colliders() const { return colliders_; }

  // Before the substep from t to t + h: decides whether any collider is within reach of the
  // cloth this substep and, if so, remembers where every vertex starts.
  void begin(const State<T>& s, double t, double h, int threads);
  // After the substep from t to t + h: responds to every contact it made. Returns true when it
  // changed some vertex.
  bool respond(const Model<T>& m, State<T>& s, double t, double h, int threads);
  const ContactStats& last() const { return stats_; }
  // The vertices the last respond() held against a collider, with its normal.
  const ColliderTouches& touches() const { return touches_; }

 private:
  struct BlockResult {
    int contacts = 0;
    double max_depth = 0.0;
    bool near = false;  // the block's box met some collider's this substep
  };
  struct EdgeRun {  // `count` edges (first + e * 1, + step) of one grid row
    int first = 0, step = 1, count = 0;
  };
  // The vertices of the blocks near a collider (vertex() for each).
  void respond_vertices(const Model<T>& m, State<T>& s, double h, int threads);
  // The response of one point moving from x0 to (x1, v) over the substep, against every
  // collider: corrects x1 and v and raises depth to what is left inside a shell. Returns
  // whether it was a contact, and sets `normal` to the outward normal of the last one; `near`,
  // when given, to the outward normal of a collider whose shell x1 ends within hold_reach_ of
  // without a contact.
  bool point(const Eigen::Vector3d& x0, Eigen::Vector3d& x1, Eigen::Vector3d& v, double h,
             double& depth, Eigen::Vector3d& normal, Eigen::Vector3d* near = nullptr) const;
  // A vertex's response, and an edge midpoint's (moving both ends); each records the vertices
  // it moved in touches_ (no two at once share a vertex: respond_edges' rounds).
  bool vertex(std::size_t i, const Model<T>& m, State<T>& s, double h, double& depth);
  bool edge(std::size_t a, std::size_t b, const Model<T>& m, State<T>& s, double h, double& depth);
  void respond_edges(const Model<T>& m, State<T>& s, double h, int threads);

  std::vector<Collider> colliders_;
  std::vector<ColliderSweep> sweeps_;
  Vec3Array<T> start_;
  std::vector<BlockResult> blocks_;
  // begin()'s cheap test holds for this many substeps when it finds nothing within reach, but
  // for no longer than kWindowSeconds: its margin assumes the cloth's speed barely changes
  // meanwhile, which at 1/60 s steps (a window of 0.27 s, in which gravity alone moves a vertex
  // 0.35 m from rest) let a falling sheet sink 24 mm into a sphere before it was tested.
  static constexpr int kWindow = 16;
  static constexpr double kWindowSeconds = 0.01;
  static int window_substeps(double h) {
    return h * kWindow <= kWindowSeconds ? kWindow : std::max(1, int(kWindowSeconds / h));
  }
  bool active_ = false;     // begin() found a collider within reach this substep
  int quiet_substeps_ = 0;  // substeps the last "nothing within reach" still covers
  bool edges_ = false;  // edge midpoints are contact points too (a collider thinner than an edge)
  std::vector<EdgeRun> rows_, columns_;
  std::vector<std::array<int, 2>> mesh_edges_;  // mesh cloths' edges (a < b)
  FeatureContacts<T> features_;                 // the colliders' corners and edges
  ColliderTouches touches_;                     // the vertices held, also through edge midpoints
  double hold_reach_ = 0.0;                     // m: see the constructor
  ContactStats stats_;
};

extern template class ContactResponse<float>;
extern template class ContactResponse<double>;

}  // namespace clothlab
