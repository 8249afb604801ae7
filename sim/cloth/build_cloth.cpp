#include "sim/cloth/build_cloth.hpp"

#include "sim/cloth/mesh_cloth.hpp"
#include "sim/cloth/tube_cloth.hpp"

namespace clothlab {

GridCloth build_cloth(const ClothSpec& spec) {
  if (spec.shape == "tube") return build_tube_cloth(spec);
  if (spec.shape == "mesh") return build_mesh_cloth(spec);
  return build_grid_cloth(spec);
}

}  // namespace clothlab
