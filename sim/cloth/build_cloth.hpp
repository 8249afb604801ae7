// The geometry of any cloth of a scene, by its shape: grid, tube or mesh (the mesh loaded).
#pragma once

#include "sim/cloth/grid_cloth.hpp"

namespace clothlab {

GridCloth build_cloth(const ClothSpec& spec);

}  // namespace clothlab
