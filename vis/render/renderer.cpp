#include "vis/render/renderer.hpp"

#include <algorithm>

#include "gl/draw_state.hpp"
#include "gl/program.hpp"
#include "gl/uploads.hpp"
#include "sim/fields/frame_fields.hpp"
#include "sim/solver.hpp"
#include "vis/colormap/colormap_texture.hpp"
#include "vis/passes/diffusion_pass.hpp"
#include "vis/passes/shadow_pass.hpp"
#include "vis/passes/sky_pass.hpp"
#include "vis/render/collider_scenery.hpp"
#include "vis/render/render_quality.hpp"
#include "vis/render/scenery.hpp"
#include "vis/render/shading_variant.hpp"

namespace clothlab::vis {
namespace {

// std140 layout of the Frame block in shaders/frame.glsl.
struct FrameBlock {
  glm::mat4 view_proj;
  glm::mat4 light_view_proj;
  glm::vec4 eye;
  glm::vec4 light_position;   // w: 0 spot, 1 directional
  glm::vec4 light_direction;  // w: cone edge cosine
  glm::vec4 light_color;      // rgb intensity, a ambient
  glm::vec4 params;           // x strain range, y floor height
  glm::vec4 shadow;           // x filter, y 1 / size, z light size (uv), w normal offset
  glm::vec4 shadow_range;     // x near, y far, z orthographic, w coloured shadows
};

FrameBlock make_frame(const ViewSettings& view, const LightRig& light, int width, int height,
                      bool translucent) {
  FrameBlock frame;
  frame.view_proj = view_projection(view.camera, width, height);
  frame.light_view_proj = light.view_proj;
  frame.eye = glm::vec4(view.camera.eye(), 1.0f);
  frame.light_position = glm::vec4(light.position, light.directional ? 1.0f : 0.0f);
  frame.light_direction = glm::vec4(light.direction, light.cone_cos);
  frame.light_color = glm::vec4(view.light_color * view.light_intensity, view.ambient);
  frame.params = glm::vec4(view.strain_range, view.floor_height, 0.0f, 0.0f);
  const float filter = view.shadows == ShadowFilter::pcss  ? 2.0f
                       : view.shadows == ShadowFilter::pcf ? 1.0f
                                                           : 0.0f;
  frame.shadow =
      glm::vec4(filter, 1.0f / float(view.shadow_map_size), light.size_uv, light.normal_offset);
  frame.shadow_range =
      glm::vec4(light.near, light.far, light.directional ? 1.0f : 0.0f, translucent ? 1.0f : 0.0f);
  return frame;
}

}  // namespace

Renderer::Renderer()
    : scenery_(std::make_unique<Scenery>()),
      gl_renderer_(gl_renderer_name()),
      frame_ubo_(dynamic_buffer(sizeof(FrameBlock))),
      empty_vao_(make_vertex_array()) {
  for (ColorMap map : kAllColorMaps) colormaps_[static_cast<int>(map)] = make_colormap_texture(map);
}

Renderer::~Renderer() = default;

RenderQuality Renderer::quality(const ViewSettings& view) const {
  return resolve_quality(view.quality, gl_renderer_);
}

void Renderer::enable_pass_timing(bool on) {
  if (on && !timer_) timer_ = std::make_unique<PassTimer>();
  if (!on) timer_.reset();
}

void Renderer::set_scene(const RenderSpec& spec, const Solver& solver,
                         const std::vector<ColliderSpec>& colliders) {
  scenery_->set_scene(spec, solver);
  if (colliders.empty()) {
    colliders_.reset();
  } else {
    if (!colliders_) colliders_ = std::make_unique<ColliderScenery>();
    colliders_->set_colliders(colliders, solver);
  }
  anchor_sky();
}

void Renderer::anchor_sky() {
  const auto [lo, hi] = casters_box();
  sky_anchor_ = 0.5f * (lo + hi);
}

void Renderer::set_cloth(const SolverState& solver) {
  cloth_.build(solver);
}

void Renderer::update_cloth(const FrameFields& fields) {
  cloth_.update(fields);
  if (colliders_) colliders_->update(fields.time);  // where the moving ones are now
}

bool Renderer::draws_springs(const ViewSettings& view) const {
  return view.mode == DisplayMode::springs || cloth_.triangle_indices() == 0;
}

void Renderer::set_scalars(const std::vector<float>& values, ScalarRange range) {
  cloth_.set_scalars(values);
  scalar_range_ = range;
}

void Renderer::set_normal_map(const Image* map) {
  cloth_pass_.set_normal_map(map);
}

// render.quality fast draws with maps of half the size: the shadow map (its kernel keeps its
// width in the world: 0.75 of its texels, shaders/lighting.glsl) and mode 6's diffusion atlas.
void Renderer::draw(const ViewSettings& view, int width, int height, const PixelRect& covered) {
  if (quality(view) != RenderQuality::fast) return draw_at(view, false, width, height, covered);
  ViewSettings half = view;
  half.shadow_map_size = shadow_map_texels(RenderQuality::fast, view.shadow_map_size);
  draw_at(half, true, width, height, covered);
}

void Renderer::draw_at(const ViewSettings& view, bool fast, int width, int height,
                       const PixelRect& covered) {
  const GLuint target = bound_draw_framebuffer();  // the shadow pass binds its own first
  const bool depth_view = view.mode == DisplayMode::light_depth;
  const bool shadows = view.shadows != ShadowFilter::none || depth_view;
  fit_light_to_casters(view);
  // Mode 5 with shadows: the cloth's shadow is coloured by its transmittance.
  const bool translucent =
      view.mode == DisplayMode::translucent && view.shadows != ShadowFilter::none;
  const glm::mat4 view_proj = upload_frame(view, width, height, translucent);
  // Fast quality draws a large grid cloth as coarse as its size on screen allows.
  cloth_.set_detail(fast && coarse_cloth_
                        ? pixels_per_metre(view.camera.eye(), cloth_.lo(), cloth_.hi(),
                                           view.camera.fov_deg, height)
                        : 0.0);
  const ShadingVariant variant{shadows ? view.shadows : ShadowFilter::none, translucent, fast};
  const std::string shading = variant.defines();
  if (shadows) {
    if (timer_) timer_->begin(Pass::shadow);
    draw_shadow_map(view, translucent);
    shadow_->bind_textures();
  } else {
    shadow_.reset();  // nothing needs the map: its memory goes too
  }
  const bool subsurface = run_diffusion(view, shading, fast);
  if (timer_) timer_->begin(Pass::scene);
  // The main pass draws into what the caller bound (the shadow pass bound its own).
  bind_target(target, width, height);
  set_capability(GL_FRAMEBUFFER_SRGB, true);
  set_capability(GL_DEPTH_TEST, true);
  set_capability(GL_MULTISAMPLE, true);
  set_capability(GL_CULL_FACE, false);  // cloth is two-sided
  const glm::vec3 bg = view.background;
  const float clear[4] = {bg.r, bg.g, bg.b, 1.0f};
  clear_target(clear);
  // A CPU rasteriser shades no fragment the depth test rejects: 30 % of a 1280-pixel window
  // lies under the panel.
  if (covered.width > 0 && covered.height > 0)
    clear_depth_in(covered.x, covered.y, covered.width, covered.height, 0.0f);
  if (depth_view)
    return depth_view_.draw(width, height, colormap_texture(ColorMap::turbo), empty_vao_.get());

  // The opaque surfaces before the floor, which covers most of the image: the depth test then
  // skips the floor behind them, and a CPU renderer shades only what it keeps. The translucent
  // cloth (mode 5) goes last, over everything opaque and the sky.
  scenery_->draw(shading);
  if (colliders_) colliders_->draw(shading);
  const bool blended_cloth = view.mode == DisplayMode::translucent;
  if (!blended_cloth) draw_cloth(view, shading, subsurface);
  const GLuint sky_cube = prepare_sky(view);
  floor_.draw(view, empty_vao_.get(), shading, sky_cube);
  draw_sky(view, view_proj);
  if (blended_cloth) draw_cloth(view, shading, subsurface);
  unbind_vertex_array();
}

// A cloth without triangles (two vertices and a spring) has no surface to shade: it is drawn as
// its springs and vertices in every mode.
void Renderer::draw_cloth(const ViewSettings& view, const std::string& shading, bool subsurface) {
  const bool surface = cloth_.triangle_indices() > 0;
  if (view.mode == DisplayMode::springs || !surface) springs_.draw(cloth_);
  if (!surface)
    springs_.draw_vertices(cloth_);
  else if (view.mode != DisplayMode::springs)
    cloth_pass_.draw(view, cloth_, scalar_range_, colormap_texture(view.color.map),
                     subsurface ? diffusion_.get() : nullptr, shading);
}

// The box of the casters the light must see: the cloth, the scenery and the colliders (planes
// aside).
std::pair<glm::vec3, glm::vec3> Renderer::casters_box() const {
  glm::vec3 lo = cloth_.lo(), hi = cloth_.hi();
  if (!scenery_->empty()) {
    lo = glm::min(lo, scenery_->lo());
    hi = glm::max(hi, scenery_->hi());
  }
  if (colliders_ && colliders_->has_bounds()) {
    lo = glm::min(lo, colliders_->lo());
    hi = glm::max(hi, colliders_->hi());
  }
  return {lo, hi};
}

// The light fitted to the casters' box of this frame.
void Renderer::fit_light_to_casters(const ViewSettings& view) {
  const auto [lo, hi] = casters_box();
  light_ = fit_light(view, lo, hi, view.floor_height, view.shadow_map_size);
}

// The Frame block every pass reads (binding 0); returns the view-projection matrix.
glm::mat4 Renderer::upload_frame(const ViewSettings& view, int width, int height,
                                 bool translucent) {
  FrameBlock frame = make_frame(view, light_, width, height, translucent);
  // Springs are drawn in mode 1, and in every mode for a cloth without triangles.
  const bool springs = draws_springs(view);
  if (!(view.strain_range > 0.0f)) frame.params.x = springs ? cloth_.strain_top() : kMinStrainRange;
  strain_range_.reset();
  if (springs) strain_range_ = ScalarRange{-frame.params.x, frame.params.x};
  update_buffer(frame_ubo_.get(), &frame, sizeof frame);
  bind_uniform_buffer(0, frame_ubo_.get());
  return frame.view_proj;
}

// Mode 6's light through the yarn: its own passes before the main one. Returns whether they ran.
bool Renderer::run_diffusion(const ViewSettings& view, const std::string& shading, bool fast) {
  const bool subsurface = view.mode == DisplayMode::weave && view.look.subsurface > 0.0 &&
                          cloth_.triangle_indices() > 0;
  if (!subsurface) {
    diffusion_.reset();
    return false;
  }
  if (timer_) timer_->begin(Pass::diffusion);
  const int atlas = diffusion_atlas_texels(fast ? RenderQuality::fast : RenderQuality::full);
  if (!diffusion_ || diffusion_->size() != atlas)
    diffusion_ = std::make_unique<DiffusionPass>(atlas);
  cloth_.update_tangents();
  cloth_pass_.bind_weave(view.look.bump);
  diffusion_->run(cloth_.cloth_vao(), cloth_.triangle_indices(), cloth_.atlas_per_metre(),
                  fabric_repeat_of(view), shading);
  return true;
}

int Renderer::sky_bakes() const {
  return sky_ ? sky_->bakes() : 0;
}

// The sky's cube map, or 0 without a sky. A spot light's sun lies towards the light from the
// casters' centre when the scene was set (sky_anchor_): the sky stays put while the cloth moves.
GLuint Renderer::prepare_sky(const ViewSettings& view) {
  if (!view.sky) {
    sky_.reset();
    return 0;
  }
  if (timer_) timer_->begin(Pass::sky);
  if (!sky_) sky_ = std::make_unique<SkyPass>();
  if (!sky_anchor_) anchor_sky();  // drawn without set_scene: the casters as first drawn
  const glm::vec3 sun = light_.directional ? -light_.direction : light_.position - *sky_anchor_;
  const GLuint cube = sky_->prepare(sun, view.sky_turbidity);
  if (timer_) timer_->begin(Pass::scene);
  return cube;
}

// The sky after the opaque passes: it fills only what nothing else covered.
void Renderer::draw_sky(const ViewSettings& view, const glm::mat4& view_proj) {
  if (!sky_) return;
  if (timer_) timer_->begin(Pass::sky);
  sky_->draw(view_proj, view.camera.eye());
  if (timer_) timer_->begin(Pass::scene);  // what follows the sky belongs to the scene again
}

// Every caster into the light's depth map: the floor, the cloth (its current positions), the
// scenery and the colliders; with coloured shadows also the opaque casters alone and the cloth's
// transmittance.
void Renderer::draw_shadow_map(const ViewSettings& view, bool translucent) {
  if (!shadow_) shadow_ = std::make_unique<ShadowPass>();
  shadow_->begin(view.shadow_map_size);
  // The floor last: it covers the whole map, and the depth test skips it behind the casters.
  const ClothGeometry::Drawn& drawn = cloth_.drawn();
  if (drawn.count > 0)
    shadow_->draw_triangles(cloth_.cloth_vao(), drawn.count, glm::mat4(1.0f), drawn.first);
  draw_shadow_casters();
  shadow_->draw_floor(view.floor_height, view.floor_half_size);
  if (translucent) {
    shadow_->begin_opaque();
    draw_shadow_casters();
    shadow_->draw_floor(view.floor_height, view.floor_half_size);
    if (cloth_.triangle_indices() > 0) {
      shadow_->begin_transmittance();
      const auto& c = view.look.color;
      const glm::vec3 flat = c ? glm::vec3((*c)[0], (*c)[1], (*c)[2]) : glm::vec3(1.0f);
      shadow_->draw_transmittance(cloth_.cloth_vao(), drawn.count, drawn.first,
                                  cloth_pass_.fabric(), fabric_repeat_of(view), flat, c.has_value(),
                                  float(view.look.opacity), float(view.look.transmission));
    }
  }
  shadow_->end();
}

// The scenery and the colliders into the shadow map.
void Renderer::draw_shadow_casters() {
  scenery_->draw_shadow(*shadow_);
  if (colliders_) colliders_->draw_shadow(*shadow_);
}

}  // namespace clothlab::vis
