// OBJ text through the mesh loader, as a mesh collider's file and as a mesh cloth's.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "load/scene_load.hpp"
#include "sim/mesh/triangle_mesh.hpp"
#include "sim/model/memory_estimate.hpp"
#include "sim/scene/scene_error.hpp"
#include "sim/solver.hpp"
#include "tests/fuzz/fuzz_targets.hpp"

namespace clothlab::fuzz {
namespace {

constexpr std::size_t kMaxMeshVertices = 4096;

void check_mesh(const TriangleMesh& mesh) {
  for (const auto& p : mesh.positions)
    if (!p.allFinite()) finding("a mesh that was read has a non-finite vertex");
  const int n = static_cast<int>(mesh.positions.size());
  for (const auto& t : mesh.triangles)
    for (int k : t)
      if (k < 0 || k >= n) finding("a triangle names a vertex outside the mesh");
}

// The mesh as a cloth draped for a few steps (when it is valid as one and small).
void step_as_cloth(const std::string& obj) {
  Scene scene;
  try {
    scene = read_scene_string("[cloth]\nshape = \"mesh\"\nfile = \"" + obj + "\"\n",
                              context().scratch_dir + "/fuzz.toml");
  } catch (const SceneError&) {
    return;
  }
  if (scene.cloths.front().resolution[0] > int(kMaxMeshVertices) ||
      estimated_solver_bytes(scene) > (64u << 20))
    return;
  std::unique_ptr<Solver> solver;
  try {
    solver = make_solver(scene);
  } catch (const SceneError&) {
    return;
  }
  const AdvanceResult r = solver->step(4);
  if (r.divergence) return;
  for (std::size_t v = 0; v < solver->vertex_count(); ++v)
    for (double x : solver->position(int(v)))
      if (!std::isfinite(x)) finding("a mesh cloth stepped to a non-finite position");
}

}  // namespace

int fuzz_obj(const std::uint8_t* data, std::size_t size) {
  const std::string path = context().scratch_dir + "/fuzz.obj";
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), long(size));
  TriangleMesh mesh;
  try {
    mesh = load_obj(path);
  } catch (const ObjError&) {
    return 0;
  }
  check_mesh(mesh);
  step_as_cloth("fuzz.obj");
  return 0;
}

}  // namespace clothlab::fuzz
