// Procedural maps of the cloth's woven surface, built from the same 2/2 twill as the albedo
// (make_fabric_texture): same thread count fabric_thread_count(size), same over/under pattern
// and phase, same thread width and texel centres, so the albedo, the bumps, the metallic-thread
// mask and the thread directions line up when sampled with the same UVs. Every map tiles
// seamlessly. No GL here: the renderer uploads the images.
//
// Orientation (all maps, as for the albedo): image row 0 is the first row uploaded, which GL
// puts at texture coordinate t = 0, and the cloth's UV is (i / (nu - 1), j / (nv - 1)) for grid
// vertex (i, j) (vis/render/renderer.cpp). So texel (x, y) covers u = (x + 0.5) / size and
// v = (y + 0.5) / size: +u is +x (to the right) and +v is +y, i.e. DOWN the image as a PNG
// viewer shows it. Warp threads run along v (down the columns), weft threads along u (across
// the rows).
//
// Normal map byte encoding (linear data, upload as GL_RGBA8, never sRGB): a tangent-space
// normal n (unit, z >= 0) is stored as byte = 128 + round(127 * n), per channel, so n = 0 is
// exactly 128 and n = 1 exactly 255 (flat = (128, 128, 255)). This is the usual n * 0.5 + 0.5
// encoding, but scaled by 127 around 128 instead of by 127.5 around 127.5, which cannot hit 0
// exactly (docs/rendering.md section 3). Decode with
//     n = byte / 127 - 128 / 127            (bytes, as decode_normal does), or in GLSL
//     n = texture(map, uv).rgb * (255.0 / 127.0) - 128.0 / 127.0
// then normalise (after filtering). The decoded vector of a texel made here is unit length
// within 1/127.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "vis/textures/image.hpp"

namespace clothlab {

// Height of the woven surface, size * size floats, row-major (index x + y * size, row 0 = v 0),
// in [0, 1]: 0 in the gaps between threads, up to 1 on the crown of a thread where it floats
// over its crossing thread. Throws std::invalid_argument if size < 1.
std::vector<float> make_weave_height(int size);

// Tangent-space normal map of make_weave_height (OpenGL convention: red = +u = tangent T,
// green = +v = bitangent B = dP/dv, blue = the surface normal), by central differences with
// wrap-around. `strength` scales the relief: the normal is normalize(-s * dh/du, -s * dh/dv, 1)
// with derivatives per thread spacing, so strength 1 makes the 0..1 height range as tall as one
// thread spacing (0.3 to 0.6 looks like real yarn); strength 0 gives a flat map. Alpha 255.
// Throws std::invalid_argument if size < 1 or strength is negative or not finite.
Image make_weave_normal_map(int size, float strength = 0.5f);

// All texels (128, 128, 255, 255): the flat map, which decodes to exactly (0, 0, 1).
// Throws std::invalid_argument if size < 1.
Image make_flat_normal_map(int size);

// Decodes the first three bytes of a normal-map texel: (byte - 128) / 127 per channel, clamped
// to [-1, 1], not renormalised. (128, 128, 255) gives exactly (0, 0, 1).
glm::vec3 decode_normal(const std::uint8_t* rgb);

// Encodes a unit vector as bytes 128 + round(127 * n) (clamped to [1, 255]), the inverse of
// decode_normal within 0.5 / 127 per channel. Writes rgb[0..2].
void encode_normal(const glm::vec3& n, std::uint8_t* rgb);

// Largest metal_fraction make_thread_mask can reach: the fraction of texels where a weft thread
// is on top (about 0.43 for size 256). Throws std::invalid_argument if size < 1.
float max_metal_fraction(int size);

// Metallic (gold/silver) thread mask: R = G = B = 255 where a metallic thread is on top, 0
// elsewhere; alpha 255. Metallic threads are whole weft threads, spread evenly across the tile
// (Bresenham spacing; `seed` picks the phase); their number is the one whose texel share is
// nearest metal_fraction (fraction of all texels, capped at max_metal_fraction(size)). Weft
// texels only, so they carry the weft's direction in make_thread_direction.
// Throws std::invalid_argument if size < 1 or metal_fraction is outside [0, 1] (or NaN).
Image make_thread_mask(int size, float metal_fraction, std::uint32_t seed = 1);

// Which thread lies on top at each texel: R = 0 where the warp is on top (the thread, and the
// anisotropic highlight's tangent, run along v: use B), R = 255 where the weft is (along u: use
// T); G = 255 where some thread covers the texel, 0 in the gaps between threads (there R = 0
// too); B = 0; alpha 255.
// Throws std::invalid_argument if size < 1.
Image make_thread_direction(int size);

}  // namespace clothlab
