// Names of enum values as they appear in scene files and messages.
#include <array>
#include <utility>

#include "sim/scene/scene.hpp"

namespace clothlab {

namespace {

constexpr std::array<std::pair<IntegratorKind, const char*>, 10> kIntegratorNames{{
    {IntegratorKind::explicit_euler, "explicit_euler"},
    {IntegratorKind::symplectic_euler, "symplectic_euler"},
    {IntegratorKind::seed_hack, "seed_hack"},
    {IntegratorKind::verlet, "verlet"},
    {IntegratorKind::rk4, "rk4"},
    {IntegratorKind::implicit_euler, "implicit_euler"},
    {IntegratorKind::xpbd, "xpbd"},
    {IntegratorKind::local_global, "local_global"},
    {IntegratorKind::vbd, "vbd"},
    {IntegratorKind::bdf2, "bdf2"},
}};

template <class E, std::size_t N>
const char* name_of(const std::array<std::pair<E, const char*>, N>& names, E value) {
  for (const auto& [k, name] : names)
    if (k == value) return name;
  return "unknown";
}

}  // namespace

const std::array<std::pair<ColliderKind, const char*>, 5> kColliderKindNames{
    {{ColliderKind::plane, "plane"},
     {ColliderKind::sphere, "sphere"},
     {ColliderKind::box, "box"},
     {ColliderKind::capsule, "capsule"},
     {ColliderKind::mesh, "mesh"}}};
const std::array<std::pair<ShadowFilter, const char*>, 3> kShadowFilterNames{
    {{ShadowFilter::none, "none"}, {ShadowFilter::pcf, "pcf"}, {ShadowFilter::pcss, "pcss"}}};
const std::array<std::pair<LightType, const char*>, 2> kLightTypeNames{
    {{LightType::spot, "spot"}, {LightType::directional, "directional"}}};
const std::array<std::pair<MeshKind, const char*>, 4> kMeshKindNames{
    {{MeshKind::sphere, "sphere"},
     {MeshKind::box, "box"},
     {MeshKind::torus_knot, "torus_knot"},
     {MeshKind::obj, "obj"}}};
const std::array<std::pair<ThreadMetal, const char*>, 3> kThreadMetalNames{
    {{ThreadMetal::none, "none"}, {ThreadMetal::gold, "gold"}, {ThreadMetal::silver, "silver"}}};

const std::array<std::pair<Backend, const char*>, 3> kBackendNames{
    {{Backend::cpu, "cpu"},
     {Backend::gpu, "gpu"},
     {Backend::transform_feedback, "transform_feedback"}}};

const char* to_string(Backend backend) {
  return name_of(kBackendNames, backend);
}
const char* to_string(ColliderKind kind) {
  return name_of(kColliderKindNames, kind);
}
const std::array<std::pair<RenderQuality, const char*>, 3> kRenderQualityNames{
    {{RenderQuality::automatic, "auto"},
     {RenderQuality::full, "full"},
     {RenderQuality::fast, "fast"}}};

const char* to_string(RenderQuality quality) {
  return name_of(kRenderQualityNames, quality);
}
const char* to_string(ShadowFilter filter) {
  return name_of(kShadowFilterNames, filter);
}
const char* to_string(MeshKind kind) {
  return name_of(kMeshKindNames, kind);
}
const char* to_string(ThreadMetal metal) {
  return name_of(kThreadMetalNames, metal);
}

const char* to_string(IntegratorKind kind) {
  for (const auto& [k, name] : kIntegratorNames)
    if (k == kind) return name;
  return "unknown";
}

std::optional<IntegratorKind> integrator_from_string(const std::string& name) {
  for (const auto& [k, text] : kIntegratorNames)
    if (name == text) return k;
  return std::nullopt;
}

}  // namespace clothlab
