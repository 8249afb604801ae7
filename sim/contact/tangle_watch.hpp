// Counts triangle contact's tangles (sim/contact/triangle_contact.hpp: a substep whose pairs
// passed the bound, undone by holding every free vertex where it began). A tangle that comes back
// kStuckSubsteps times, with fewer than kCleanSubsteps substeps without one in between, means the
// cloth cannot go on: an exploding lattice (a step beyond the method's stability limit; the held
// vertices hide its kinetic energy from the divergence monitor), or cloth wrung or stacked denser
// than the bound, which moving pins would meanwhile drag through itself (docs/contact.md
// section 7). The solver then stops the run with a report instead of a frozen cloth.
#pragma once

namespace clothlab {

struct TangleWatch {
  static constexpr int kStuckSubsteps = 8, kCleanSubsteps = 60;
  int tangles = 0;         // since the last kCleanSubsteps clean substeps in a row
  int clean_substeps = 0;  // since the last tangle
  double since = 0.0;      // s: the first of them

  // After every substep with triangle contact, at its start time t.
  void count(bool tangled, double t) {
    if (!tangled) {
      if (++clean_substeps >= kCleanSubsteps) tangles = 0;
      return;
    }
    if (tangles == 0) since = t;
    ++tangles;
    clean_substeps = 0;
  }
  bool stuck() const { return tangles >= kStuckSubsteps; }
};

}  // namespace clothlab
