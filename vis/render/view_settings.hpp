// ViewSettings: every choice a user can make about how the cloth is shown, in one plain struct
// with its defaults here (docs/style.md: one settings struct edited by keys and the UI, no
// scattered statics). Nothing here changes the physics.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <optional>

#include "sim/forces/force_source.hpp"
#include "sim/scene/render_spec.hpp"
#include "vis/colormap/colormap.hpp"

namespace clothlab {
class SolverState;
struct Scene;
}  // namespace clothlab

namespace clothlab::vis {

// Keys 1-7 (docs/design.md): springs as lines coloured by strain, world normals as colour, Lambert
// with the fabric texture, the cloth BRDF, translucent cloth, the normal-mapped weave, and the
// light's depth map.
enum class DisplayMode {
  springs = 1,
  normals = 2,
  lambert = 3,
  cloth_brdf = 4,
  translucent = 5,
  weave = 6,
  light_depth = 7
};

// A rectangle of a framebuffer in pixels, origin bottom-left (GL's); empty by default.
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// A camera orbiting a target point: yaw about +y, pitch above the horizon, distance in metres.
struct OrbitCamera {
  glm::vec3 target{0.0f, 1.5f, 0.0f};
  float yaw_deg = 25.0f;
  float pitch_deg = 15.0f;
  float distance = 5.0f;
  float fov_deg = 40.0f;  // vertical field of view
  // Moves the image sideways by this much of the half-width (normalised device x; a lens
  // shift, not a turn): the window centres the scene in the part its panel leaves free.
  float lens_shift = 0.0f;

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;
  void orbit(float dyaw_deg, float dpitch_deg);
  void pan(float right, float up);  // in metres
  void zoom(float factor);          // distance *= factor
};

// What the cloth is coloured by in modes 2 and 3 (none: the mode's own colours). Each scalar is
// computed per vertex on the CPU only while it is shown (vis/render/scalar_field.hpp) and mapped
// through the colour map per fragment. error (the distance from the window's live reference run)
// is the window's alone: only it runs a reference, so kColourScalars leaves it out.
enum class ScalarField { none, force, speed, strain, height, contact, error };

struct ColorSettings {
  ScalarField field = ScalarField::none;
  ColorMap map = ColorMap::viridis;
  RangeMode range = RangeMode::automatic;
  ScalarRange fixed{0.0, 1.0};  // used when range is fixed
  bool shaded = false;          // multiply by the light (shape) or show the exact map colour
};

// Instanced arrow glyphs at (a subset of) the vertices: F force arrows, N normal arrows.
enum class ArrowScale { linear, log };
struct ArrowSettings {
  bool force = false;    // F
  bool normals = false;  // N
  // Every stride-th vertex along both grid directions; 0 chooses a stride that shows at most
  // about kAutoArrowsPerSide arrows along each side.
  int stride = 0;
  // Longest force arrow as a multiple of the spacing between shown vertices (linear: lengths
  // proportional to |F|; log: 3 decades below the range's top map onto the length).
  ArrowScale scale = ArrowScale::linear;
  float length = 0.9f;
};

// The scalars the cloth can be coloured by (ScalarField::none aside).
inline constexpr std::array<ScalarField, 5> kColourScalars{ScalarField::force, ScalarField::speed,
                                                           ScalarField::strain, ScalarField::height,
                                                           ScalarField::contact};

// The scientific views: what the colours and arrows show. A scene file leaves them at these
// defaults; the window's keys and panel and `render`'s options (--color-by, --arrows, ...) set
// them.
struct ScientificViews {
  ColorSettings color;
  ArrowSettings arrows;
  bool legends = true;  // colour bars for the colour-by scalar and the force arrows
  // Which force the |force| colouring and the force arrows show (probes show the total).
  ForceSource force_source = ForceSource::total;
  // Force arrows of the total show the springs' force instead where the total is near zero (a
  // cloth at rest, vis/render/arrow_field.hpp); the legend says so. Off once a source is chosen
  // explicitly (--force-source).
  bool springs_at_rest = true;
};

struct ViewSettings : ScientificViews {
  DisplayMode mode = DisplayMode::lambert;
  // render.quality as the scene says it; the renderer resolves automatic for its GL renderer
  // (vis/render/render_quality.hpp).
  RenderQuality quality = RenderQuality::automatic;
  float window_scale = 0.5f;  // render.window_scale (render_quality.hpp: window_scale)
  OrbitCamera camera;
  // The scene's light ([render.light]): a spot at light_position aimed at light_target (the
  // scene's centre when unset), or a directional light travelling along light_direction.
  LightType light_type = LightType::spot;
  glm::vec3 light_position{1.0f, 4.0f, 2.5f};  // m
  std::optional<glm::vec3> light_target;
  glm::vec3 light_direction{-0.35f, -1.0f, -0.55f};
  glm::vec3 light_color{1.0f, 0.95f, 0.88f};
  float light_intensity = 16.0f;  // scales light_color; spot: irradiance falls off as 1/d^2
  float light_size = 0.15f;       // m (spot) or radians (directional): the penumbrae of PCSS
  ShadowFilter shadows = ShadowFilter::pcf;
  int shadow_map_size = 2048;
  bool sky = true;
  float sky_turbidity = 2.0f;
  ClothLookSpec look;  // mode 4-6 material ([render.cloth])
  float ambient = 0.05f;
  // Mode 1's colour map saturates at +-strain_range; 0: automatic, the kStrainRangeQuantile
  // quantile of the springs' |strain| this frame (vis/render/cloth_geometry.hpp).
  float strain_range = 0.0f;
  float floor_height = 0.0f;     // m
  float floor_half_size = 6.0f;  // m
  float floor_tile_size = 1.0f;  // m per floor texture repeat
  float fabric_repeat = 6.0f;    // fabric texture repeats across a cloth
  // Mode 6 draws the weave this many times coarser, so its relief shows from the default
  // camera: at 6 repeats a thread of a 2 m sheet is 2 cm, 2-3 pixels there, and the normal
  // map's mipmaps average the relief flat (docs/rendering.md section 3).
  float weave_coarsening = 3.0f;
  glm::vec3 background{0.60f, 0.70f, 0.80f};  // sRGB
};

// The camera's projection * view for a view of width x height pixels: every pass that must
// land on the same pixels (the shaded cloth, the field pass, tests projecting a vertex) uses it.
glm::mat4 view_projection(const OrbitCamera& camera, int width, int height);

// The fabric's repeats across a cloth in the view's mode: mode 6's weave is coarser.
float fabric_repeat_of(const ViewSettings& view);

// Settings framing the solver's cloth: camera on its bounding box, floor below its lowest point
// (at 0 when the cloth is above 0), light above and in front.
ViewSettings default_view(const SolverState& solver);

// default_view with the scene's [render] choices: display mode, shadows, light, sky; framing the
// colliders (other than planes) as well as the cloth, and the floor at the height of a ground
// plane collider where the scene has one (floor_collider.hpp).
ViewSettings scene_view(const Scene& scene, const SolverState& solver);

}  // namespace clothlab::vis
