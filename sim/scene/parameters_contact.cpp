// The parameter table, part three: [[colliders]], their friction and motion, [music] and
// [mannequin]. See parameters.cpp.
#include <vector>

#include "sim/scene/parameter_binding.hpp"
#include "sim/scene/special_values.hpp"

// Records are designated initializers that leave the fields they do not name at their
// defaults; GCC 12's -Wextra warns about every such field.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace clothlab {
namespace {

using namespace binding;
using S = Section;

std::vector<Parameter> collider_shape() {
  return {
      choice_row<&ColliderSpec::kind, kColliderKindNames, "collider type">(
          {.name = "type",
           .description = "plane, sphere, box, capsule or mesh",
           .required = "a collider needs type = \"plane\", \"sphere\", \"box\" or \"capsule\""}),
      row<&ColliderSpec::point>(
          {.name = "point", .unit = "m", .fallback = "[0, 0, 0]", .description = "plane: on it"}),
      row<&ColliderSpec::normal>({.name = "normal",
                                  .fallback = "[0, 1, 0]",
                                  .description = "plane: the side the cloth stays on (non-zero)"}),
      row<&ColliderSpec::center>({.name = "center",
                                  .unit = "m",
                                  .fallback = "[0, 0.5, 0]",
                                  .description = "sphere, box, mesh"}),
      row<&ColliderSpec::radius>({.name = "radius",
                                  .range = kPositive,
                                  .unit = "m",
                                  .fallback = "0.4",
                                  .description = "sphere, capsule"}),
      row<&ColliderSpec::half_extents>({.name = "half_extents",
                                        .range = kPositive,
                                        .unit = "m",
                                        .fallback = "[0.3, 0.3, 0.3]",
                                        .description = "box"}),
      row<&ColliderSpec::rotation>({.name = "rotation",
                                    .unit = "deg",
                                    .fallback = "[0, 0, 0]",
                                    .description = "box, mesh: about x, then y, then z"}),
      row<&ColliderSpec::rounding>(
          {.name = "rounding",
           .range = kNonNegative,
           .unit = "m",
           .fallback = "0",
           .description = "box: edge radius, below the smallest half extent"}),
      row<&ColliderSpec::a>(
          {.name = "a", .unit = "m", .fallback = "[-0.5, 0.5, 0]", .description = "capsule: end"}),
      row<&ColliderSpec::b>({.name = "b",
                             .unit = "m",
                             .fallback = "[0.5, 0.5, 0]",
                             .description = "capsule: the other end (not a)"}),
  };
}

// Contact, motion and mesh keys of a collider.
std::vector<Parameter> collider_contact() {
  return {
      row<&ColliderSpec::thickness>({.name = "thickness",
                                     .range = kNonNegative,
                                     .unit = "m",
                                     .fallback = "0.005",
                                     .description = "the cloth stays this far outside"}),
      special_row<&ColliderSpec::static_friction>(
          &special::read_collider_friction, {.name = "friction",
                                             .form = "mu or { static, kinetic }",
                                             .child = S::friction,
                                             .description = "Coulomb friction (one number: both)"}),
      table_row<&ColliderSpec::motion, S::motion>(
          {.name = "motion", .description = "constant velocities, or keyframes"}),
      row<&ColliderSpec::scale>({.name = "scale",
                                 .range = kPositive,
                                 .fallback = "1",
                                 .description = "mesh: applied to the OBJ's coordinates"}),
      row<&ColliderSpec::sdf_resolution>(
          {.name = "resolution",
           .range = between(8, 256),
           .range_text = "between 8 and 256 cells",
           .fallback = "64",
           .description = "mesh: distance-grid cells along its longest side"}),
      row<&ColliderSpec::file>(
          {.name = "file", .description = "mesh: a closed OBJ, relative to the scene"}),
  };
}

// friction's keys are read by its parent's reader; their values are checked on the collider.
std::vector<Parameter> friction_and_motion() {
  Parameter stat{.section = S::friction,
                 .name = "static",
                 .range = kNonNegative,
                 .fallback = "0.6",
                 .description = "sticks while |v_t| <= mu_s dv_n"};
  stat.values = &special::static_friction_values;
  Parameter kinetic{.section = S::friction,
                    .name = "kinetic",
                    .range = kNonNegative,
                    .fallback = "0.4",
                    .description = "sliding loses mu_k dv_n"};
  kinetic.values = &special::kinetic_friction_values;
  return {
      stat,
      kinetic,
      row<&ColliderMotion::velocity>(
          {.name = "velocity", .unit = "m/s", .fallback = "[0, 0, 0]", .description = "linear"}),
      row<&ColliderMotion::angular_velocity>({.name = "angular_velocity",
                                              .unit = "rad/s",
                                              .fallback = "[0, 0, 0]",
                                              .description = "about its centre, world axes"}),
      tables_row<&ColliderMotion::keys, S::keyframe, " of tables ({ time, offset, rotation })">(
          {.name = "keys", .description = "poses at times (not with velocities)"}),
      row<&ColliderKey::time>({.name = "time",
                               .unit = "s",
                               .description = "increasing",
                               .required = "a keyframe needs its time in s"}),
      row<&ColliderKey::offset>({.name = "offset",
                                 .unit = "m",
                                 .fallback = "[0, 0, 0]",
                                 .description = "the centre moved by this"}),
      row<&ColliderKey::rotation>({.name = "rotation",
                                   .unit = "deg",
                                   .fallback = "[0, 0, 0]",
                                   .description = "turned about the centre (slerp between keys)"}),
  };
}

std::vector<Parameter> music_and_mannequin() {
  return {
      row<&MusicSpec::file>(
          {.name = "file",
           .description = "WAV, FLAC, OGG or MP3 (libsndfile); absent: the drum track"}),
      row<&MusicSpec::tempo>({.name = "tempo",
                              .range = between(40.0, 240.0),
                              .unit = "BPM",
                              .fallback = "120",
                              .description = "the generated drum track's tempo"}),
      row<&MusicSpec::seconds>({.name = "seconds",
                                .range = between(1.0, 3600.0),
                                .unit = "s",
                                .fallback = "40",
                                .description = "the generated track's length"}),
      row<&MannequinSpec::position>(
          {.name = "position", .unit = "m", .fallback = "[0, 0, 0]", .description = "its soles"}),
      row<&MannequinSpec::facing>({.name = "facing",
                                   .unit = "deg",
                                   .fallback = "0",
                                   .description = "about +y; 0 faces +z"}),
      row<&MannequinSpec::settle>({.name = "settle",
                                   .range = between(0.0, 60.0),
                                   .unit = "s",
                                   .fallback = "1.5",
                                   .description = "in the rest pose before the dance blends in"}),
      row<&MannequinSpec::blend_beats>({.name = "blend_beats",
                                        .range = between(1, 64),
                                        .fallback = "4",
                                        .description = "beats of the blend"}),
      row<&MannequinSpec::amplitude>({.name = "amplitude",
                                      .range = between(0.0, 1.5),
                                      .fallback = "1",
                                      .description = "scales every pose's departure from rest"}),
      special_row<&MannequinSpec::static_friction>(&special::read_mannequin_friction,
                                                   {.name = "friction",
                                                    .fallback = "{ static = 0.8, kinetic = 0.6 }",
                                                    .form = "mu or { static, kinetic }",
                                                    .child = S::friction,
                                                    .description = "of every part"}),
      row<&MannequinSpec::thickness>({.name = "thickness",
                                      .range = kNonNegative,
                                      .unit = "m",
                                      .fallback = "0.006",
                                      .description = "the cloth stays this far outside"}),
  };
}

}  // namespace

std::vector<Parameter> contact_parameters() {
  std::vector<Parameter> all;
  for (auto part :
       {collider_shape(), collider_contact(), friction_and_motion(), music_and_mannequin()})
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

}  // namespace clothlab
