// clothlab.Simulation: one solver, stepped with the GIL released (a frame's worth of steps at a
// time, so Ctrl-C stops a long run within a frame), read as numpy arrays. Fields are copies in
// the solver's precision: the solver keeps its state by axis (x of every vertex, then y, then z),
// not as the (vertices, 3) rows a notebook wants, so a view would not have that shape.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "factory/solver_factory.hpp"
#include "python/bindings/bindings.hpp"
#include "sim/fields/spring_strain.hpp"
#include "sim/push_region.hpp"
#include "sim/scene/name_list.hpp"
#include "sim/solver.hpp"
#include "sim/trace/trace_run.hpp"

namespace py = pybind11;

namespace clothlab::py_bindings {

namespace {

// Steps run between two looks at Python's signals: one 1/60 s frame's worth.
constexpr double kSignalCheckSeconds = 1.0 / 60.0;

class Simulation {
 public:
  explicit Simulation(const SceneSource& source);

  // n steps; raises DivergenceError when the solver's monitor stops the run.
  void step(long n);

  // The steps advance(seconds) takes on the solver (the remainder carried to the next call).
  void advance(double seconds);

  py::array positions() const;
  py::array velocities() const;
  py::array rest_positions() const {
    return field([&](int v) { return solver_->rest_position(v); });
  }
  py::array forces(ForceSource source);

  py::dict energy();

  // Each spring's strain (spring_pairs order) and its mean at each vertex, float32.
  std::pair<py::array_t<float>, py::array_t<float>> strain();

  // Like the window's P: `impulse` (N s) on the free vertices within `radius` of `center`;
  // by default where the window pushes (sim/push_region.hpp).
  void push(const std::array<double, 3>& impulse, std::optional<std::array<double, 3>> center,
            std::optional<double> radius);

  void reset();

  void drop();

  // This call's hold on the solver: a second thread that steps, reads or changes the simulation
  // while one steps it (with the GIL released) is refused, never left to race.
  std::unique_lock<std::mutex> exclusive() const;

  const Solver& solver() const { return *solver_; }
  Solver& solver() { return *solver_; }
  const SceneSource& source() const { return source_; }
  const std::string& note() const { return note_; }
  bool doubles() const { return doubles_; }

  py::array_t<int> triangles() const;
  py::array_t<int> springs() const;

 private:
  // (vertices, 3) in the solver's precision, from a per-vertex reader.
  template <class Read>
  py::array field(Read read) const;
  template <class T, class Read>
  static py::array fill(py::ssize_t n, Read read);

  SceneSource source_;
  GlContextHandle context_;  // a GPU scene's headless context; outlives solver_
  std::unique_ptr<Solver> solver_;
  std::string note_;
  std::optional<SpringStrain> strain_;
  bool doubles_ = false;
  long chunk_ = 1;
  double pending_ = 0.0;
  mutable std::mutex busy_;  // held while a call steps, reads or changes the solver
};

inline Simulation::Simulation(const SceneSource& source) : source_(source) {
  std::string tolerance_note;
  const Scene scene = source.load_to_run(tolerance_note);
  doubles_ = scene.solver.precision == Precision::f64;
  solver_ = make_headless_backend_solver(scene, context_, note_);
  if (!tolerance_note.empty()) note_ += (note_.empty() ? "" : "; ") + tolerance_note;
  chunk_ = std::max(1L, std::lround(kSignalCheckSeconds / solver_->dt()));
}

inline void Simulation::step(long n) {
  if (n < 0)
    throw py::value_error("clothlab.Simulation.step: n must be >= 0 (got " + std::to_string(n) +
                          ")");
  const auto lock = exclusive();
  for (long done = 0; done < n;) {
    const long count = std::min(chunk_, n - done);
    AdvanceResult r;
    {
      py::gil_scoped_release release;
      r = solver_->step(count);
    }
    if (r.divergence) raise_divergence(*r.divergence);
    done += count;
    check_signals();
  }
}

inline void Simulation::advance(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds))
    throw py::value_error("clothlab.Simulation.advance: seconds must be finite and >= 0");
  const double wanted = pending_ + seconds;
  const long count = whole_steps(wanted, solver_->dt());
  if (count < 0) throw py::value_error("clothlab.Simulation.advance: too many steps");
  pending_ = std::max(0.0, wanted - double(count) * solver_->dt());
  step(count);
}

inline py::array Simulation::positions() const {
  const auto lock = exclusive();
  return field([&](int v) { return solver_->position(v); });
}

inline py::array Simulation::velocities() const {
  const auto lock = exclusive();
  return field([&](int v) { return solver_->velocity(v); });
}

inline py::array Simulation::forces(ForceSource source) {
  const auto lock = exclusive();
  solver_->update_force_field(source);
  return field([&](int v) { return solver_->force(v); });
}

inline py::dict Simulation::energy() {
  const auto lock = exclusive();
  const Energy e = solver_->energy();
  py::dict d;
  d["kinetic"] = e.kinetic, d["elastic"] = e.elastic, d["gravity"] = e.gravity;
  d["total"] = e.total();
  return d;
}

inline std::pair<py::array_t<float>, py::array_t<float>> Simulation::strain() {
  const auto lock = exclusive();
  if (!strain_) strain_.emplace(*solver_);
  std::vector<float> xyz(3 * solver_->vertex_count()), per_spring, per_vertex;
  solver_->copy_positions(xyz.data());
  strain_->per_spring(xyz, per_spring);
  strain_->per_vertex(per_spring, per_vertex);
  return {py::array_t<float>(py::ssize_t(per_spring.size()), per_spring.data()),
          py::array_t<float>(py::ssize_t(per_vertex.size()), per_vertex.data())};
}

inline void Simulation::push(const std::array<double, 3>& impulse,
                             std::optional<std::array<double, 3>> center,
                             std::optional<double> radius) {
  const auto lock = exclusive();
  const PushRegion region = default_push_region(*solver_);
  const Vec3d c = center ? Vec3d{(*center)[0], (*center)[1], (*center)[2]} : region.center;
  const double r = radius ? *radius : region.radius;
  if (!(r > 0.0) || !std::isfinite(r))
    throw py::value_error("clothlab.Simulation.push: radius must be > 0 and finite");
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(impulse[std::size_t(k)]) || !std::isfinite(c[std::size_t(k)]))
      throw py::value_error("clothlab.Simulation.push: impulse and center must be finite");
  solver_->apply_impulse(c, r, Vec3d{impulse[0], impulse[1], impulse[2]});
}

inline void Simulation::reset() {
  const auto lock = exclusive();
  solver_->reset();
  pending_ = 0.0;
}

inline void Simulation::drop() {
  const auto lock = exclusive();
  solver_->release_pins();
}

inline std::unique_lock<std::mutex> Simulation::exclusive() const {
  std::unique_lock<std::mutex> lock(busy_, std::try_to_lock);
  if (!lock.owns_lock())
    throw std::runtime_error("clothlab.Simulation: busy stepping in another thread");
  return lock;
}

inline py::array_t<int> Simulation::triangles() const {
  const auto& tris = solver_->triangles();
  py::array_t<int> out({py::ssize_t(tris.size()), py::ssize_t(3)});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) w(py::ssize_t(t), k) = tris[t][std::size_t(k)];
  return out;
}

inline py::array_t<int> Simulation::springs() const {
  const auto pairs = solver_->spring_pairs();
  py::array_t<int> out({py::ssize_t(pairs.size()), py::ssize_t(2)});
  auto w = out.mutable_unchecked<2>();
  for (std::size_t s = 0; s < pairs.size(); ++s)
    w(py::ssize_t(s), 0) = pairs[s][0], w(py::ssize_t(s), 1) = pairs[s][1];
  return out;
}

template <class Read>
inline py::array Simulation::field(Read read) const {
  const auto n = py::ssize_t(solver_->vertex_count());
  if (doubles_) return fill<double>(n, read);
  return fill<float>(n, read);
}

template <class T, class Read>
inline py::array Simulation::fill(py::ssize_t n, Read read) {
  py::array_t<T> out({n, py::ssize_t(3)});
  auto w = out.template mutable_unchecked<2>();
  for (py::ssize_t v = 0; v < n; ++v) {
    const Vec3d x = read(int(v));
    for (int k = 0; k < 3; ++k) w(v, k) = T(x[k]);
  }
  return out;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation",
                         "A running simulation of a Scene. Fields are numpy copies of shape "
                         "(vertices, 3) in the scene's solver.precision.")
      .def(py::init<const SceneSource&>(), py::arg("scene"))
      .def("step", &Simulation::step, py::arg("n") = 1,
           "Runs n steps of dt (the GIL released; Ctrl-C stops within a frame's worth).")
      .def("advance", &Simulation::advance, py::arg("seconds"),
           "Runs the whole steps that fit into `seconds` plus the remainder carried from the last "
           "call, as `clothlab trace --duration` counts them.")
      .def_property_readonly("time", [](const Simulation& s) { return s.solver().time(); })
      .def_property_readonly("dt", [](const Simulation& s) { return s.solver().dt(); })
      .def_property_readonly("steps", [](const Simulation& s) { return s.solver().step_count(); })
      .def_property_readonly("vertex_count",
                             [](const Simulation& s) { return s.solver().vertex_count(); })
      .def_property_readonly("positions", &Simulation::positions, "m, a copy")
      .def_property_readonly("velocities", &Simulation::velocities, "m/s, a copy")
      .def_property_readonly("rest_positions", &Simulation::rest_positions, "m, as built")
      .def_property_readonly(
          "forces", [](Simulation& s) { return s.forces(ForceSource::total); },
          "N, the total force on each vertex (a pinned vertex: its support's), a copy")
      .def(
          "force",
          [](Simulation& s, const std::string& source) {
            const auto f = parse_force_source(source);
            if (!f)
              throw py::value_error("clothlab.Simulation.force: unknown source '" + source +
                                    "' (one of " + comma_list(kAllForceSources, force_source_name) +
                                    ")");
            return s.forces(*f);
          },
          py::arg("source") = "total", "One force source's field (N), a copy.")
      .def_property_readonly("masses",
                             [](const Simulation& s) {
                               const auto& solver = s.solver();
                               std::vector<double> kg(solver.vertex_count());
                               for (std::size_t v = 0; v < kg.size(); ++v)
                                 kg[v] = solver.mass(int(v));
                               return py::array_t<double>(py::ssize_t(kg.size()), kg.data());
                             })
      .def_property_readonly("pinned",
                             [](const Simulation& s) {
                               const auto& solver = s.solver();
                               py::array_t<bool> out(py::ssize_t(solver.vertex_count()));
                               auto w = out.mutable_unchecked<1>();
                               for (py::ssize_t v = 0; v < w.shape(0); ++v)
                                 w(v) = solver.pinned(int(v));
                               return out;
                             })
      .def(
          "vertex_index",
          [](const Simulation& s, int i, int j, int cloth) {
            const auto& cloths = s.solver().cloths();
            const bool inside = cloth >= 0 && std::size_t(cloth) < cloths.size() && i >= 0 &&
                                j >= 0 && i < cloths[std::size_t(cloth)].nu &&
                                j < cloths[std::size_t(cloth)].nv;
            if (!inside)
              throw py::index_error("clothlab.Simulation.vertex_index: no vertex (" +
                                    std::to_string(i) + ", " + std::to_string(j) + ") in cloth " +
                                    std::to_string(cloth));
            return s.solver().vertex_index({cloth, i, j});
          },
          py::arg("i"), py::arg("j"), py::arg("cloth") = 0,
          "The row of vertex (i, j) of a cloth in the field arrays.")
      .def_property_readonly("triangles", &Simulation::triangles, "(triangles, 3) vertex indices")
      .def_property_readonly("springs", &Simulation::springs, "(springs, 2) vertex indices")
      .def("strain", &Simulation::strain,
           "(per spring, per vertex): engineering strain (l - l0) / l0 of each spring, in "
           "`springs` order, and its mean over the springs at each vertex")
      .def("energy", &Simulation::energy, "kinetic, elastic, gravity and total (J)")
      .def(
          "intersections", [](const Simulation& s) { return s.solver().intersections(); },
          "Crossing (edge, triangle) pairs of the cloth surfaces now: edges that pass through a "
          "triangle they share no vertex with (0 when no cloth passes through cloth).")
      .def_property_readonly(
          "contact",
          [](const Simulation& s) -> py::object {
            const auto c = s.solver().last_cloth_contact();
            if (!c) return py::none();
            py::dict d;
            d["candidates"] = c->candidates, d["contacts"] = c->contacts;
            d["rolled_back"] = c->rolled_back, d["unresolved"] = c->unresolved;
            d["overflow"] = c->overflow, d["collected"] = c->collected;
            d["recollected"] = c->recollected, d["flat_patches"] = c->flat_patches;
            d["flat_triangles"] = c->flat_triangles;
            return d;
          },
          "Triangle contact's last pass (None with solver.cloth_contact off): candidate pairs, "
          "pairs pushed apart, vertices the fail-safe returned, whether the pairs were collected, "
          "flat patches and their triangles.")
      .def("push", &Simulation::push, py::arg("impulse"), py::arg("center") = py::none(),
           py::arg("radius") = py::none(), "A push like the window's P (impulse in N s).")
      .def("drop", &Simulation::drop, "Lets go of every pin, like the window's D.")
      .def("reset", &Simulation::reset, "Back to t = 0, pins held again.")
      .def_property_readonly("scene", &Simulation::source)
      .def_property_readonly("backend",
                             [](const Simulation& s) { return backend_name(s.solver()); })
      .def_property_readonly("backend_note", &Simulation::note,
                             "Why a GPU scene runs on the CPU here, and the setting "
                             "solver.tolerance chose ('' when neither).")
      .def_property_readonly("threads", [](const Simulation& s) { return s.solver().threads(); })
      .def_property_readonly("solve_totals", [](const Simulation& s) {
        const SolveTotals& t = s.solver().solve_totals();
        py::dict d;
        d["substeps"] = t.substeps, d["iterations"] = t.iterations, d["solves"] = t.solves;
        d["max_iterations"] = t.max_iterations, d["max_residual"] = t.max_residual;
        d["unconverged"] = t.unconverged;
        return d;
      });
}

}  // namespace clothlab::py_bindings
