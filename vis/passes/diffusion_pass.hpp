// Mode 6's subsurface imitation by texture-space diffusion (d'Eon & Luebke, "Advanced Techniques
// for Realistic Real-Time Skin Rendering", GPU Gems 3 ch. 14; docs/rendering.md section 4): the
// irradiance of the cloth's lit side drawn into the cloths' UV atlas, then blurred by three
// Gaussians of growing width (each blur applied to the previous one, so variances add), each a
// horizontal and a vertical 7-tap pass. The cloth pass samples the three blurs back and weighs
// them per channel. Only built and run while mode 6 shows with subsurface on.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <string>

#include "gl/objects.hpp"
#include "gl/program_variants.hpp"

namespace clothlab::vis {

class DiffusionPass {
 public:
  explicit DiffusionPass(int size = 512);

  // The Gaussians' standard deviations, m of cloth (yarn scale).
  static constexpr std::array<float, 3> kSigma{0.002f, 0.005f, 0.012f};

  // Draws the irradiance of the cloth (`vao` with positions 0, normals 1, uv 2, tangents 5 and
  // atlas coordinates 6) into the atlas and blurs it. atlas_per_metre: atlas uv per metre of
  // cloth along u and v. Needs the Frame block, the shadow maps and the weave normal map (unit 3)
  // bound; leaves its own framebuffer bound. The blurs are as wide in metres of the cloth as it
  // is now, stretched or not (a stretch map from the irradiance pass); atlas_per_metre serves
  // only outside the cloth, where the blurs dilate its border.
  // `shading`: the irradiance shader's variant (ShadingVariant::defines).
  void run(GLuint vao, GLsizei index_count, glm::vec2 atlas_per_metre, float repeat,
           const std::string& shading);
  // Binds the three blurs to units 10, 11 and 12 (shaders/cloth.frag).
  void bind_results() const;
  int size() const { return size_; }

 private:
  // Blurs by a Gaussian of standard deviation `sigma` metres of cloth.
  void blur(const Texture& source, const Texture& target, float sigma);

  int size_;
  ProgramVariants irradiance_programs_;
  Program blur_program_;
  Framebuffer fbo_;
  Texture irradiance_, stretch_, temp_;
  std::array<Texture, 3> blurred_;
  VertexArray empty_vao_;
};

}  // namespace clothlab::vis
