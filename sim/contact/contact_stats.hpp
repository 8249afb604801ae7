// What the collision response did in the last substep (sim/contact/contact_response.hpp).
#pragma once

namespace clothlab {

struct ContactStats {
  int contacts = 0;        // vertices the last substep corrected
  double max_depth = 0.0;  // m: largest thickness - phi left after the response (0: none)
};

}  // namespace clothlab
