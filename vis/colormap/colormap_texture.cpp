#include "vis/colormap/colormap_texture.hpp"

#include <string>

namespace clothlab::vis {

Texture make_colormap_texture(ColorMap map) {
  const auto table = colormap_table(map);
  Texture t = make_texture(GL_TEXTURE_2D);
  glTextureStorage2D(t.get(), 1, GL_SRGB8, 256, 1);
  // One row of tightly packed 3-byte texels (Rgb8 has no padding): the unpack alignment, which
  // only spaces rows, does not matter.
  glTextureSubImage2D(t.get(), 0, 0, 0, 256, 1, GL_RGB, GL_UNSIGNED_BYTE, table.data());
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const std::string label = "colour map " + std::string(colormap_name(map));
  glObjectLabel(GL_TEXTURE, t.get(), -1, label.c_str());
  return t;
}

}  // namespace clothlab::vis
