#include "sim/model/model_check.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "sim/scene/parameter_keys.hpp"
#include "sim/scene/validate.hpp"

// GCC 12 at -O3 reports a false -Wrestrict inside std::string for `"text" + std::string(...)`
// (GCC bug 105329); the message texts below are built that way throughout.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

namespace clothlab {
namespace {

using binding::key_of;

// Finite, and inside T's range (every value of the model already is a T; a double model's values
// are held to the float range as the scene's are, so both precisions mean the same scene).
template <class T>
bool representable(T x) {
  return std::isfinite(x) && std::abs(double(x)) <= std::numeric_limits<float>::max();
}

// The cloth whose global vertex index is v (its ClothSpec).
const ClothSpec& cloth_of(const std::vector<ClothRange>& ranges, const Scene& scene,
                          std::size_t v) {
  std::size_t c = 0;
  while (c + 1 < ranges.size() && v >= std::size_t(ranges[c + 1].offset)) ++c;
  return scene.cloths[c];
}

[[noreturn]] void fail(const Scene& scene, const std::string& key, const std::string& message) {
  throw SceneError(location_of(scene, key), key, message);
}

template <class T>
const char* precision_name() {
  return sizeof(T) == sizeof(float) ? "float" : "double";
}

std::string springs_key() {
  return section_path(Section::springs);
}

}  // namespace

template <class T>
void check_built_model(const Model<T>& m, const Scene& scene, double energy) {
  for (std::size_t v = 0; v < m.n; ++v) {
    const auto bad_position = [&] {
      const ClothSpec& cloth = cloth_of(m.cloths, scene, v);
      fail(scene, cloth.key,
           "vertex " + std::to_string(v) + " is built at a position the " + precision_name<T>() +
               " solver cannot hold (|x| <= 3.4e+38 m); check " + cloth.key + "." +
               std::string(key_of<&ClothSpec::size>()) + ", " + cloth.key + "." +
               std::string(key_of<&ClothSpec::origin>()));
    };
    for (int a = 0; a < 3; ++a)
      if (!representable(m.rest_positions.axis(a)[v])) bad_position();
    if (!(representable(m.mass[v]) && m.mass[v] > T(0))) {
      const ClothSpec& cloth = cloth_of(m.cloths, scene, v);
      fail(scene, cloth.key + "." + std::string(key_of<&ClothSpec::mass>()),
           "gives vertex masses of " + format_number(double(m.mass[v])) + " kg in " +
               precision_name<T>() + " (each must be positive and finite)");
    }
  }
  auto springs = [&](const auto& values, const char* what) {
    for (std::size_t s = 0; s < values.size(); ++s)
      if (!representable(values[s]))
        fail(scene, springs_key(),
             std::string("a spring's ") + what + " is " + format_number(double(values[s])) +
                 " in " + precision_name<T>());
  };
  springs(m.stiffness, "stiffness");
  springs(m.rest_length, "rest length");
  springs(m.damping, "damping");
  for (const GridStencil<T>& g : m.grids)
    for (const auto& e : g.entries)
      if (!representable(e.stiffness) || !representable(e.rest_length) || !representable(e.damping))
        fail(scene, springs_key(),
             "a spring's stiffness, rest length or damping is not finite in " +
                 std::string(precision_name<T>()) + " (stiffness " +
                 format_number(double(e.stiffness)) + ", rest length " +
                 format_number(double(e.rest_length)) + ")");
  if (!std::isfinite(energy))
    fail(scene, scene.cloths.front().key,
         "the built cloth's energy is " + format_number(energy) +
             " J (not finite); check the cloths' size, origin, mass and the forces");
}

template <class T>
void check_built_forces(const Vec3Array<T>& f, const Model<T>& m, const Scene& scene) {
  for (std::size_t v = 0; v < m.n; ++v)
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(f.axis(a)[v])) {
        const std::string& key = cloth_of(m.cloths, scene, v).key;
        fail(scene, key,
             "the force on vertex " + std::to_string(v) + " of the built cloth is not finite in " +
                 precision_name<T>() +
                 " (its springs' squared lengths or the forces overflow); check " + key + "." +
                 std::string(key_of<&ClothSpec::size>()) + " and the stiffness, drag and wind");
      }
}

template <class T>
void check_contact_thickness(const Model<T>& m, const Scene& scene) {
  if (!scene.solver.cloth_contact || m.triangles.empty()) return;
  double sum = 0.0;
  for (const auto& t : m.triangles)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto a = std::size_t(t[k]), b = std::size_t(t[(k + 1) % 3]);
      sum += std::sqrt(std::pow(double(m.rest_positions.x[a] - m.rest_positions.x[b]), 2) +
                       std::pow(double(m.rest_positions.y[a] - m.rest_positions.y[b]), 2) +
                       std::pow(double(m.rest_positions.z[a] - m.rest_positions.z[b]), 2));
    }
  const double mean = sum / double(3 * m.triangles.size());
  if (scene.solver.self_thickness <= mean) return;
  const std::string key =
      section_path(Section::solver) + "." + std::string(key_of<&SolverSpec::self_thickness>());
  fail(scene, key,
       "with cloth_contact the thickness (" + format_number(scene.solver.self_thickness) +
           " m) must be at most the cloths' mean edge at rest (" + format_number(mean) +
           " m): refine the cloth or thin the layers");
}

void check_step(double dt, int substeps, const Scene& scene) {
  const std::string key =
      section_path(Section::solver) + "." + std::string(key_of<&SolverSpec::dt>());
  if (std::isfinite(dt) && dt > 0.0 && substeps >= 1 && std::isfinite(dt / substeps) &&
      dt / substeps > 0.0)
    return;
  fail(scene, key,
       std::string(scene.solver.dt_auto ? "the automatic step" : "the step") + " is " +
           format_number(dt) + " s in " + std::to_string(substeps) +
           " substep(s), not a positive finite time (stiffness, drag or mass out of proportion?)");
}

template void check_built_model<float>(const Model<float>&, const Scene&, double);
template void check_built_model<double>(const Model<double>&, const Scene&, double);
template void check_contact_thickness<float>(const Model<float>&, const Scene&);
template void check_contact_thickness<double>(const Model<double>&, const Scene&);
template void check_built_forces<float>(const Vec3Array<float>&, const Model<float>&, const Scene&);
template void check_built_forces<double>(const Vec3Array<double>&, const Model<double>&,
                                         const Scene&);

}  // namespace clothlab
