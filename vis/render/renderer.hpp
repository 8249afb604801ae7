// The render passes shared by the window and headless rendering: floor, shaded cloth (modes 2
// and 3) and springs as lines (mode 1). Draws into whatever framebuffer is bound; only context
// creation differs between window and headless. Needs a current OpenGL 4.5 core context.
#pragma once

#include <array>
#include <vector>

#include <memory>

#include "sim/model/model.hpp"
#include "sim/scene/collider_spec.hpp"
#include "vis/gl/objects.hpp"
#include "vis/gl/pass_timer.hpp"
#include "vis/render/light_rig.hpp"
#include "vis/render/view_settings.hpp"

namespace clothlab {
class DeviceCloth;
class Solver;
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
  void set_cloth(Solver& solver);
  // (Re)builds the scenery of the scene's [render] table (the pole from the solver's pins and
  // the extra meshes) and of its [[colliders]] (vis/render/collider_scenery.hpp; a horizontal
  // plane is the floor, which scene_view() places). Call after set_cloth.
  void set_scene(const RenderSpec& spec, const Solver& solver,
                 const std::vector<ColliderSpec>& colliders = {});
  // Uploads the current positions and smooth normals (computed in parallel by the solver) into
  // the vertex buffer, in place, and poses moving colliders at the solver's time(). Call once
  // per frame before draw().
  // With the GPU backend (vis/gpu/gpu_solver.hpp) the positions and normals go from the solver's
  // buffers into the vertex buffer by a compute pass (shaders/cloth_pack.comp), never through the
  // CPU; the CPU reads only the state mirror the solver keeps anyway, for the cloth's bounds.
  void update_cloth(Solver& solver);
  // The colour-by scalar, one per vertex (vertex_count() values), and the range the colour map
  // spans, for draws while view.color.field is not none.
  void set_scalars(const std::vector<float>& values, ScalarRange range);
  // Draws the scene into the bound framebuffer of the given size: first the shadow map when
  // the view needs one (a shadow filter, or key 7), then the view.
  void draw(const ViewSettings& view, int width, int height);
  // Time per pass (benchmarks): on, draw() brackets its passes (vis/gl/pass_timer.hpp).
  void enable_pass_timing(bool on);
  PassTimer* pass_timer() { return timer_.get(); }
  // Replaces mode 6's procedural weave normal map with `map` (tangent-space, encoded as in
  // vis/textures/weave_maps.hpp), until called with nullptr. Tests give a known map to check the
  // tangent frame.
  void set_normal_map(const Image* map);
  // The light as the last draw() placed it (tests project through its matrices).
  const LightRig& light() const { return light_; }

  // Render vertices: the solver's vertices (same indices), then for every tube (wrap_u) one copy
  // of column 0 per row with u = 1, which the seam's triangles use instead of column 0 so the
  // texture wraps round the ring rather than running back from 1 to 0 across one quad.
  // For passes that draw the same cloth (FieldPass): the buffer whose first 3 floats per render
  // vertex are the positions of the last update_cloth(), and the triangles' index buffer (the
  // solver's triangles in their order, indexing render vertices).
  GLuint position_buffer() const { return dynamic_vbo_.get(); }
  GLuint triangle_buffer() const { return triangle_ebo_.get(); }
  GLsizei triangle_index_count() const { return triangle_indices_; }
  // The solver's vertices (what set_scalars and FieldPass::draw take values for).
  std::size_t vertex_count() const { return vertices_; }
  std::size_t render_vertex_count() const { return vertices_ + seam_copies_.size(); }
  // The solver vertex render vertex vertex_count() + k copies.
  const std::vector<int>& seam_copies() const { return seam_copies_; }
  // The solver vertex behind any render vertex.
  int physics_vertex(std::size_t render_vertex) const {
    return render_vertex < vertices_ ? static_cast<int>(render_vertex)
                                     : seam_copies_[render_vertex - vertices_];
  }
  // The 256 x 1 sRGB table of a colour map (for the arrows and legends that share it).
  GLuint colormap_texture(ColorMap map) const { return colormaps_[static_cast<int>(map)].get(); }

 private:
  void draw_shadow_map(const ViewSettings& view, bool translucent);
  void draw_sky(const ViewSettings& view, const glm::mat4& view_proj, glm::vec3 centre);
  void update_tangents();
  void pack_from_gpu(const DeviceCloth& gpu);  // update_cloth's vertex buffer with the GPU backend
  void set_thread_fraction(double fraction);
  void set_weave_bump(double strength);
  void upload_normal_map(const Image& map);

  Program cloth_program_, floor_program_, springs_program_, depth_view_program_;
  std::unique_ptr<PassTimer> timer_;          // only while a benchmark times the passes
  std::unique_ptr<ShadowPass> shadow_;        // only while shadows or the depth view are on
  std::unique_ptr<SkyPass> sky_;              // only while the sky is shown
  std::unique_ptr<DiffusionPass> diffusion_;  // only while mode 6 shows subsurface light
  glm::vec2 atlas_per_metre_{1.0f};           // UV-atlas units per metre of cloth (u, v)
  std::unique_ptr<Scenery> scenery_;
  std::unique_ptr<ColliderScenery> colliders_;  // only while the scene has colliders
  LightRig light_;
  // The box around the cloth's current positions (update_cloth): a caster the light must see.
  glm::vec3 cloth_lo_{0.0f}, cloth_hi_{0.0f};
  Texture fabric_, tiles_;
  Buffer frame_ubo_;
  // One vertex buffer for what changes every frame (positions, then normals) and one for what
  // does not (UVs, then rest positions); triangles and spring lines index the same vertices.
  Buffer dynamic_vbo_, static_vbo_, triangle_ebo_, line_ebo_;
  Buffer scalar_vbo_;   // the colour-by scalar per vertex
  Buffer tangent_vbo_;  // modes 4-6: per-vertex tangent frame (xyz, handedness)
  bool tangents_stale_ = true;
  std::vector<float> tangents_;
  std::vector<ClothRange> grids_;  // the cloths' grids, for the tangents
  // Mesh cloths' tangents come from their triangles and UVs (empty without a mesh cloth).
  std::vector<float> mesh_uvs_, tangent_scratch_;
  std::vector<std::array<int, 3>> mesh_triangles_;
  Texture threads_;  // r: metal thread mask, g: weft on top
  double thread_fraction_ = -1.0;
  Texture weave_normals_;  // mode 6: the weave's tangent-space normal map
  double weave_bump_ = -1.0;
  bool custom_normals_ = false;  // set_normal_map gave the map
  ScalarRange scalar_range_;
  std::array<Texture, kAllColorMaps.size()> colormaps_;
  VertexArray cloth_vao_, line_vao_, empty_vao_;
  std::vector<float> staging_;         // positions, then normals, per render vertex
  std::vector<float> scalar_staging_;  // the colour-by scalar per render vertex
  std::size_t vertices_ = 0;           // the solver's
  // The GPU backend's cloth the last update_cloth() packed from (normals for the tangents are
  // read back from it only when a mode needs them), else null.
  const DeviceCloth* gpu_source_ = nullptr;  // the solver's device_cloth() at update_cloth
  Program pack_program_;          // cloth_pack.comp, built on the first GPU-backend frame
  Buffer seam_source_;            // seam_copies_ for cloth_pack.comp
  std::vector<int> seam_copies_;  // render vertex vertices_ + k copies solver vertex [k]
  GLsizei triangle_indices_ = 0, line_indices_ = 0;
};

}  // namespace clothlab::vis
