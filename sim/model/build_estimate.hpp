// How long a scene's solver takes to build, estimated before it is built, so that `clothlab
// check` answers at once for any size and refuses (unless forced) a build of more than a minute
// (docs/inputs.md, "Memory and build time"). The figures are microseconds per vertex measured with
// `clothlab check` on 1000 x 1000 sheets on a 2-core host; the estimate is meant to
// be within a factor of two, enough to tell seconds from minutes.
#pragma once

#include "sim/scene/scene.hpp"

namespace clothlab {

// Seconds to build the solver of `scene` (every cloth, its integrator, contact and colliders).
double estimated_build_seconds(const Scene& scene);

}  // namespace clothlab
