// What the collision responses did: the colliders' in the last substep
// (sim/contact/contact_response.hpp), self-collision's in the last step
// (sim/contact/self_collision.hpp).
#pragma once

namespace clothlab {

struct ContactStats {
  int contacts = 0;        // vertices, edges and features the last substep corrected
  double max_depth = 0.0;  // m: largest thickness - phi left after the response (0: none)
};

struct SelfCollisionStats {
  int pairs = 0;              // candidate pairs found at the start of the step
  int dropped = 0;            // pairs beyond the buffer's bound (0 unless the cloth is crushed)
  int contacts = 0;           // pairs the last substep corrected
  double max_depth = 0.0;     // m: largest thickness - distance the last substep pushed apart
  double query_radius = 0.0;  // m: thickness + 2 vmax dt of this step
};

}  // namespace clothlab
