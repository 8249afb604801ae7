// The extension module `clothlab._clothlab`: Scene, Simulation and the trace run, with the C++
// errors turned into clothlab.SceneError and clothlab.DivergenceError (python/clothlab/).
#include <pybind11/pybind11.h>

#include "python/bindings/bindings.hpp"
#include "sim/scene/scene_error.hpp"

namespace py = pybind11;

namespace clothlab::py_bindings {

void raise_divergence(const Divergence& d) {
  const py::object cls = py::module_::import("clothlab.errors").attr("DivergenceError");
  const py::object error = cls(d.message(), d.step, d.time,
                               py::make_tuple(d.vertex.cloth, d.vertex.i, d.vertex.j), d.quantity);
  PyErr_SetObject(cls.ptr(), error.ptr());
  throw py::error_already_set();
}

void check_signals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

}  // namespace clothlab::py_bindings

PYBIND11_MODULE(_clothlab, m) {
  using namespace clothlab;
  m.doc() = "ClothLab's solver for Python: use the `clothlab` package, which wraps this module.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      const py::object cls = py::module_::import("clothlab.errors").attr("SceneError");
      const py::object error = cls(e.what(), e.loc.file, e.loc.line, e.key);
      PyErr_SetObject(cls.ptr(), error.ptr());
    }
  });
  py_bindings::bind_scene(m);
  py_bindings::bind_simulation(m);
  py_bindings::bind_trace(m);
  py_bindings::bind_tune(m);
  py_bindings::bind_render(m);
}
