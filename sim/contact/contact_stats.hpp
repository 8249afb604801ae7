// What the collision responses did: the colliders' in the last substep
// (sim/contact/contact_response.hpp), self-collision's in the last step
// (sim/contact/self_collision.hpp), triangle contact's in its last pass (one or more substeps).
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

// Triangle contact's last pass (sim/contact/triangle_contact.hpp).
struct ClothContactStats {
  int candidates = 0;        // vertex-triangle and edge-edge pairs the broad phase found
  int contacts = 0;          // pairs the proximity pass pushed apart to the thickness
  int rolled_back = 0;       // vertices the fail-safe returned to their start of the pass
  int unresolved = 0;        // flagged pairs with no free vertex left to return (pins that move)
  bool overflow = false;     // a tangle beyond the pair bound: the pass was undone
  bool collected = false;    // the broad phase ran (a vertex left its widened box)
  bool recollected = false;  // again after the proximity pass moved a vertex out of its box
  int flat_patches = 0;      // patches skipped as flat (sim/contact/flat_patches.hpp)
  int flat_triangles = 0;    // triangles in them
};

}  // namespace clothlab
