// The parameter table, part two: [render] and its tables (how the scene is shown; vis/ reads
// them, nothing here changes the physics). See parameters.cpp.
#include <vector>

#include "sim/scene/parameter_binding.hpp"

// Records are designated initializers that leave the fields they do not name at their
// defaults; GCC 12's -Wextra warns about every such field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace clothlab {
namespace {

using namespace binding;
using S = Section;

std::vector<Parameter> render_table() {
  return {
      row<&RenderSpec::mode>({.name = "mode",
                              .range = between(1, 7),
                              .range_text = "a display mode from 1 to 7",
                              .fallback = "3",
                              .description = "the display mode (key 1-7) the view starts in"}),
      choice_row<&RenderSpec::quality, kRenderQualityNames, "render quality">(
          {.name = "quality",
           .fallback = "\"auto\"",
           .description = "full, fast (same look, cheaper on a CPU renderer), or auto: fast on a "
                          "software renderer"}),
      row<&RenderSpec::window_scale>(
          {.name = "window_scale",
           .range = between(0.25, 1.0),
           .range_text = "between 0.25 and 1",
           .fallback = "0.5",
           .description = "at fast quality, the window draws the scene at this fraction of its "
                          "pixels per side and scales it up (the panel stays sharp)"}),
      choice_row<&RenderSpec::shadows, kShadowFilterNames, "shadow filter">(
          {.name = "shadows", .fallback = "\"pcf\"", .description = "the shadow filter"}),
      row<&RenderSpec::shadow_map_size>({.name = "shadow_map_size",
                                         .range = between(256, 8192),
                                         .range_text = "between 256 and 8192 texels",
                                         .fallback = "2048",
                                         .ui = between(512, 4096),
                                         .description = "texels per side of the shadow map"}),
      table_row<&RenderSpec::light, S::light>({.name = "light", .description = "the light"}),
      table_row<&RenderSpec::sky, S::sky>({.name = "sky", .description = "the Preetham sky"}),
      table_row<&RenderSpec::pole, S::pole>(
          {.name = "pole", .description = "the bar the pinned row hangs from"}),
      tables_row<&RenderSpec::meshes, S::mesh, " of tables ([[render.meshes]])">(
          {.name = "meshes", .description = "scenery: casts and takes shadows, does not collide"}),
      table_row<&RenderSpec::cloth, S::look>(
          {.name = "cloth", .description = "the cloth's material in modes 4-6"}),
      table_row<&RenderSpec::camera, S::camera>(
          {.name = "camera", .description = "where the view starts; what is absent is framed"}),
  };
}

std::vector<Parameter> light_sky_pole() {
  return {
      choice_row<&LightSpec::type, kLightTypeNames, "light type">(
          {.name = "type", .fallback = "\"spot\"", .description = "spot or directional"}),
      row<&LightSpec::position>({.name = "position",
                                 .unit = "m",
                                 .fallback = "framed",
                                 .description = "spot: where it stands"}),
      row<&LightSpec::target>({.name = "target",
                               .unit = "m",
                               .fallback = "framed",
                               .description = "spot: what it points at (not its position)"}),
      row<&LightSpec::direction>({.name = "direction",
                                  .fallback = "[-0.35, -1, -0.55]",
                                  .description = "directional: the way the light travels"}),
      row<&LightSpec::color>({.name = "color",
                              .range = between(0.0, 1e3),
                              .fallback = "[1, 0.95, 0.88]",
                              .description = "linear RGB"}),
      row<&LightSpec::intensity>(
          {.name = "intensity",
           .range = kNonNegative,
           .fallback = "1.2",
           .description = "irradiance at the cloth's centre (spot) or everywhere"}),
      row<&LightSpec::size>({.name = "size",
                             .range = kNonNegative,
                             .unit = "m or rad",
                             .fallback = "0.15",
                             .description = "the emitter's width: PCSS penumbrae widen with it"}),
      row<&SkySpec::enabled>(
          {.name = "enabled", .fallback = "true", .description = "draw the sky"}),
      row<&SkySpec::turbidity>({.name = "turbidity",
                                .range = between(1.7, 10.0),
                                .fallback = "2",
                                .description = "2 clear .. 10 hazy (Preetham's fitted range)"}),
      row<&PoleSpec::enabled>(
          {.name = "enabled", .fallback = "true", .description = "draw the pole"}),
      row<&PoleSpec::radius>(
          {.name = "radius", .range = between(1e-4, 1.0), .unit = "m", .fallback = "0.02"}),
  };
}

std::vector<Parameter> meshes() {
  return {
      choice_row<&MeshSpec::kind, kMeshKindNames, "mesh type">(
          {.name = "type",
           .description = "sphere, box, torus_knot or obj",
           .required = "a mesh needs type = \"sphere\", \"box\", \"torus_knot\" or \"obj\""}),
      row<&MeshSpec::center>({.name = "center", .unit = "m", .fallback = "[0, 0.5, 0]"}),
      row<&MeshSpec::radius>({.name = "radius",
                              .range = kPositive,
                              .unit = "m",
                              .fallback = "0.3",
                              .description = "sphere; torus knot: overall radius"}),
      row<&MeshSpec::half_extents>({.name = "half_extents",
                                    .range = kPositive,
                                    .unit = "m",
                                    .fallback = "[0.2, 0.2, 0.2]",
                                    .description = "box"}),
      row<&MeshSpec::rotation>({.name = "rotation",
                                .unit = "deg",
                                .fallback = "[0, 0, 0]",
                                .description = "about x, then y, then z"}),
      row<&MeshSpec::color>({.name = "color",
                             .range = kUnit,
                             .fallback = "[0.75, 0.75, 0.75]",
                             .description = "sRGB"}),
      row<&MeshSpec::file>({.name = "file", .description = "obj: the OBJ, relative to the scene"}),
      row<&MeshSpec::scale>({.name = "scale",
                             .range = kPositive,
                             .fallback = "1",
                             .description = "obj: about its own origin"}),
      row<&MeshSpec::smooth>(
          {.name = "smooth",
           .fallback = "false",
           .description = "obj: normals averaged at shared vertices (false: one per facet)"}),
  };
}

std::vector<Parameter> look_and_camera() {
  return {
      row<&ClothLookSpec::roughness>({.name = "roughness",
                                      .range = kUnit,
                                      .fallback = "0.5",
                                      .description = "Oren-Nayar roughness"}),
      row<&ClothLookSpec::sheen>({.name = "sheen",
                                  .range = kUnit,
                                  .fallback = "1",
                                  .description = "sheen strength (colour sqrt(albedo) * sheen)"}),
      row<&ClothLookSpec::sheen_roughness>({.name = "sheen_roughness",
                                            .range = between(0.07, 1.0),
                                            .fallback = "0.5",
                                            .description = "Charlie sheen alpha"}),
      choice_row<&ClothLookSpec::threads, kThreadMetalNames, "thread metal">(
          {.name = "threads", .fallback = "\"gold\"", .description = "the metallic weft threads"}),
      row<&ClothLookSpec::opacity>({.name = "opacity",
                                    .range = kUnit,
                                    .fallback = "0.85",
                                    .description = "mode 5: thread coverage"}),
      row<&ClothLookSpec::transmission>({.name = "transmission",
                                         .range = kUnit,
                                         .fallback = "0.6",
                                         .description = "mode 5: light a thread lets through"}),
      row<&ClothLookSpec::thread_fraction>({.name = "thread_fraction",
                                            .range = kUnit,
                                            .fallback = "0.125",
                                            .description = "of weft threads that are metallic"}),
      row<&ClothLookSpec::color>({.name = "color",
                                  .range = kUnit,
                                  .fallback = "woven texture",
                                  .description = "a plain sRGB albedo instead of the weave"}),
      row<&ClothLookSpec::bump>({.name = "bump",
                                 .range = between(0.0, 2.0),
                                 .fallback = "1",
                                 .description = "mode 6: the weave's relief"}),
      row<&ClothLookSpec::subsurface>({.name = "subsurface",
                                       .range = kUnit,
                                       .fallback = "1",
                                       .description = "mode 6: light spread through the yarn"}),
      row<&ClothLookSpec::glints>({.name = "glints",
                                   .fallback = "true",
                                   .description = "mode 4: specular lights beside the camera"}),
      row<&CameraSpec::target>({.name = "target", .unit = "m", .fallback = "framed"}),
      row<&CameraSpec::yaw>({.name = "yaw",
                             .unit = "deg",
                             .fallback = "framed",
                             .description = "about the vertical, from +z"}),
      row<&CameraSpec::pitch>({.name = "pitch",
                               .range = between(-89.0, 89.0),
                               .unit = "deg",
                               .fallback = "framed",
                               .description = "raised above the horizontal"}),
      row<&CameraSpec::distance>({.name = "distance",
                                  .range = between(0.01, 1e4),
                                  .unit = "m",
                                  .fallback = "framed",
                                  .description = "from the target"}),
  };
}

}  // namespace

std::vector<Parameter> render_parameters() {
  std::vector<Parameter> all;
  for (auto part : {render_table(), light_sky_pole(), meshes(), look_and_camera()})
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace clothlab
