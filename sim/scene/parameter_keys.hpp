// The key name of a Scene struct's member, from the parameter table: key_of<&ClothSpec::pins>()
// is the key pins. Code outside the table names keys through this, never by spelling them.
#pragma once

#include <string_view>
#include <type_traits>

#include "sim/scene/parameters.hpp"
#include "sim/scene/scene.hpp"

namespace clothlab::binding {

template <class S>
constexpr Section section_of() {
  if constexpr (std::is_same_v<S, Scene>) return Section::top;
  if constexpr (std::is_same_v<S, ClothSpec>) return Section::cloth;
  if constexpr (std::is_same_v<S, SpringSpec>) return Section::springs;
  if constexpr (std::is_same_v<S, ForceSpec>) return Section::forces;
  if constexpr (std::is_same_v<S, WindSpec>) return Section::wind;
  if constexpr (std::is_same_v<S, SolverSpec>) return Section::solver;
  if constexpr (std::is_same_v<S, TraceSpec>) return Section::trace;
  if constexpr (std::is_same_v<S, RenderSpec>) return Section::render;
  if constexpr (std::is_same_v<S, LightSpec>) return Section::light;
  if constexpr (std::is_same_v<S, SkySpec>) return Section::sky;
  if constexpr (std::is_same_v<S, PoleSpec>) return Section::pole;
  if constexpr (std::is_same_v<S, MeshSpec>) return Section::mesh;
  if constexpr (std::is_same_v<S, ClothLookSpec>) return Section::look;
  if constexpr (std::is_same_v<S, CameraSpec>) return Section::camera;
  if constexpr (std::is_same_v<S, ColliderSpec>) return Section::collider;
  if constexpr (std::is_same_v<S, ColliderMotion>) return Section::motion;
  if constexpr (std::is_same_v<S, ColliderKey>) return Section::keyframe;
  if constexpr (std::is_same_v<S, MusicSpec>) return Section::music;
  if constexpr (std::is_same_v<S, MannequinSpec>) return Section::mannequin;
}

template <class M>
struct Member;
template <class S, class T>
struct Member<T S::*> {
  using Struct = S;
  using Type = T;
};
template <auto M>
using StructOf = typename Member<decltype(M)>::Struct;
template <auto M>
using TypeOf = typename Member<decltype(M)>::Type;

template <auto M>
StructOf<M>& object_of(void* object) {
  return *static_cast<StructOf<M>*>(object);
}

template <auto M>
void* address_of(void* object) {
  return &(object_of<M>(object).*M);
}

// The key name of member M, found by the member's address in a default-made struct.
template <auto M>
std::string_view key_of() {
  StructOf<M> probe{};
  void* const target = &(probe.*M);
  for (const Parameter& p : parameters())
    if (p.section == section_of<StructOf<M>>() && p.address && p.address(&probe) == target)
      return p.name;
  return "?";
}

}  // namespace clothlab::binding

namespace clothlab {
using binding::key_of;
}  // namespace clothlab
