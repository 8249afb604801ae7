// Readers for the keys whose value has a form of its own ("auto" or seconds, one radius or two,
// pins, a cloth table or a list of them, ...). Each reads the value the TomlReader stands on
// into its section's struct; the parameter table (parameters.cpp) points at them.
#pragma once

#include <string>
#include <string_view>

#include "sim/scene/toml_reader.hpp"

namespace clothlab::special {

// Top level (object: Scene).
void read_cloths(TomlReader& in, void* scene);  // [cloth] or [[cloth]]
void read_trace(TomlReader& in, void* scene);
void read_music(TomlReader& in, void* scene);
void read_mannequin(TomlReader& in, void* scene);

// [cloth] (object: ClothSpec).
void read_pins(TomlReader& in, void* cloth);
void read_radius(TomlReader& in, void* cloth);
void read_pins_follow(TomlReader& in, void* cloth);
void read_cloth_springs(TomlReader& in, void* cloth);
int radius_values(const void* cloth, double* out);

// springs.preset (object: SpringSpec): applies the preset's values as it is read.
void read_spring_preset(TomlReader& in, void* springs);
int spring_preset_index(const void* springs);
void choose_spring_preset(void* springs, int index);

// [solver] (object: SolverSpec).
void read_integrator(TomlReader& in, void* solver);
int integrator_index(const void* solver);
void choose_integrator(void* solver, int index);
void read_dt(TomlReader& in, void* solver);
int dt_values(const void* solver, double* out);
// solver.substeps: an integer >= 1 or "auto" (stored as 0); the range applies to integers only.
void read_substeps(TomlReader& in, void* solver);
int substeps_values(const void* solver, double* out);

// forces.wind.seed (object: WindSpec).
void read_seed(TomlReader& in, void* wind);

// friction = 0.5 or { static, kinetic } (object: ColliderSpec or MannequinSpec).
void read_collider_friction(TomlReader& in, void* collider);
void read_mannequin_friction(TomlReader& in, void* mannequin);
int static_friction_values(const void* collider, double* out);
int kinetic_friction_values(const void* collider, double* out);

// [trace] (object: TraceSpec).
void read_trace_vertices(TomlReader& in, void* trace);
void read_trace_fields(TomlReader& in, void* trace);

// The valid names of an enum's table ("a, b, c"), for the key table and messages.
std::string_view integrator_names();
std::string_view spring_preset_names();

}  // namespace clothlab::special
