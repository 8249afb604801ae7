// Long-range attachments ("tethers"; Kim, Chentanez & Mueller 2012, "Long Range Attachments - A
// Method to Simulate Inextensible Clothing in Computer Games", SCA '12): each free vertex of a
// flat grid cloth may be no further from a pin of its cloth than in the built (rest) sheet,
//   C(x) = |x - p| - d0 <= 0,
// projected per vertex after the constraint sweep. In a flat sheet the rest distance is the
// geodesic one, and no deformation that does not stretch the cloth can take a vertex further
// from a pin, so the tether only acts where the sweep left the sheet stretched: it carries the
// pins' hold across the sheet at once, where Gauss-Seidel sweeps carry it a vertex or two per
// sweep (docs/solver.md, "Small steps at scale").
//
// A tether forbids stretch the material would have, so a cloth gets tethers only where its own
// weight stretches it by less than kTetherMaxStrain: a column's weight on its top structural
// spring, (M |g| / columns) / (k L), is 0.2 % on the accuracy sheet (k0 = 1e3) and 2 % on a
// single 100 N/m spring with 0.1 kg, which keeps its oscillation. Each vertex keeps its
// kTetherSlots nearest pins of the same cloth; a vertex with fewer pins fills the other slots
// with a distance no position reaches.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "sim/integrators/constraints/stretch_slack.hpp"
#include "sim/model/model.hpp"

namespace clothlab {

inline constexpr int kTetherSlots = 4;
inline constexpr double kTetherMaxStrain = 0.01;

// The strain of grid cloth c (row_sweep model) hanging under its own weight, as above; infinite
// where it has no structural spring.
template <class T>
double static_strain(const Model<T>& m, std::size_t c);

// Cloth c's static strain and longer side, for the slack its stretch limits allow.
template <class T>
ClothSlack cloth_slack(const Model<T>& m, std::size_t c);

// The distance between vertices i and j in the built (rest) positions.
template <class T>
double rest_distance(const Model<T>& m, std::size_t i, std::size_t j);

// Cloth c takes stretch limits (tethers, coarse_stretch.hpp): a flat grid of the row_sweep
// kernel whose static strain is under kTetherMaxStrain.
template <class T>
bool stretch_limited(const Model<T>& m, std::size_t c);

template <class T>
class Tethers {
 public:
  // The tethers of the model's grid cloths (none where a cloth has no pin); empty() when none.
  Tethers() = default;
  explicit Tethers(const Model<T>& m);
  bool empty() const { return slots_ == 0; }

  // Copies the pins' current positions (they may move: moving pins, the grab) and whether each
  // is still pinned (a released pin holds nothing): once per substep, before project() runs on
  // any block.
  void gather_pins(const Vec3Array<T>& x, const T* inv_mass);
  // The substep's length, for the slack each cloth's tethers allow (stretch_slack.hpp): once per
  // substep, before project() runs on any block.
  void set_substep(double h);
  // Projects the free vertices [b, e) of x onto their tethers, slot by slot.
  void project(Vec3Array<T>& x, const T* inv_mass, std::size_t b, std::size_t e) const;

 private:
  // A cloth's vertices [begin, end) and their slots; with at most kTetherSlots pins slot s is
  // the cloth's pin s for every vertex (shared: one position for the whole pass, no gathers).
  struct Span {
    std::size_t begin = 0, end = 0;
    int slots = 0;
    bool shared = false;
    std::int32_t pin[kTetherSlots] = {};
    ClothSlack slack;  // of the cloth
    T scale = T(1);    // slack.scale() at this substep: a tether holds at rest * scale
  };
  void project_slot(Vec3Array<T>& x, const T* inv_mass, const Span& span, int s, std::size_t lo,
                    std::size_t hi) const;

  std::vector<Span> spans_;
  int slots_ = 0;
  std::size_t n_ = 0;
  std::vector<int> pins_;          // vertex index of each pin
  Vec3Array<T> pin_pos_;           // their positions this substep
  AlignedVector<T> pin_held_;      // 1 while the pin is pinned, else 0
  std::vector<std::int32_t> pin_;  // slot-major: pin_[s * n + i] indexes pins_
  AlignedVector<T> rest_;          // slot-major: the rest distance to that pin
};

}  // namespace clothlab
