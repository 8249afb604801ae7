// The scene's [render] table (docs/design.md, "Scene file"): how the scene is shown -- display
// mode, shadows, the light, the sky, the pole the cloth hangs from, extra meshes and the cloth's
// look. Plain data read by vis/; nothing here changes the physics.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace clothlab {

struct TriangleMesh;

using Vec3d = std::array<double, 3>;

enum class ShadowFilter { none, pcf, pcss };
// How much a frame may cost (docs/rendering.md, "Render quality"): full is the reference look;
// fast keeps every mode's meaning and look at a fraction of the cost on a software renderer;
// automatic picks fast on one (llvmpipe, softpipe, swrast) and full elsewhere.
enum class RenderQuality { automatic, full, fast };
enum class LightType { spot, directional };
enum class MeshKind { sphere, box, torus_knot, obj };
enum class ThreadMetal { none, gold, silver };

struct LightSpec {
  LightType type = LightType::spot;
  // Spot: where it stands and what it points at (absent: placed above and in front of the
  // cloth, as the default view does). Directional: the direction the light travels.
  std::optional<Vec3d> position, target;
  Vec3d direction{-0.35, -1.0, -0.55};
  Vec3d color{1.0, 0.95, 0.88};  // linear RGB
  double intensity = 1.2;  // irradiance at the cloth's centre (spot) or everywhere (directional)
  double size = 0.15;      // m, the emitter's width: PCSS penumbrae widen with it
};

struct SkySpec {
  bool enabled = true;
  double turbidity = 2.0;  // Preetham 1999: 2 (clear) .. 10 (hazy); 2 reads blue near the horizon
};

// The bar the cloth's pinned vertices hang from, placed along the pins (when there are at least
// two pinned vertices in a row).
struct PoleSpec {
  bool enabled = true;
  double radius = 0.02;  // m
};

struct MeshSpec {
  MeshKind kind = MeshKind::sphere;
  Vec3d center{0.0, 0.5, 0.0};
  double radius = 0.3;                // sphere; torus knot overall radius
  Vec3d half_extents{0.2, 0.2, 0.2};  // box
  Vec3d rotation{0.0, 0.0, 0.0};      // degrees about x, then y, then z
  Vec3d color{0.75, 0.75, 0.75};      // sRGB albedo
  // obj: a Wavefront OBJ (path relative to the scene file's folder), scaled about its own origin
  // and then placed at `center` turned by `rotation`; smooth = false gives every facet its own
  // normal (hard-edged furniture), true averages them (area-weighted) at shared vertices.
  std::string file;
  double scale = 1.0;
  bool smooth = false;
  std::shared_ptr<const TriangleMesh> obj;  // read by the load step (load/)
  std::string key;                          // "render.meshes[2]", for messages
};

// The cloth's material in modes 4-6 (docs/rendering.md sections 2-5).
struct ClothLookSpec {
  double roughness = 0.5;        // Oren-Nayar roughness, 0..1
  double sheen = 1.0;            // sheen strength, 0..1 (sheen colour = sqrt(albedo) * sheen)
  double sheen_roughness = 0.5;  // Charlie alpha, 0.07..1
  ThreadMetal threads = ThreadMetal::gold;
  double thread_fraction = 0.125;  // of weft threads that are metallic
  double opacity = 0.85;           // mode 5: thread coverage c (1 - light let through the gaps)
  double transmission = 0.6;       // mode 5: light a thread lets through, tau (times its albedo)
  double bump = 1.0;               // mode 6: the weave's relief (normal-map strength), 0..2
  double subsurface = 1.0;         // mode 6: share of light spread through the yarn, 0..1
  bool glints = true;              // mode 4: two specular-only lights beside the camera
  std::optional<Vec3d> color;      // a plain sRGB albedo instead of the woven texture
};

// Where the view starts (the orbit camera: it looks at `target` from `distance` m, turned `yaw`
// degrees about the vertical from +z and raised `pitch` degrees); anything absent is framed from
// the cloth and the colliders.
struct CameraSpec {
  std::optional<Vec3d> target;
  std::optional<double> yaw, pitch, distance;
};

struct RenderSpec {
  int mode = 3;  // the display mode (keys 1-7) the view starts in
  RenderQuality quality = RenderQuality::automatic;
  // At fast quality the window draws the scene at this fraction of its pixels per side and
  // scales it up (vis/render/render_quality.hpp); renders keep the size asked for.
  double window_scale = 0.5;
  ShadowFilter shadows = ShadowFilter::pcf;
  int shadow_map_size = 2048;
  LightSpec light;
  SkySpec sky;
  PoleSpec pole;
  std::vector<MeshSpec> meshes;
  ClothLookSpec cloth;
  CameraSpec camera;
};

// Names as written in scene files, in enum order (the parser and the UI list them).
extern const std::array<std::pair<ShadowFilter, const char*>, 3> kShadowFilterNames;
extern const std::array<std::pair<RenderQuality, const char*>, 3> kRenderQualityNames;
extern const std::array<std::pair<LightType, const char*>, 2> kLightTypeNames;
extern const std::array<std::pair<MeshKind, const char*>, 4> kMeshKindNames;
extern const std::array<std::pair<ThreadMetal, const char*>, 3> kThreadMetalNames;

const char* to_string(ShadowFilter filter);
const char* to_string(RenderQuality quality);
const char* to_string(MeshKind kind);
const char* to_string(ThreadMetal metal);

}  // namespace clothlab
