// clothlab.trace's C++ half: `clothlab trace`'s run (the same solver, steps and CSV writer) into
// a file the Python half reads with pandas, so the DataFrame holds the CSV's columns and values.
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "factory/solver_factory.hpp"
#include "python/bindings/bindings.hpp"
#include "sim/scene/trace_fields.hpp"
#include "sim/solver.hpp"
#include "sim/trace/trace_run.hpp"

namespace py = pybind11;

namespace clothlab::py_bindings {

namespace {

// The scene's trace table (or the default one) with the fields and interval asked for.
TraceSpec trace_spec(const Scene& scene, const std::optional<std::vector<std::string>>& fields,
                     std::optional<int> every) {
  TraceSpec spec = scene.trace ? *scene.trace : default_trace(scene);
  if (fields) {
    spec.position = spec.velocity = spec.force = spec.energy = false;
    for (const std::string& f : *fields) {
      bool* flag = trace_field(spec, f);
      if (!flag)
        throw py::value_error("clothlab.trace: unknown field '" + f + "' (" + trace_field_list() +
                              ")");
      *flag = true;
    }
  }
  if (every) {
    if (*every < 1)
      throw py::value_error("clothlab.trace: every must be >= 1 (got " + std::to_string(*every) +
                            ")");
    spec.every = *every;
  }
  return spec;
}

// Runs the trace into `out_path`; returns the summary `clothlab trace` prints, as a dict.
py::dict run(const SceneSource& source, double duration,
             const std::optional<std::vector<std::string>>& fields, std::optional<int> every,
             const std::string& out_path) {
  const Scene scene = source.load();
  const TraceSpec spec = trace_spec(scene, fields, every);
  GlContextHandle context;
  std::string note;
  const auto solver = make_headless_backend_solver(scene, context, note);
  const long total = whole_steps(duration, solver->dt());
  if (total <= 0)
    throw py::value_error("clothlab.trace: duration " + std::to_string(duration) +
                          " s is not a whole number of steps of " + std::to_string(solver->dt()) +
                          " s (at least 1)");
  bool interrupted = false;
  const TraceProgress progress = [&](long, long, double) {
    py::gil_scoped_acquire gil;
    interrupted = PyErr_CheckSignals() != 0;
    return !interrupted;
  };
  TraceRunResult r;
  {
    py::gil_scoped_release release;
    r = run_trace(*solver, spec, scene.multi_cloth, scene.solver.precision == Precision::f64, total,
                  out_path, progress);
  }
  if (interrupted) throw py::error_already_set();
  if (r.divergence) raise_divergence(*r.divergence);
  py::dict d;
  d["steps"] = r.steps, d["time"] = r.simulated_time, d["dt"] = solver->dt();
  d["step_seconds"] = r.step_seconds, d["written_steps"] = r.written_steps;
  d["backend"] = backend_name(*solver), d["backend_note"] = note;
  return d;
}

}  // namespace

void bind_trace(py::module_& m) {
  m.def("_run_trace", &run, py::arg("scene"), py::arg("duration"), py::arg("fields"),
        py::arg("every"), py::arg("out_path"));
}

}  // namespace clothlab::py_bindings
