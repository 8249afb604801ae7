#include "vis/colormap/colormap_texture.hpp"

#include <string>

#include "gl/uploads.hpp"

namespace clothlab::vis {

Texture make_colormap_texture(ColorMap map) {
  return srgb_table_texture(reinterpret_cast<const std::uint8_t*>(colormap_table(map).data()),
                            "colour map " + std::string(colormap_name(map)));
}

}  // namespace clothlab::vis
