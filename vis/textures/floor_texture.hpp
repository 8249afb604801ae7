// Floor albedo: a checker of light and dark grey stone tiles separated by grout lines, with
// seeded per-tile tone variation and tileable mottling. Tiles seamlessly.
#pragma once

#include <cstdint>

#include "vis/textures/image.hpp"

namespace clothlab {

// Stone tiles across the texture in each direction (even, so the checker tiles seamlessly).
inline constexpr int kFloorTiles = 4;

// size x size RGBA image (display/sRGB values), alpha 255, row 0 at the top. The same
// (size, seed) gives the same bytes within a build; compilers or flags that fuse float
// multiply-adds differently may move a channel by one step.
// Tile (tx, ty), tx, ty in [0, kFloorTiles), is light when (tx + ty) is even.
// Throws std::invalid_argument if size < 1.
Image make_floor_texture(int size = 256, std::uint32_t seed = 2);

}  // namespace clothlab
