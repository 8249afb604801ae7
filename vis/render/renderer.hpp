// The frame shared by the window and headless rendering: the shadow map, mode 6's diffusion,
// then the floor, the scenery, the colliders, the cloth (vis/passes/cloth_pass, springs_pass)
// and the sky, in that order, over the cloth's buffers (vis/render/cloth_geometry). Draws into
// whatever framebuffer is bound; only context creation differs between window and headless.
// Needs a current OpenGL 4.5 core context.
#pragma once

#include <array>
#include <vector>

#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "gl/objects.hpp"
#include "gl/pass_timer.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/collider_spec.hpp"
#include "vis/passes/cloth_pass.hpp"
#include "vis/passes/depth_view_pass.hpp"
#include "vis/passes/floor_pass.hpp"
#include "vis/passes/springs_pass.hpp"
#include "vis/render/cloth_geometry.hpp"
#include "vis/render/light_rig.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
class Solver;
class SolverState;
struct FrameFields;
struct Image;
}  // namespace clothlab

namespace clothlab::vis {

class ColliderScenery;
class DiffusionPass;
class Scenery;
class ShadowPass;
class SkyPass;

class Renderer {
 public:
  Renderer();
  ~Renderer();

  // (Re)builds the cloth's static buffers: UVs, rest positions, triangle and spring indices.
  // Call after building or resizing the solver.
  void set_cloth(const SolverState& solver);
  // (Re)builds the scenery of the scene's [render] table (the pole from the solver's pins and
  // the extra meshes) and of its [[colliders]] (vis/render/collider_scenery.hpp; a horizontal
  // plane is the floor, which scene_view() places). Call after set_cloth.
  void set_scene(const RenderSpec& spec, const Solver& solver,
                 const std::vector<ColliderSpec>& colliders = {});
  // Uploads the snapshot's positions and smooth normals into the vertex buffer, in place, and
  // poses moving colliders at its time. Call once per frame before draw(), with a snapshot taken
  // for frame_request(view, *this) (vis/render/frame_request.hpp). With the GPU backend
  // (FrameFields::device) the positions and normals go from the solver's device buffers to the
  // vertex buffer on the GPU.
  void update_cloth(const FrameFields& fields);
  // Whether draw(view) draws the springs (mode 1, or a cloth without triangles in any mode).
  bool draws_springs(const ViewSettings& view) const;
  // The colour-by scalar, one per vertex (vertex_count() values), and the range the colour map
  // spans, for draws while view.color.field is not none.
  void set_scalars(const std::vector<float>& values, ScalarRange range);
  // Draws the scene into the bound framebuffer of the given size: first the shadow map when
  // the view needs one (a shadow filter, or key 7), then the view. Nothing is shaded inside
  // `covered` (pixels, origin bottom-left; the window's opaque panel): its depth is set to the
  // near plane first, and it keeps the background colour.
  void draw(const ViewSettings& view, int width, int height, const PixelRect& covered = {});
  // view.quality for this context's GL renderer: full or fast (render_quality.hpp).
  RenderQuality quality(const ViewSettings& view) const;
  const std::string& gl_renderer() const { return gl_renderer_; }
  // Fast quality draws a large grid cloth as coarse as its size on screen allows (on by
  // default; cloth_detail.hpp); off draws every triangle at either quality (tests compare the
  // two). The stride of the last draw(): every stride-th vertex of a row and a column.
  void enable_coarse_cloth(bool on) { coarse_cloth_ = on; }
  int cloth_stride() const { return cloth_.drawn().stride; }
  // Time per pass (benchmarks): on, draw() brackets its passes (gl/pass_timer.hpp).
  void enable_pass_timing(bool on);
  PassTimer* pass_timer() { return timer_.get(); }
  // Replaces mode 6's procedural weave normal map with `map` (tangent-space, encoded as in
  // vis/textures/weave_maps.hpp), until called with nullptr. Tests give a known map to check the
  // tangent frame.
  void set_normal_map(const Image* map);
  // How often the sky's cube map was baked since the sky was turned on (tests).
  int sky_bakes() const;
  // The light as the last draw() placed it (tests project through its matrices).
  const LightRig& light() const { return light_; }
  // The springs' strain colour range of the last draw() (+-r), when it drew springs (mode 1, or
  // a cloth without triangles); for the legend.
  const std::optional<ScalarRange>& strain_range() const { return strain_range_; }

  // Render vertices: the solver's vertices (same indices), then for every tube (wrap_u) one copy
  // of column 0 per row with u = 1, which the seam's triangles use instead of column 0 so the
  // texture wraps round the ring rather than running back from 1 to 0 across one quad.
  // For passes that draw the same cloth (FieldPass): the buffer whose first 3 floats per render
  // vertex are the positions of the last update_cloth(), and the triangles' index buffer (the
  // solver's triangles in their order, indexing render vertices).
  GLuint position_buffer() const { return cloth_.position_buffer(); }
  GLsizei position_stride() const { return cloth_.position_stride(); }
  GLuint triangle_buffer() const { return cloth_.triangle_buffer(); }
  GLsizei triangle_index_count() const { return cloth_.triangle_indices(); }
  // The solver's vertices (what set_scalars and FieldPass::draw take values for).
  std::size_t vertex_count() const { return cloth_.vertex_count(); }
  std::size_t render_vertex_count() const { return cloth_.render_vertex_count(); }
  // The solver vertex render vertex vertex_count() + k copies.
  const std::vector<int>& seam_copies() const { return cloth_.seam_copies(); }
  // The solver vertex behind any render vertex.
  int physics_vertex(std::size_t render_vertex) const {
    const std::size_t n = vertex_count();
    return render_vertex < n ? static_cast<int>(render_vertex) : seam_copies()[render_vertex - n];
  }
  // The 256 x 1 sRGB table of a colour map (for the arrows and legends that share it).
  GLuint colormap_texture(ColorMap map) const { return colormaps_[static_cast<int>(map)].get(); }

 private:
  std::pair<glm::vec3, glm::vec3> casters_box() const;
  void anchor_sky();  // sky_anchor_ from the casters as they are now
  void fit_light_to_casters(const ViewSettings& view);
  glm::mat4 upload_frame(const ViewSettings& view, int width, int height, bool translucent);
  void draw_at(const ViewSettings& view, bool fast, int width, int height,
               const PixelRect& covered);
  void draw_cloth(const ViewSettings& view, const std::string& shading, bool subsurface);
  bool run_diffusion(const ViewSettings& view, const std::string& shading, bool fast);
  void draw_shadow_map(const ViewSettings& view, bool translucent);
  void draw_shadow_casters();
  GLuint prepare_sky(const ViewSettings& view);
  void draw_sky(const ViewSettings& view, const glm::mat4& view_proj);

  ClothGeometry cloth_;
  bool coarse_cloth_ = true;
  FloorPass floor_;
  ClothPass cloth_pass_;
  SpringsPass springs_;
  DepthViewPass depth_view_;
  std::unique_ptr<PassTimer> timer_;          // only while a benchmark times the passes
  std::unique_ptr<ShadowPass> shadow_;        // only while shadows or the depth view are on
  std::unique_ptr<SkyPass> sky_;              // only while the sky is shown
  std::unique_ptr<DiffusionPass> diffusion_;  // only while mode 6 shows subsurface light
  std::unique_ptr<Scenery> scenery_;
  std::unique_ptr<ColliderScenery> colliders_;  // only while the scene has colliders
  LightRig light_;
  // Where a spot light's sun is seen from: the casters' centre at set_scene, or at the first draw
  // without one (prepare_sky). set_cloth keeps it: tests draw one state from two solvers.
  std::optional<glm::vec3> sky_anchor_;
  std::optional<ScalarRange> strain_range_;
  std::string gl_renderer_;  // GL_RENDERER of this context
  Buffer frame_ubo_;
  ScalarRange scalar_range_;
  std::array<Texture, kAllColorMaps.size()> colormaps_;
  VertexArray empty_vao_;
};

}  // namespace clothlab::vis
