#include "vis/render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "sim/solver.hpp"
#include "sim/step_backend.hpp"
#include "vis/colormap/colormap_texture.hpp"
#include "vis/gl/program.hpp"
#include "vis/passes/diffusion_pass.hpp"
#include "vis/passes/shadow_pass.hpp"
#include "vis/passes/sky_pass.hpp"
#include "vis/render/collider_scenery.hpp"
#include "vis/render/scenery.hpp"
#include "vis/textures/cloth_tangents.hpp"
#include "vis/textures/fabric_texture.hpp"
#include "vis/textures/floor_texture.hpp"
#include "vis/textures/planar_uv.hpp"
#include "vis/textures/weave_maps.hpp"

namespace clothlab::vis {
namespace {

// Explicit uniform locations of shaders/floor.vert and shaders/cloth.frag (no lookups per frame).
constexpr GLint kFloorHalfSize = 0, kFloorTileSize = 1;
constexpr GLint kClothMode = 0, kClothTextureRepeat = 1, kClothColorBy = 2, kClothRange = 3,
                kClothShaded = 4, kClothLook = 5, kClothMetalF0 = 6, kClothGlints = 7,
                kClothFlatAlbedo = 9, kClothUseFlat = 10, kClothTranslucency = 11,
                kClothDiffusionWeights = 12, kClothSubsurface = 15, kClothGlintsOn = 16;
// Mode 6's diffusion weights per channel (sharp term, then the three blurs of DiffusionPass;
// each row sums to 1): red light travels farthest through the dyed yarn, blue least.
constexpr float kDiffusionWeights[3][4] = {
    {0.40f, 0.25f, 0.20f, 0.15f}, {0.60f, 0.25f, 0.11f, 0.04f}, {0.72f, 0.20f, 0.06f, 0.02f}};
constexpr int kThreadTextureSize = 256;  // as the fabric albedo, so the weaves line up

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
  glm::vec4 shadow_range;     // x near, y far, z orthographic
};
constexpr GLint kDepthViewViewport = 0;  // explicit uniform location in shaders/depth_view.frag

// Anisotropic filtering (8x) on a GPU. On Mesa's llvmpipe (the CPU rasteriser of CI and
// headless renders) trilinear only: its anisotropic sampler can spend minutes on one frame (the
// drop_sphere scene at 1280x720: 0.3 s frames, then one of 210 s with the time in the JIT-compiled
// fragment code, and 0.29 s with anisotropy off), and on a CPU it is the dearest sampling anyway.
float max_anisotropy() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, "llvmpipe") ? 1.0f : 8.0f;
}

Texture upload_texture(const Image& image) {
  Texture t = make_texture(GL_TEXTURE_2D);
  const int levels = 1 + static_cast<int>(std::log2(std::max(image.width, image.height)));
  glTextureStorage2D(t.get(), levels, GL_SRGB8_ALPHA8, image.width, image.height);
  glTextureSubImage2D(t.get(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      image.rgba.data());
  glGenerateTextureMipmap(t.get());
  glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTextureParameterf(t.get(), GL_TEXTURE_MAX_ANISOTROPY, max_anisotropy());
  return t;
}

void attribute(GLuint vao, GLuint index, GLuint binding, int components) {
  glEnableVertexArrayAttrib(vao, index);
  glVertexArrayAttribFormat(vao, index, components, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, index, binding);
}

}  // namespace

Renderer::Renderer()
    : cloth_program_(build_program({"cloth.vert", "cloth.frag"})),
      floor_program_(build_program({"floor.vert", "floor.frag"})),
      springs_program_(build_program({"springs.vert", "springs.geom", "springs.frag"})),
      depth_view_program_(build_program({"depth_view.vert", "depth_view.frag"})),
      scenery_(std::make_unique<Scenery>()),
      fabric_(upload_texture(make_fabric_texture())),
      tiles_(upload_texture(make_floor_texture())),
      frame_ubo_(make_buffer()),
      empty_vao_(make_vertex_array()) {
  glNamedBufferStorage(frame_ubo_.get(), sizeof(FrameBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glObjectLabel(GL_TEXTURE, fabric_.get(), -1, "fabric albedo");
  glObjectLabel(GL_TEXTURE, tiles_.get(), -1, "floor tiles");
  for (ColorMap map : kAllColorMaps) colormaps_[static_cast<int>(map)] = make_colormap_texture(map);
}

Renderer::~Renderer() = default;

void Renderer::enable_pass_timing(bool on) {
  if (on && !timer_) timer_ = std::make_unique<PassTimer>();
  if (!on) timer_.reset();
}

void Renderer::set_scene(const RenderSpec& spec, const Solver& solver,
                         const std::vector<ColliderSpec>& colliders) {
  scenery_->set_scene(spec, solver);
  if (colliders.empty()) {
    colliders_.reset();
    return;
  }
  if (!colliders_) colliders_ = std::make_unique<ColliderScenery>();
  colliders_->set_colliders(colliders, solver);
}

void Renderer::set_cloth(Solver& solver) {
  vertices_ = solver.vertex_count();
  const std::size_t n = vertices_;
  const auto cloths = solver.cloths();
  // A tube's seam copies: column 0 once more per row, appended after the solver's vertices so
  // these keep their indices (springs, scalars and probes need no mapping).
  seam_copies_.clear();
  std::vector<std::size_t> first_copy(cloths.size(), 0);  // render index of cloth k's row 0 copy
  for (std::size_t k = 0; k < cloths.size(); ++k) {
    const ClothRange& c = cloths[k];
    first_copy[k] = n + seam_copies_.size();
    if (c.wrap_u)
      for (int j = 0; j < c.nv; ++j) seam_copies_.push_back(c.offset + j * c.nu);
  }
  const std::size_t rn = render_vertex_count();
  // Static attributes per render vertex: UV per cloth (i / (nu - 1), j / (nv - 1) on a grid;
  // i / nu round a tube, its seam copies at u = 1), then rest positions, then the place in the UV
  // atlas of mode 6's diffusion (cloth k of K in rows k / K .. (k + 1) / K).
  std::vector<float> fixed(7 * rn);
  solver.copy_rest_positions(fixed.data() + 2 * rn);
  float longest_u = 1e-3f, longest_v = 1e-3f;
  for (std::size_t k = 0; k < cloths.size(); ++k) {
    const ClothRange& c = cloths[k];
    if (c.mesh) {
      const glm::vec2 span =
          planar_uvs(fixed.data() + 2 * rn, c.offset, c.offset + c.nu, fixed.data());
      longest_u = std::max(longest_u, span.x);
      longest_v = std::max(longest_v, span.y);
      continue;
    }
    const float u_steps = c.wrap_u ? float(c.nu) : float(c.nu - 1);
    for (int j = 0; j < c.nv; ++j) {
      const float v_coord = c.nv > 1 ? float(j) / float(c.nv - 1) : 0.0f;
      for (int i = 0; i < c.nu; ++i) {
        const std::size_t v = static_cast<std::size_t>(c.offset + i + j * c.nu);
        fixed[2 * v] = c.nu > 1 ? float(i) / u_steps : 0.0f;
        fixed[2 * v + 1] = v_coord;
      }
      if (c.wrap_u) {
        const std::size_t copy = first_copy[k] + static_cast<std::size_t>(j);
        fixed[2 * copy] = 1.0f;
        fixed[2 * copy + 1] = v_coord;
      }
    }
  }
  for (std::size_t k = 0; k < seam_copies_.size(); ++k)
    for (int d = 0; d < 3; ++d)
      fixed[2 * rn + 3 * (n + k) + d] =
          fixed[2 * rn + 3 * static_cast<std::size_t>(seam_copies_[k]) + d];
  const float rows = static_cast<float>(std::max<std::size_t>(1, cloths.size()));
  for (std::size_t k = 0; k < cloths.size(); ++k) {
    const ClothRange& c = cloths[k];
    auto rest = [&](int i, int j) {
      const std::size_t v = 2 * rn + 3 * static_cast<std::size_t>(c.offset + i + j * c.nu);
      return glm::vec3(fixed[v], fixed[v + 1], fixed[v + 2]);
    };
    if (c.mesh) {
      // planar_uvs above gave its spans
    } else if (c.wrap_u) {
      // Round the longer of the end rings (a frustum's differ), the seam's chord included.
      for (int j : {0, c.nv - 1}) {
        float ring = 0.0f;
        for (int i = 0; i < c.nu; ++i) ring += glm::length(rest((i + 1) % c.nu, j) - rest(i, j));
        longest_u = std::max(longest_u, ring);
      }
    } else {
      longest_u = std::max(longest_u, glm::length(rest(c.nu - 1, 0) - rest(0, 0)));
    }
    if (!c.mesh) longest_v = std::max(longest_v, glm::length(rest(0, c.nv - 1) - rest(0, 0)));
    auto to_atlas = [&](std::size_t at) {
      fixed[5 * rn + 2 * at] = fixed[2 * at];
      fixed[5 * rn + 2 * at + 1] = (fixed[2 * at + 1] + float(k)) / rows;
    };
    for (int v = c.offset; v < c.offset + c.nu * c.nv; ++v) to_atlas(static_cast<std::size_t>(v));
    if (c.wrap_u)
      for (int j = 0; j < c.nv; ++j) to_atlas(first_copy[k] + static_cast<std::size_t>(j));
  }
  atlas_per_metre_ = glm::vec2(1.0f / longest_u, 1.0f / (longest_v * rows));

  // The solver's triangles; on a tube those of the seam's quads (with a vertex in column nu - 1
  // and one in column 0) take column 0's seam copies, at u = 1.
  std::vector<std::uint32_t> triangles;
  const auto& solver_triangles = solver.triangles();
  triangles.reserve(3 * solver_triangles.size());
  std::vector<std::uint32_t> seam_copy;  // per solver vertex: its copy, or itself
  if (!seam_copies_.empty()) {
    seam_copy.resize(n);
    for (std::size_t v = 0; v < n; ++v) seam_copy[v] = static_cast<std::uint32_t>(v);
    for (std::size_t k = 0; k < seam_copies_.size(); ++k)
      seam_copy[static_cast<std::size_t>(seam_copies_[k])] = static_cast<std::uint32_t>(n + k);
  }
  auto column = [&](int v, const ClothRange*& cloth) {
    for (const ClothRange& c : cloths)
      if (v >= c.offset && v < c.offset + c.nu * c.nv) {
        cloth = &c;
        return (v - c.offset) % c.nu;
      }
    cloth = nullptr;
    return -1;
  };
  for (const auto& t : solver_triangles) {
    bool seam = false;
    if (!seam_copies_.empty()) {
      const ClothRange* c = nullptr;
      bool first = false, last = false;
      for (int v : t) {
        const int i = column(v, c);
        if (c && c->wrap_u) first |= i == 0, last |= i == c->nu - 1;
      }
      seam = first && last;
    }
    for (int v : t)
      triangles.push_back(seam ? seam_copy[static_cast<std::size_t>(v)]
                               : static_cast<std::uint32_t>(v));
  }
  std::vector<std::uint32_t> lines;
  for (const auto& s : solver.spring_pairs())
    for (int v : s) lines.push_back(static_cast<std::uint32_t>(v));
  triangle_indices_ = static_cast<GLsizei>(triangles.size());
  line_indices_ = static_cast<GLsizei>(lines.size());

  dynamic_vbo_ = make_buffer();
  seam_source_ = Buffer();
  static_vbo_ = make_buffer();
  scalar_vbo_ = make_buffer();
  tangent_vbo_ = make_buffer();
  grids_ = solver.cloths();
  mesh_uvs_.clear();
  mesh_triangles_.clear();
  if (std::any_of(cloths.begin(), cloths.end(), [](const ClothRange& c) { return c.mesh; })) {
    mesh_uvs_.assign(fixed.begin(), fixed.begin() + std::ptrdiff_t(2 * n));
    mesh_triangles_ = solver_triangles;
  }
  tangents_.assign(4 * rn, 0.0f);
  tangents_stale_ = true;
  triangle_ebo_ = make_buffer();
  line_ebo_ = make_buffer();
  auto bytes = [](const auto& v) {
    return static_cast<GLsizeiptr>(std::max<std::size_t>(1, v.size() * sizeof(v[0])));
  };
  glNamedBufferStorage(dynamic_vbo_.get(), static_cast<GLsizeiptr>(6 * rn * sizeof(float)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(static_vbo_.get(), bytes(fixed), fixed.data(), 0);
  glNamedBufferStorage(scalar_vbo_.get(),
                       static_cast<GLsizeiptr>(std::max<std::size_t>(1, rn) * sizeof(float)),
                       nullptr, GL_DYNAMIC_STORAGE_BIT);
  glNamedBufferStorage(triangle_ebo_.get(), bytes(triangles), triangles.data(), 0);
  glNamedBufferStorage(line_ebo_.get(), bytes(lines), lines.data(), 0);

  // Two vertex arrays over the same vertex buffers: triangles and spring lines.
  cloth_vao_ = make_vertex_array();
  line_vao_ = make_vertex_array();
  for (GLuint vao : {cloth_vao_.get(), line_vao_.get()}) {
    const auto n_bytes = static_cast<GLintptr>(3 * rn * sizeof(float));
    glVertexArrayVertexBuffer(vao, 0, dynamic_vbo_.get(), 0, 3 * sizeof(float));        // position
    glVertexArrayVertexBuffer(vao, 1, dynamic_vbo_.get(), n_bytes, 3 * sizeof(float));  // normal
    glVertexArrayVertexBuffer(vao, 2, static_vbo_.get(), 0, 2 * sizeof(float));         // uv
    glVertexArrayVertexBuffer(vao, 3, static_vbo_.get(),
                              static_cast<GLintptr>(2 * rn * sizeof(float)),
                              3 * sizeof(float));  // rest position
    for (GLuint a = 0; a < 4; ++a) attribute(vao, a, a, a == 2 ? 2 : 3);
  }
  glVertexArrayVertexBuffer(cloth_vao_.get(), 4, scalar_vbo_.get(), 0, sizeof(float));
  attribute(cloth_vao_.get(), 4, 4, 1);
  glNamedBufferStorage(tangent_vbo_.get(),
                       static_cast<GLsizeiptr>(std::max<std::size_t>(1, 4 * rn) * sizeof(float)),
                       nullptr, GL_DYNAMIC_STORAGE_BIT);
  glVertexArrayVertexBuffer(cloth_vao_.get(), 5, tangent_vbo_.get(), 0, 4 * sizeof(float));
  attribute(cloth_vao_.get(), 5, 5, 4);
  glVertexArrayVertexBuffer(cloth_vao_.get(), 6, static_vbo_.get(),
                            static_cast<GLintptr>(5 * rn * sizeof(float)), 2 * sizeof(float));
  attribute(cloth_vao_.get(), 6, 6, 2);
  glVertexArrayElementBuffer(cloth_vao_.get(), triangle_ebo_.get());
  glVertexArrayElementBuffer(line_vao_.get(), line_ebo_.get());
  staging_.resize(6 * rn);
  scalar_staging_.resize(rn);
}

void Renderer::update_cloth(Solver& solver) {
  DeviceCloth* gpu = solver.device_cloth();  // the GPU backend's buffers, or null
  gpu_source_ = gpu;
  solver.copy_positions(staging_.data());
  // The cloth's current bounds: the light's frustum follows the cloth, so the shadow map spends
  // its texels on it wherever it has moved.
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (std::size_t v = 0; v < vertices_; ++v) {
    const glm::vec3 p(staging_[3 * v], staging_[3 * v + 1], staging_[3 * v + 2]);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (vertices_ == 0 || !std::isfinite(lo.x + hi.x + lo.y + hi.y + lo.z + hi.z))
    lo = hi = glm::vec3(0.0f);
  cloth_lo_ = lo;
  cloth_hi_ = hi;
  tangents_stale_ = true;
  if (colliders_) colliders_->update(solver.time());  // where the moving ones are now
  if (gpu) {
    gpu->update_normals();
    pack_from_gpu(*gpu);
    return;
  }
  const std::size_t rn = render_vertex_count();
  solver.copy_normals(staging_.data() + 3 * rn);
  // The seam copies take their solver vertex's position and normal.
  for (std::size_t k = 0; k < seam_copies_.size(); ++k) {
    const std::size_t from = 3 * static_cast<std::size_t>(seam_copies_[k]),
                      to = 3 * (vertices_ + k);
    for (int d = 0; d < 3; ++d) {
      staging_[to + d] = staging_[from + d];
      staging_[3 * rn + to + d] = staging_[3 * rn + from + d];
    }
  }
  glNamedBufferSubData(dynamic_vbo_.get(), 0,
                       static_cast<GLsizeiptr>(staging_.size() * sizeof(float)), staging_.data());
}

void Renderer::pack_from_gpu(const DeviceCloth& gpu) {
  const std::size_t rn = render_vertex_count();
  if (!pack_program_) pack_program_ = build_program({"cloth_pack.comp"});
  if (!seam_source_) {  // after each set_cloth
    std::vector<std::int32_t> seams(seam_copies_.begin(), seam_copies_.end());
    seam_source_ = make_buffer();
    glNamedBufferStorage(seam_source_.get(),
                         static_cast<GLsizeiptr>(std::max<std::size_t>(1, seams.size()) * 4),
                         seams.empty() ? nullptr : seams.data(), 0);
  }
  const GLuint p = pack_program_.get();
  glProgramUniform1ui(p, glGetUniformLocation(p, "n"), static_cast<GLuint>(vertices_));
  glProgramUniform1ui(p, glGetUniformLocation(p, "render_n"), static_cast<GLuint>(rn));
  glUseProgram(p);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, gpu.position_buffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, gpu.normal_buffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, seam_source_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, dynamic_vbo_.get());
  glDispatchCompute(static_cast<GLuint>((rn + 63) / 64), 1, 1);
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(0);
}

// The tangent frame of every grid cloth from the positions and normals of the last
// update_cloth(), only when a mode that needs it is drawn.
void Renderer::update_tangents() {
  if (!tangents_stale_ || vertices_ == 0) return;
  if (gpu_source_) {  // the normals stayed on the GPU: the tangents need them here
    const std::size_t rn = render_vertex_count();
    gpu_source_->read_normals(staging_.data() + 3 * rn);
  }
  const float* positions = staging_.data();
  const float* normals = staging_.data() + 3 * render_vertex_count();
  for (const ClothRange& c : grids_) {
    const std::size_t o = static_cast<std::size_t>(c.offset);
    if (c.mesh) {
      compute_mesh_tangents(c.offset, c.offset + c.nu, mesh_triangles_, positions, normals,
                            mesh_uvs_.data(), tangents_.data(), tangent_scratch_);
      continue;
    }
    compute_grid_tangents(c.nu, c.nv, positions + 3 * o, normals + 3 * o, tangents_.data() + 4 * o,
                          c.wrap_u);
  }
  // A seam copy has column 0's frame: the ring's dP/du is continuous there, so is the frame.
  for (std::size_t k = 0; k < seam_copies_.size(); ++k)
    for (int d = 0; d < 4; ++d)
      tangents_[4 * (vertices_ + k) + d] =
          tangents_[4 * static_cast<std::size_t>(seam_copies_[k]) + d];
  glNamedBufferSubData(tangent_vbo_.get(), 0,
                       static_cast<GLsizeiptr>(tangents_.size() * sizeof(float)), tangents_.data());
  tangents_stale_ = false;
}

// The thread texture for a metal fraction: r the mask of metal threads, g where the weft is on
// top (vis/textures/weave_maps.hpp), both linear, mipmapped like the fabric.
void Renderer::set_thread_fraction(double fraction) {
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
void Renderer::set_weave_bump(double strength) {
  if (custom_normals_ || (strength == weave_bump_ && weave_normals_)) return;
  upload_normal_map(make_weave_normal_map(kThreadTextureSize, static_cast<float>(strength)));
  weave_bump_ = strength;
}

void Renderer::set_normal_map(const Image* map) {
  custom_normals_ = map != nullptr;
  weave_bump_ = -1.0;  // the procedural map is rebuilt when it is next needed
  weave_normals_ = Texture{};
  if (map) upload_normal_map(*map);
}

void Renderer::upload_normal_map(const Image& map) {
  weave_normals_ = make_texture(GL_TEXTURE_2D);
  const int levels = 1 + static_cast<int>(std::log2(std::max(map.width, map.height)));
  glTextureStorage2D(weave_normals_.get(), levels, GL_RGBA8, map.width, map.height);
  glTextureSubImage2D(weave_normals_.get(), 0, 0, 0, map.width, map.height, GL_RGBA,
                      GL_UNSIGNED_BYTE, map.rgba.data());
  glGenerateTextureMipmap(weave_normals_.get());
  glTextureParameteri(weave_normals_.get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(weave_normals_.get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameterf(weave_normals_.get(), GL_TEXTURE_MAX_ANISOTROPY, max_anisotropy());
  glObjectLabel(GL_TEXTURE, weave_normals_.get(), -1, "weave normal map");
}

void Renderer::set_scalars(const std::vector<float>& values, ScalarRange range) {
  if (values.size() != vertices_)
    throw std::invalid_argument("Renderer::set_scalars: one value per vertex expected");
  // Through the staging copy (sized by set_cloth: no allocation per frame), seam copies filled.
  std::copy(values.begin(), values.end(), scalar_staging_.begin());
  for (std::size_t k = 0; k < seam_copies_.size(); ++k)
    scalar_staging_[vertices_ + k] = values[static_cast<std::size_t>(seam_copies_[k])];
  glNamedBufferSubData(scalar_vbo_.get(), 0,
                       static_cast<GLsizeiptr>(scalar_staging_.size() * sizeof(float)),
                       scalar_staging_.data());
  scalar_range_ = range;
}

void Renderer::draw(const ViewSettings& view, int width, int height) {
  GLint target = 0;  // the caller's framebuffer: the shadow pass binds its own first
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  const bool depth_view = view.mode == DisplayMode::light_depth;
  const bool shadows = view.shadows != ShadowFilter::none || depth_view;
  // The casters the light must see: the cloth, the scenery and the colliders (planes aside).
  glm::vec3 lo = cloth_lo_, hi = cloth_hi_;
  if (!scenery_->empty()) {
    lo = glm::min(lo, scenery_->lo());
    hi = glm::max(hi, scenery_->hi());
  }
  if (colliders_ && colliders_->has_bounds()) {
    lo = glm::min(lo, colliders_->lo());
    hi = glm::max(hi, colliders_->hi());
  }
  light_ = fit_light(view, lo, hi, view.floor_height, view.shadow_map_size);

  const glm::vec3 centre = 0.5f * (lo + hi);  // the sun of the sky lies from here to the light

  FrameBlock frame;
  frame.view_proj = view_projection(view.camera, width, height);
  frame.light_view_proj = light_.view_proj;
  frame.eye = glm::vec4(view.camera.eye(), 1.0f);
  frame.light_position = glm::vec4(light_.position, light_.directional ? 1.0f : 0.0f);
  frame.light_direction = glm::vec4(light_.direction, light_.cone_cos);
  frame.light_color = glm::vec4(view.light_color * view.light_intensity, view.ambient);
  frame.params = glm::vec4(view.strain_range, view.floor_height, 0.0f, 0.0f);
  const float filter = view.shadows == ShadowFilter::pcss  ? 2.0f
                       : view.shadows == ShadowFilter::pcf ? 1.0f
                                                           : 0.0f;
  frame.shadow =
      glm::vec4(filter, 1.0f / float(view.shadow_map_size), light_.size_uv, light_.normal_offset);
  // Mode 5 with shadows: the cloth's shadow is coloured by its transmittance.
  const bool translucent =
      view.mode == DisplayMode::translucent && view.shadows != ShadowFilter::none;
  frame.shadow_range = glm::vec4(light_.near, light_.far, light_.directional ? 1.0f : 0.0f,
                                 translucent ? 1.0f : 0.0f);
  glNamedBufferSubData(frame_ubo_.get(), 0, sizeof frame, &frame);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, frame_ubo_.get());

  if (shadows) {
    if (timer_) timer_->begin(Pass::shadow);
    draw_shadow_map(view, translucent);
    shadow_->bind_textures();
  } else {
    shadow_.reset();  // nothing needs the map: its memory goes too
  }
  // Mode 6's light through the yarn: its own passes before the main one.
  const bool subsurface =
      view.mode == DisplayMode::weave && view.look.subsurface > 0.0 && triangle_indices_ > 0;
  if (subsurface) {
    if (timer_) timer_->begin(Pass::diffusion);
    if (!diffusion_) diffusion_ = std::make_unique<DiffusionPass>();
    update_tangents();
    set_weave_bump(view.look.bump);
    glBindTextureUnit(3, weave_normals_.get());
    diffusion_->run(cloth_vao_.get(), triangle_indices_, atlas_per_metre_, view.fabric_repeat);
  } else {
    diffusion_.reset();
  }
  if (timer_) timer_->begin(Pass::scene);
  // The main pass draws into what the caller bound (the shadow pass bound its own).
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
  glViewport(0, 0, width, height);

  glEnable(GL_FRAMEBUFFER_SRGB);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_MULTISAMPLE);
  glDisable(GL_CULL_FACE);  // cloth is two-sided
  const glm::vec3 bg = view.background;
  const float clear[4] = {bg.r, bg.g, bg.b, 1.0f};
  glClearBufferfv(GL_COLOR, 0, clear);
  glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);

  if (depth_view) {
    glUseProgram(depth_view_program_.get());
    glProgramUniform2f(depth_view_program_.get(), kDepthViewViewport, float(width), float(height));
    glBindTextureUnit(1, colormap_texture(ColorMap::turbo));
    glBindVertexArray(empty_vao_.get());
    glDisable(GL_DEPTH_TEST);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(0);
    return;
  }

  // Floor.
  glUseProgram(floor_program_.get());
  glProgramUniform1f(floor_program_.get(), kFloorHalfSize, view.floor_half_size);
  glProgramUniform1f(floor_program_.get(), kFloorTileSize, view.floor_tile_size);
  glBindTextureUnit(0, tiles_.get());
  glBindVertexArray(empty_vao_.get());
  glDrawArrays(GL_TRIANGLES, 0, 6);

  scenery_->draw();
  if (colliders_) colliders_->draw();
  const bool blended_cloth = view.mode == DisplayMode::translucent;
  if (blended_cloth) draw_sky(view, frame.view_proj, centre);  // behind the translucent cloth

  if (view.mode == DisplayMode::springs) {
    glUseProgram(springs_program_.get());
    glBindVertexArray(line_vao_.get());
    glDrawElements(GL_LINES, line_indices_, GL_UNSIGNED_INT, nullptr);
  } else {
    glUseProgram(cloth_program_.get());
    glProgramUniform1i(cloth_program_.get(), kClothMode, static_cast<int>(view.mode));
    glProgramUniform1f(cloth_program_.get(), kClothTextureRepeat, view.fabric_repeat);
    const bool color_by = view.color.field != ScalarField::none;
    glProgramUniform1i(cloth_program_.get(), kClothColorBy, color_by ? 1 : 0);
    glProgramUniform2f(cloth_program_.get(), kClothRange, static_cast<float>(scalar_range_.min),
                       static_cast<float>(scalar_range_.max));
    glProgramUniform1i(cloth_program_.get(), kClothShaded, view.color.shaded ? 1 : 0);
    glBindTextureUnit(0, fabric_.get());
    glBindTextureUnit(1, colormap_texture(view.color.map));
    // Units only modes 4 and 6 read are emptied otherwise: llvmpipe specialises the shader for
    // every bound texture, and a stale one made mode 3 measurably slower after mode 6.
    for (GLuint unit : {2u, 3u, 10u, 11u, 12u}) glBindTextureUnit(unit, 0);
    const glm::vec3 flat = view.look.color ? glm::vec3((*view.look.color)[0], (*view.look.color)[1],
                                                       (*view.look.color)[2])
                                           : glm::vec3(1.0f);
    glProgramUniform3f(cloth_program_.get(), kClothFlatAlbedo, flat.r, flat.g, flat.b);
    glProgramUniform1i(cloth_program_.get(), kClothUseFlat, view.look.color ? 1 : 0);
    glProgramUniform2f(cloth_program_.get(), kClothTranslucency, float(view.look.opacity),
                       float(view.look.transmission));
    if (blended_cloth) {
      // Over what is behind it; its own layers in drawing order (no sorting: one sheet).
      glEnable(GL_BLEND);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      glDepthMask(GL_FALSE);
    }
    if (view.mode == DisplayMode::weave) {
      update_tangents();
      set_weave_bump(view.look.bump);
      glBindTextureUnit(3, weave_normals_.get());
      const float s = subsurface ? static_cast<float>(view.look.subsurface) : 0.0f;
      float w[3][4];
      for (int c = 0; c < 3; ++c) {
        w[c][0] = 1.0f - s * (1.0f - kDiffusionWeights[c][0]);
        for (int k = 1; k < 4; ++k) w[c][k] = s * kDiffusionWeights[c][k];
      }
      glProgramUniform4fv(cloth_program_.get(), kClothDiffusionWeights, 3, &w[0][0]);
      glProgramUniform1i(cloth_program_.get(), kClothSubsurface, subsurface ? 1 : 0);
      if (subsurface) diffusion_->bind_results();
    }
    if (view.mode == DisplayMode::cloth_brdf) {
      update_tangents();
      set_thread_fraction(view.look.thread_fraction);
      glBindTextureUnit(2, threads_.get());
      const ClothLookSpec& look = view.look;
      glProgramUniform3f(cloth_program_.get(), kClothLook, float(look.roughness), float(look.sheen),
                         float(look.sheen_roughness));
      const glm::vec3 f0 = look.threads == ThreadMetal::gold     ? glm::vec3(1.00f, 0.71f, 0.29f)
                           : look.threads == ThreadMetal::silver ? glm::vec3(0.95f, 0.93f, 0.88f)
                                                                 : glm::vec3(0.0f);
      glProgramUniform3f(cloth_program_.get(), kClothMetalF0, f0.x, f0.y, f0.z);
      // Two glint lights beside the camera (specular only), so the threads sparkle from where
      // one looks.
      const glm::mat4 v = view.camera.view();
      const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
      const glm::vec3 eye = view.camera.eye(), d = glm::vec3(0.3f * view.camera.distance);
      const glm::vec3 glints[2] = {eye + d * (0.6f * right + 0.4f * up),
                                   eye + d * (-0.7f * right + 0.2f * up)};
      glProgramUniform3fv(cloth_program_.get(), kClothGlints, 2, &glints[0][0]);
      glProgramUniform1i(cloth_program_.get(), kClothGlintsOn, look.glints ? 1 : 0);
    }
    glBindVertexArray(cloth_vao_.get());
    glDrawElements(GL_TRIANGLES, triangle_indices_, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
  glBindVertexArray(0);
  if (!blended_cloth) draw_sky(view, frame.view_proj, centre);
}

// The sky after the opaque passes: it fills only what nothing else covered.
void Renderer::draw_sky(const ViewSettings& view, const glm::mat4& view_proj, glm::vec3 centre) {
  if (!view.sky) {
    sky_.reset();
    return;
  }
  if (timer_) timer_->begin(Pass::sky);
  if (!sky_) sky_ = std::make_unique<SkyPass>();
  const glm::vec3 sun = light_.directional ? -light_.direction : light_.position - centre;
  sky_->draw(sun, view.sky_turbidity, view_proj, view.camera.eye());
  if (timer_) timer_->begin(Pass::scene);  // what follows the sky belongs to the scene again
}

// Every caster into the light's depth map: the floor, the cloth (its current positions), the
// scenery and the colliders.
void Renderer::draw_shadow_map(const ViewSettings& view, bool translucent) {
  if (!shadow_) shadow_ = std::make_unique<ShadowPass>();
  shadow_->begin(view.shadow_map_size);
  shadow_->draw_floor(view.floor_height, view.floor_half_size);
  if (triangle_indices_ > 0)
    shadow_->draw_triangles(cloth_vao_.get(), triangle_indices_, glm::mat4(1.0f));
  scenery_->draw_shadow(*shadow_);
  if (colliders_) colliders_->draw_shadow(*shadow_);
  if (translucent) {
    shadow_->begin_opaque();
    shadow_->draw_floor(view.floor_height, view.floor_half_size);
    scenery_->draw_shadow(*shadow_);
    if (colliders_) colliders_->draw_shadow(*shadow_);
    if (triangle_indices_ > 0) {
      shadow_->begin_transmittance();
      const glm::vec3 flat =
          view.look.color
              ? glm::vec3((*view.look.color)[0], (*view.look.color)[1], (*view.look.color)[2])
              : glm::vec3(1.0f);
      shadow_->draw_transmittance(cloth_vao_.get(), triangle_indices_, fabric_.get(),
                                  view.fabric_repeat, flat, view.look.color.has_value(),
                                  float(view.look.opacity), float(view.look.transmission));
    }
  }
  shadow_->end();
}

}  // namespace clothlab::vis
