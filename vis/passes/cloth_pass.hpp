// The shaded cloth, modes 2-6 (shaders/cloth.vert, cloth.frag): the woven fabric texture, the
// colour-by scalar, the cloth BRDF with metal threads and glint lights (mode 4, docs/rendering.md
// section 2), translucency (mode 5, section 5), the weave's relief and its light through the yarn
// (mode 6, sections 3 and 4). Owns the cloth's textures. Needs a current GL 4.5 context.
#pragma once

#include <memory>
#include <string>

#include "gl/objects.hpp"
#include "gl/program_variants.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
struct Image;
}  // namespace clothlab

namespace clothlab::vis {

class ClothGeometry;
class DiffusionPass;

class ClothPass {
 public:
  ClothPass();

  // Draws the cloth into the bound framebuffer in view.mode. `colormap`: the colour map's table;
  // `diffusion`: mode 6's blurred irradiance, or null without subsurface light.
  // `shading`: the lit shader's variant (ShadingVariant::defines).
  void draw(const ViewSettings& view, ClothGeometry& cloth, ScalarRange range, GLuint colormap,
            const DiffusionPass* diffusion, const std::string& shading);
  // Binds mode 6's normal map (the weave at this relief, or set_normal_map's) to unit 3.
  void bind_weave(double bump);
  // Replaces the procedural weave normal map with `map` until called with nullptr.
  void set_normal_map(const Image* map);
  GLuint fabric() const { return fabric_.get(); }

 private:
  void set_material(const ViewSettings& view);
  void set_weave(const ViewSettings& view, ClothGeometry& cloth, const DiffusionPass* diffusion);
  void set_brdf(const ViewSettings& view, ClothGeometry& cloth);
  void set_thread_fraction(double fraction);
  void upload_normal_map(const Image& map);

  ProgramVariants programs_;
  // With a geometry shader giving each triangle its normal (ClothGeometry::flat_normals()),
  // made the first time such a cloth is drawn.
  std::unique_ptr<ProgramVariants> flat_programs_;
  GLuint program_ = 0;  // the variant this draw uses
  Texture fabric_;
  Texture threads_;  // r: metal thread mask, g: weft on top
  double thread_fraction_ = -1.0;
  Texture weave_normals_;  // mode 6: the weave's tangent-space normal map
  double weave_bump_ = -1.0;
  bool custom_normals_ = false;  // set_normal_map gave the map
};

}  // namespace clothlab::vis
