// The parameter table: every key a scene file may hold, once. Its order is the order the parser
// reads a table's keys in (the shape before the pins, the top-level springs before the cloths)
// and the order of `clothlab params`. The key table in docs/scene-format.md is generated from it
// (tests/parameter_table_test.cpp compares them).
#include "sim/scene/parameters.hpp"

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
using W = Widget;

constexpr double kInf = Range::kInf;

constexpr std::array<std::pair<Precision, const char*>, 2> kPrecisionNames{
    {{Precision::f32, "float"}, {Precision::f64, "double"}}};
constexpr std::array<std::pair<StepSolver, const char*>, 2> kStepSolverNames{
    {{StepSolver::newton, "newton"}, {StepSolver::vbd, "vbd"}}};
constexpr std::array<std::pair<LinearSolver, const char*>, 3> kLinearSolverNames{
    {{LinearSolver::automatic, "auto"},
     {LinearSolver::block_jacobi, "block_jacobi"},
     {LinearSolver::multigrid, "multigrid"}}};

std::vector<Parameter> top_level() {
  return {
      table_row<&Scene::springs, S::springs>(
          {.name = "springs", .description = "the springs of every cloth without its own"}),
      special_row<&Scene::cloths>(
          &special::read_cloths,
          {.name = "cloth",
           .form = "[cloth] or [[cloth]]",
           .child = S::cloth,
           .description = "one cloth, or several (a skirt and a cape); at least one"}),
      table_row<&Scene::forces, S::forces>({.name = "forces", .description = "external forces"}),
      table_row<&Scene::solver, S::solver>({.name = "solver", .description = "the time step"}),
      special_row<&Scene::trace>(
          &special::read_trace,
          {.name = "trace",
           .form = "[trace]",
           .child = S::trace,
           .description = "what `clothlab trace` and the window's recorder write"}),
      table_row<&Scene::render, S::render>(
          {.name = "render", .description = "how the scene is shown (vis/ only)"}),
      tables_row<&Scene::colliders, S::collider, " of tables ([[colliders]])">(
          {.name = "colliders", .description = "[[colliders]]: the solid shapes the cloth meets"}),
      special_row<&Scene::music>(
          &special::read_music,
          {.name = "music",
           .form = "[music]",
           .child = S::music,
           .description = "what the mannequin dances to: a sound file or the drum track"}),
      special_row<&Scene::mannequin>(
          &special::read_mannequin,
          {.name = "mannequin",
           .form = "[mannequin]",
           .child = S::mannequin,
           .description = "the dancing figure; its parts become colliders mannequin.<part>"}),

  };
}

std::vector<Parameter> cloth() {
  return {
      row<&ClothSpec::shape>({.name = "shape",
                              .fallback = "\"grid\"",
                              .choices = "grid, tube, mesh",
                              .description = "grid, tube (a cylinder or frustum) or mesh (OBJ)"}),
      row<&ClothSpec::size>({.name = "size",
                             .range = kPositive,
                             .unit = "m",
                             .fallback = "[2, 2]",
                             .description = "grid: metres along u and v",
                             .whole_key = true}),
      row<&ClothSpec::resolution>({.name = "resolution",
                                   .range = between(1, kInf),
                                   .fallback = "[32, 32]",
                                   .ui = between(2, 512),
                                   .description = "vertices along u and v (at most 16 M in all)",
                                   .whole_key = true}),
      row<&ClothSpec::origin>({.name = "origin",
                               .unit = "m",
                               .fallback = "[-1, 2.5, 0]",
                               .description = "world position of vertex (0, 0)"}),
      row<&ClothSpec::u_axis>({.name = "u_axis",
                               .fallback = "[1, 0, 0]",
                               .description = "direction of increasing i (normalised; non-zero)"}),
      row<&ClothSpec::v_axis>(
          {.name = "v_axis",
           .fallback = "[0, -1, 0]",
           .description = "direction of increasing j (normalised; orthogonal to u_axis)"}),
      row<&ClothSpec::mass>({.name = "mass",
                             .range = kPositive,
                             .unit = "kg",
                             .fallback = "1",
                             .description = "total mass, spread over the vertices"}),
  };
}

// Pins, tube and mesh keys of a cloth, and its own springs.
std::vector<Parameter> cloth_more() {
  return {
      special_row<&ClothSpec::pins>(
          &special::read_pins,
          {.name = "pins",
           .form = "[[i, j], ...]; mesh: OBJ vertex numbers",
           .description = "vertices held fixed (inside the grid, once each, one left free)"}),
      row<&ClothSpec::release_at>({.name = "release_at",
                                   .range = kNonNegative,
                                   .unit = "s",
                                   .description = "the pins let go at this time (a drop)"}),
      special_row<&ClothSpec::radius>(&special::read_radius,
                                      {.name = "radius",
                                       .count = 2,
                                       .range = kPositive,
                                       .unit = "m",
                                       .fallback = "0.3",
                                       .form = "r or [first ring, last ring]",
                                       .description = "tube: ring radii (one number: a cylinder)"},
                                      &special::radius_values),
      row<&ClothSpec::length>({.name = "length",
                               .range = kPositive,
                               .unit = "m",
                               .fallback = "0.6",
                               .description = "tube: first ring to last"}),
      special_row<&ClothSpec::pins_follow>(
          &special::read_pins_follow,
          {.name = "pins_follow",
           .form = "collider index or mannequin part name, or an array of them",
           .description = "the pins move with that collider (\"pelvis\", \"chest\", ...); with "
                          "several, each pin with the one whose centre is nearest at t = 0"}),
      special_row<&ClothSpec::springs>(
          &special::read_cloth_springs,
          {.name = "springs",
           .form = "a [springs] table",
           .child = S::springs,
           .description = "this cloth's springs; keys not given come from [springs]"}),
      row<&ClothSpec::file>(
          {.name = "file", .description = "mesh: the OBJ cloth (relative to the scene file)"}),
      row<&ClothSpec::scale>({.name = "scale",
                              .range = kPositive,
                              .fallback = "1",
                              .description = "mesh: scales the OBJ's coordinates"}),
      row<&ClothSpec::rotation>({.name = "rotation",
                                 .unit = "deg",
                                 .fallback = "[0, 0, 0]",
                                 .description = "mesh: turned about x, then y, then z"}),
  };
}

// springs.stretch / shear / bend: a class's specific stiffness, `stiffness` when not given.
template <auto M>
Parameter class_row(std::string_view name, std::string_view description) {
  return row<M>({.name = name,
                 .range = kNonNegative,
                 .unit = "N/m",
                 .fallback = "stiffness",
                 .widget = W::log_slider,
                 .ui = between(0.1, 1e5),
                 .description = description});
}

// Read before the values it sets, so keys written beside it override them.
Parameter spring_preset_row() {
  Parameter p = special_row<&SpringSpec::preset>(
      &special::read_spring_preset,
      {.name = "preset",
       .fallback = "none",
       .form = "a name",
       .choices = special::spring_preset_names(),
       .widget = W::combo,
       .description = "a material: sets stiffness, shear, bend and damping (docs/materials.md)"});
  p.choice_index = &special::spring_preset_index;
  p.choose = &special::choose_spring_preset;
  return p;
}

std::vector<Parameter> dynamics() {
  return {
      row<&SpringSpec::rule>({.name = "rule",
                              .fallback = "\"seed\"",
                              .choices = "seed",
                              .description = "seed: every vertex pair closer than 2 sqrt(2) edge"}),
      spring_preset_row(),
      row<&SpringSpec::stiffness>(
          {.name = "stiffness",
           .range = kNonNegative,
           .unit = "N/m",
           .fallback = "800",
           .widget = W::log_slider,
           .ui = between(1.0, 1e5),
           .description = "for a spring one edge long: k = stiffness * edge / L"}),
      class_row<&SpringSpec::stretch>("stretch", "axis neighbours and mesh edges (as stiffness)"),
      class_row<&SpringSpec::shear>("shear", "grid diagonals (as stiffness)"),
      class_row<&SpringSpec::bend>(
          "bend", "two steps along the grid, knight's moves, across mesh edges (as stiffness)"),
      row<&SpringSpec::damping>({.name = "damping",
                                 .range = kNonNegative,
                                 .unit = "N s/m",
                                 .fallback = "0",
                                 .widget = W::log_slider,
                                 .ui = between(0.0, 10.0),
                                 .description = "along the spring: F = -c ((v_a - v_b) . n) n"}),
      row<&ForceSpec::gravity>(
          {.name = "gravity", .unit = "m/s^2", .fallback = "[0, -9.81, 0]", .description = "g"}),
      row<&ForceSpec::drag>({.name = "drag",
                             .range = kNonNegative,
                             .unit = "N s/m",
                             .fallback = "0",
                             .widget = W::log_slider,
                             .ui = between(0.0, 1.0),
                             .description = "linear drag per vertex, F = -drag v"}),
      table_row<&ForceSpec::wind, S::wind>(
          {.name = "wind",
           .description = "gusty wind on the surface normal (docs/scene-format.md \"Wind\")"}),
      row<&WindSpec::velocity>({.name = "velocity",
                                .unit = "m/s",
                                .description = "the mean wind W",
                                .required = "wind needs velocity = [x, y, z] in m/s"}),
      row<&WindSpec::gust>({.name = "gust",
                            .range = kNonNegative,
                            .fallback = "0",
                            .description = "relative gust amplitude (0.5 = +-50 %)"}),
      special_row<&WindSpec::seed>(
          &special::read_seed, {.name = "seed",
                                .fallback = "0",
                                .form = "an integer >= 0",
                                .description = "noise seed: the same seed gives the same gusts"}),
      row<&WindSpec::gust_period>({.name = "gust_period",
                                   .range = between(1e-6, kInf),
                                   .unit = "s",
                                   .fallback = "1",
                                   .description = "time scale of the gust noise"}),
      row<&WindSpec::coefficient>({.name = "coefficient",
                                   .range = kNonNegative,
                                   .unit = "kg/(m^2 s)",
                                   .fallback = "1",
                                   .description = "F = coefficient A ((w - v) . n) n"}),
  };
}

Parameter integrator_row() {
  Parameter p = special_row<&SolverSpec::integrator>(
      &special::read_integrator, {.name = "integrator",
                                  .fallback = "\"symplectic_euler\"",
                                  .form = "a name",
                                  .choices = special::integrator_names(),
                                  .widget = W::combo,
                                  .description = "the time integrator (docs/solver.md)"});
  p.choice_index = &special::integrator_index;
  p.choose = &special::choose_integrator;
  return p;
}

std::vector<Parameter> solver() {
  return {
      integrator_row(),
      special_row<&SolverSpec::dt>(
          &special::read_dt,
          {.name = "dt",
           .range = {0.0, 1.0, true, false},
           .unit = "s",
           .fallback = "0.001",
           .form = "seconds or \"auto\"",
           .widget = W::step,
           .description = "the step, or auto: from the scene's highest frequency"},
          &special::dt_values),
      special_row<&SolverSpec::substeps>(
          &special::read_substeps,
          {.name = "substeps",
           .range = between(1, 100000),
           .fallback = "\"auto\"",
           .form = "an integer or \"auto\"",
           .widget = W::substeps,
           .description = "integrator steps of dt / substeps per step, or auto: xpbd 10 per "
                          "1/60 s (one per 10 vertices of a side beyond 100 where no coarse "
                          "stretch levels carry the corrections), every other method 1"},
          &special::substeps_values),
      row<&SolverSpec::tolerance>(
          {.name = "tolerance",
           .range = kNonNegative,
           .unit = "m",
           .fallback = "0",
           .description = "an accuracy instead of a step: trace and render take the cheapest "
                          "setting `clothlab tune` finds within this RMS distance of the scene's "
                          "reference to 1 s, kept in the cache (docs/tuning.md); 0: none"}),
      row<&SolverSpec::iterations>(
          {.name = "iterations",
           .range = between(0, 100000),
           .range_text = "between 0 (the method's default) and 100000",
           .fallback = "0",
           .only_for = "xpbd, local_global, vbd, bdf2",
           .widget = W::input,
           .description = "xpbd: sweeps per substep (1); local_global: per step (10); vbd and bdf2 "
                          "with bdf2_solver = vbd: per step (30); 0 = default"}),
      row<&SolverSpec::tethers>(
          {.name = "tethers",
           .fallback = "true",
           .only_for = "xpbd",
           .description = "grid cloths: no free vertex gets further from a pin than at rest "
                          "(long-range attachments, Kim et al. 2012)"}),
      row<&SolverSpec::coarse_stretch>(
          {.name = "coarse_stretch",
           .fallback = "true",
           .only_for = "xpbd",
           .description = "grid cloths of 64 or more vertices a side: one-sided stretch "
                          "constraints on coarser grids after each sweep (after Mueller 2008)"}),
      row<&SolverSpec::stretch_slack>(
          {.name = "stretch_slack",
           .fallback = "true",
           .only_for = "xpbd",
           .description =
               "tethers and coarse levels allow a strain that grows with the substeps "
               "beyond 10 per 1/60 s, so more substeps keep converging (docs/solver.md); "
               "false: none at any count"}),
  };
}

// The iterative solves of the large-step methods.
std::vector<Parameter> solver_iterations() {
  return {
      row<&SolverSpec::chebyshev_rho>(
          {.name = "chebyshev_rho",
           .range = {0.0, 1.0, false, true},
           .range_text = "between 0 (the method's default) and 1, exclusive of 1",
           .fallback = "0",
           .only_for = "local_global, vbd, bdf2",
           .widget = W::input,
           .description = "Chebyshev acceleration's spectral radius (Wang 2015): local_global "
                          "0.97, vbd 0.9; 0 = default, 1e-9 = off"}),
      row<&SolverSpec::cg_tolerance>(
          {.name = "cg_tolerance",
           .range = {0.0, 1.0, false, true},
           .range_text = "between 0 (automatic) and 1, exclusive of 1",
           .fallback = "0",
           .only_for = "implicit_euler, bdf2",
           .widget = W::log_slider,
           .ui = between(1e-10, 1e-1),
           .description = "PCG stops at relative residual |r| / |b| below this; 0 = 1e-6 for "
                          "one Newton iteration, 1e-2 per iteration when Newton iterates"}),
      row<&SolverSpec::newton_iterations>(
          {.name = "newton_iterations",
           .range = between(0, 100),
           .range_text = "between 0 (the method's default) and 100",
           .fallback = "0",
           .only_for = "implicit_euler, bdf2",
           .widget = W::input,
           .description = "Newton iterations per step at most (8); 1 = Baraff-Witkin's step"}),
      row<&SolverSpec::newton_tolerance>(
          {.name = "newton_tolerance",
           .range = {0.0, 1.0, true, false},
           .fallback = "0.01",
           .only_for = "implicit_euler, bdf2",
           .widget = W::log_slider,
           .ui = between(1e-6, 0.5),
           .description = "Newton stops once its correction is below this part of the step's "
                          "change of velocity (mass-weighted)"}),
      choice_row<&SolverSpec::bdf2_solver, kStepSolverNames, "bdf2 solver">(
          {.name = "bdf2_solver",
           .fallback = "\"newton\"",
           .only_for = "bdf2",
           .widget = W::combo,
           .description = "what solves each bdf2 step: newton (PCG) or vbd (iterations)"}),
      choice_row<&SolverSpec::linear_solver, kLinearSolverNames, "linear solver">(
          {.name = "linear_solver",
           .fallback = "\"auto\"",
           .only_for = "implicit_euler, bdf2",
           .widget = W::combo,
           .description =
               "PCG's preconditioner: block_jacobi, multigrid (one aggregation "
               "K-cycle per iteration), or auto (multigrid on grids from 65536 vertices, or "
               "once a block-Jacobi solve needs more than 150 iterations)"}),
      row<&SolverSpec::cg_max_iterations>({.name = "cg_max_iterations",
                                           .range = between(1, 100000),
                                           .fallback = "500",
                                           .only_for = "implicit_euler, bdf2",
                                           .widget = W::input,
                                           .description = "PCG iteration cap per step"}),
  };
}

std::vector<Parameter> solver_more() {
  return {
      row<&SolverSpec::threads>(
          {.name = "threads",
           .range = between(0, 1024),
           .range_text = "between 0 (auto) and 1024",
           .fallback = "0",
           .description = "OpenMP threads, 0 = auto (one below 8192 vertices, else all cores)"}),
      choice_row<&SolverSpec::precision, kPrecisionNames, "precision">(
          {.name = "precision",
           .fallback = "\"float\"",
           .description = "float or double (double for reference runs)"}),
      row<&SolverSpec::self_collision>(
          {.name = "self_collision",
           .fallback = "false",
           .description = "the cloth keeps its layers self_thickness apart"}),
      row<&SolverSpec::cloth_contact>(
          {.name = "cloth_contact",
           .fallback = "false",
           .description = "triangles of every cloth keep self_thickness apart and never pass "
                          "through each other"}),
      row<&SolverSpec::self_thickness>({.name = "self_thickness",
                                        .range = kPositive,
                                        .unit = "m",
                                        .fallback = "0.005",
                                        .description = "how far apart two layers stay"}),
      choice_row<&SolverSpec::backend, kBackendNames, "backend">(
          {.name = "backend",
           .fallback = "\"cpu\"",
           .widget = W::combo,
           .description = "gpu: the step as OpenGL compute shaders where it can run; "
                          "transform_feedback: as a vertex shader whose output is captured "
                          "(grid cloths; symplectic_euler, explicit_euler, seed_hack; float)"}),

  };
}

std::vector<Parameter> trace() {
  return {
      special_row<&TraceSpec::vertices>(
          &special::read_trace_vertices,
          {.name = "vertices",
           .form = "[[i, j], ...] or [[c, i, j], ...] with [[cloth]]",
           .description = "vertices to record (default: the middle of the last row)"}),
      special_row<&TraceSpec::position>(&special::read_trace_fields,
                                        {.name = "fields",
                                         .fallback = "all",
                                         .form = "names",
                                         .choices = "position, velocity, force, energy",
                                         .description = "what each row holds"}),
      row<&TraceSpec::every>({.name = "every",
                              .range = between(1, kInf),
                              .fallback = "1",
                              .description = "write every N steps"}),
  };
}

}  // namespace

std::vector<Parameter> render_parameters();   // parameters_render.cpp
std::vector<Parameter> contact_parameters();  // parameters_contact.cpp

std::span<const Parameter> parameters() {
  static const std::vector<Parameter> table = [] {
    std::vector<Parameter> all;
    for (auto part : {top_level(), cloth(), cloth_more(), dynamics(), solver(), solver_iterations(),
                      solver_more(), trace(), render_parameters(), contact_parameters()})
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }();
  return table;
}

}  // namespace clothlab
