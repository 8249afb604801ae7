// Woven fabric albedo for the cloth: a 2/2 twill of dark red warp and weft threads with shaded
// thread crossings and seeded per-thread colour variation. Tiles seamlessly.
#pragma once

#include <cstdint>

#include "vis/textures/image.hpp"

namespace clothlab {

// Threads across the tile in each direction for a texture of `size` pixels: 16 from size 64 up
// (16 px per thread at 256), fewer for tiny textures so each thread keeps >= 4 px; always a
// multiple of 4, the repeat of the 2/2 twill, so the weave tiles seamlessly.
int fabric_thread_count(int size);

// size x size RGBA image (display/sRGB values), alpha 255, row 0 at the top. The same
// (size, seed) gives the same bytes within a build; compilers or flags that fuse float
// multiply-adds differently may move a channel by one step.
// Throws std::invalid_argument if size < 1.
Image make_fabric_texture(int size = 256, std::uint32_t seed = 1);

}  // namespace clothlab
