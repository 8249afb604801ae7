#include "vis/passes/cloth_pass.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gl/program.hpp"
#include "gl/uploads.hpp"
#include "vis/passes/diffusion_pass.hpp"
#include "vis/render/cloth_geometry.hpp"
#include "vis/render/shading_variant.hpp"
#include "vis/textures/fabric_texture.hpp"
#include "vis/textures/image_texture.hpp"
#include "vis/textures/weave_maps.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations of shaders/cloth.frag (no lookups per frame).
constexpr GLint kClothTextureRepeat = 1, kClothRange = 3, kClothShaded = 4, kClothLook = 5,
                kClothMetalF0 = 6, kClothGlints = 7, kClothFlatAlbedo = 9, kClothUseFlat = 10,
                kClothTranslucency = 11, kClothDiffusionWeights = 12, kClothSubsurface = 15,
                kClothGlintsOn = 16;
// Mode 6's diffusion weights per channel (sharp term, then the three blurs of DiffusionPass;
// each row sums to 1): red light travels farthest through the dyed yarn, blue least.
constexpr float kDiffusionWeights[3][4] = {
    {0.40f, 0.25f, 0.20f, 0.15f}, {0.60f, 0.25f, 0.11f, 0.04f}, {0.72f, 0.20f, 0.06f, 0.02f}};
constexpr int kThreadTextureSize = 256;  // as the fabric albedo, so the weaves line up

// The cloth shader's own compile-time choices (shaders/cloth.frag), after the shading variant's.
std::string cloth_defines(DisplayMode mode, bool color_by) {
  return "#define CLOTH_MODE " + std::to_string(static_cast<int>(mode)) +
         "\n#define CLOTH_COLOR_BY " + (color_by ? "1" : "0") + "\n";
}

// shaders/cloth.vert's switch to the flat-normal geometry shader (shaders/cloth_flat.geom).
constexpr const char* kFlatNormals = "#define FLAT_NORMALS 1\n";

}  // namespace

ClothPass::ClothPass()
    : programs_({"cloth.vert", "cloth.frag"},
                ShadingVariant{}.defines() + cloth_defines(DisplayMode::lambert, false)),
      fabric_(upload_texture(make_fabric_texture())) {
  glObjectLabel(GL_TEXTURE, fabric_.get(), -1, "fabric albedo");
}

void ClothPass::draw(const ViewSettings& view, ClothGeometry& cloth, ScalarRange range,
                     GLuint colormap, const DiffusionPass* diffusion, const std::string& shading) {
  const std::string defines =
      shading + cloth_defines(view.mode, view.color.field != ScalarField::none);
  if (cloth.flat_normals() && !flat_programs_)
    flat_programs_ = std::make_unique<ProgramVariants>(
        std::vector<std::string>{"cloth.vert", "cloth_flat.geom", "cloth.frag"},
        defines + kFlatNormals);
  program_ =
      cloth.flat_normals() ? flat_programs_->get(defines + kFlatNormals) : programs_.get(defines);
  const GLuint p = program_;
  glUseProgram(p);
  glProgramUniform1f(p, kClothTextureRepeat, fabric_repeat_of(view));
  glProgramUniform2f(p, kClothRange, static_cast<float>(range.min), static_cast<float>(range.max));
  glProgramUniform1i(p, kClothShaded, view.color.shaded ? 1 : 0);
  glBindTextureUnit(0, fabric_.get());
  glBindTextureUnit(1, colormap);
  // Units only modes 4 and 6 read are emptied otherwise: llvmpipe specialises the shader for
  // every bound texture, and a stale one made mode 3 measurably slower after mode 6.
  for (GLuint unit : {2u, 3u, 10u, 11u, 12u}) glBindTextureUnit(unit, 0);
  set_material(view);
  const bool blended = view.mode == DisplayMode::translucent;
  if (blended) {
    // Over what is behind it; its own layers in drawing order (no sorting: one sheet).
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
  }
  if (view.mode == DisplayMode::weave) set_weave(view, cloth, diffusion);
  if (view.mode == DisplayMode::cloth_brdf) set_brdf(view, cloth);
  glBindVertexArray(cloth.cloth_vao());
  const ClothGeometry::Drawn& drawn = cloth.drawn();
  glDrawElements(GL_TRIANGLES, drawn.count, GL_UNSIGNED_INT, element_offset(drawn.first));
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
}

// A plain albedo instead of the weave, and mode 5's coverage and transmission.
void ClothPass::set_material(const ViewSettings& view) {
  const GLuint p = program_;
  const auto& c = view.look.color;
  const glm::vec3 flat = c ? glm::vec3((*c)[0], (*c)[1], (*c)[2]) : glm::vec3(1.0f);
  glProgramUniform3f(p, kClothFlatAlbedo, flat.r, flat.g, flat.b);
  glProgramUniform1i(p, kClothUseFlat, c ? 1 : 0);
  glProgramUniform2f(p, kClothTranslucency, float(view.look.opacity),
                     float(view.look.transmission));
}

// Mode 6: the relief, and the diffusion's blurs mixed in per channel by `subsurface`.
void ClothPass::set_weave(const ViewSettings& view, ClothGeometry& cloth,
                          const DiffusionPass* diffusion) {
  cloth.update_tangents();
  bind_weave(view.look.bump);
  const float s = diffusion ? static_cast<float>(view.look.subsurface) : 0.0f;
  float w[3][4];
  for (int c = 0; c < 3; ++c) {
    w[c][0] = 1.0f - s * (1.0f - kDiffusionWeights[c][0]);
    for (int k = 1; k < 4; ++k) w[c][k] = s * kDiffusionWeights[c][k];
  }
  glProgramUniform4fv(program_, kClothDiffusionWeights, 3, &w[0][0]);
  glProgramUniform1i(program_, kClothSubsurface, diffusion ? 1 : 0);
  if (diffusion) diffusion->bind_results();
}

// Mode 4: the BRDF's parameters, the metal threads and two glint lights beside the camera
// (specular only), so the threads sparkle from where one looks.
void ClothPass::set_brdf(const ViewSettings& view, ClothGeometry& cloth) {
  const GLuint p = program_;
  cloth.update_tangents();
  set_thread_fraction(view.look.thread_fraction);
  glBindTextureUnit(2, threads_.get());
  const ClothLookSpec& look = view.look;
  glProgramUniform3f(p, kClothLook, float(look.roughness), float(look.sheen),
                     float(look.sheen_roughness));
  const glm::vec3 f0 = look.threads == ThreadMetal::gold     ? glm::vec3(1.00f, 0.71f, 0.29f)
                       : look.threads == ThreadMetal::silver ? glm::vec3(0.95f, 0.93f, 0.88f)
                                                             : glm::vec3(0.0f);
  glProgramUniform3f(p, kClothMetalF0, f0.x, f0.y, f0.z);
  const glm::mat4 v = view.camera.view();
  const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
  const glm::vec3 eye = view.camera.eye(), d = glm::vec3(0.3f * view.camera.distance);
  const glm::vec3 glints[2] = {eye + d * (0.6f * right + 0.4f * up),
                               eye + d * (-0.7f * right + 0.2f * up)};
  glProgramUniform3fv(p, kClothGlints, 2, &glints[0][0]);
  glProgramUniform1i(p, kClothGlintsOn, look.glints ? 1 : 0);
}

// The thread texture for a metal fraction: r the mask of metal threads, g where the weft is on
// top (vis/textures/weave_maps.hpp), both linear, mipmapped like the fabric.
void ClothPass::set_thread_fraction(double fraction) {
  if (fraction == thread_fraction_ && threads_) return;
  const float limit = max_metal_fraction(kThreadTextureSize);
  const Image mask = make_thread_mask(kThreadTextureSize, std::min(float(fraction), limit));
  const Image direction = make_thread_direction(kThreadTextureSize);
  std::vector<std::uint8_t> rg(2 * static_cast<std::size_t>(kThreadTextureSize) *
                               kThreadTextureSize);
  for (std::size_t i = 0; i < rg.size() / 2; ++i) {
    rg[2 * i] = mask.rgba[4 * i];
    rg[2 * i + 1] = direction.rgba[4 * i];
  }
  threads_ = make_texture(GL_TEXTURE_2D);
  const int levels = 1 + static_cast<int>(std::log2(kThreadTextureSize));
  glTextureStorage2D(threads_.get(), levels, GL_RG8, kThreadTextureSize, kThreadTextureSize);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(threads_.get(), 0, 0, 0, kThreadTextureSize, kThreadTextureSize, GL_RG,
                      GL_UNSIGNED_BYTE, rg.data());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glGenerateTextureMipmap(threads_.get());
  glTextureParameteri(threads_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(threads_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameterf(threads_.get(), GL_TEXTURE_MAX_ANISOTROPY, max_anisotropy());
  glObjectLabel(GL_TEXTURE, threads_.get(), -1, "thread mask and direction");
  thread_fraction_ = fraction;
}

// The weave's normal map at a relief strength (rebuilt only when it changes): linear bytes,
// mipmapped, the same tile as the fabric albedo. A map given by set_normal_map wins.
void ClothPass::bind_weave(double bump) {
  if (!custom_normals_ && !(bump == weave_bump_ && weave_normals_)) {
    upload_normal_map(make_weave_normal_map(kThreadTextureSize, static_cast<float>(bump)));
    weave_bump_ = bump;
  }
  glBindTextureUnit(3, weave_normals_.get());
}

void ClothPass::set_normal_map(const Image* map) {
  custom_normals_ = map != nullptr;
  weave_bump_ = -1.0;  // the procedural map is rebuilt when it is next needed
  weave_normals_ = Texture{};
  if (map) upload_normal_map(*map);
}

void ClothPass::upload_normal_map(const Image& map) {
  weave_normals_ = upload_texture(map, false);
  glObjectLabel(GL_TEXTURE, weave_normals_.get(), -1, "weave normal map");
}

}  // namespace clothlab::vis
