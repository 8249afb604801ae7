// The pieces of the `clothlab._clothlab` extension module (python/bindings/module.cpp), each
// registering its classes and functions, and the Python exceptions they raise (defined in
// python/clothlab/errors.py, so they carry attributes and pickle across processes).
#pragma once

#include <pybind11/pybind11.h>

#include "python/bindings/scene_source.hpp"
#include "sim/divergence.hpp"
#include "tune/tune.hpp"

namespace clothlab::py_bindings {

void bind_scene(pybind11::module_& m);
void bind_simulation(pybind11::module_& m);
void bind_trace(pybind11::module_& m);
void bind_render(pybind11::module_& m);
void bind_tune(pybind11::module_& m);

// The scene read with extra --set lines after its own (tune/tune.hpp).
tune::SceneReader reader_of(const SceneSource& source);

// Raises clothlab.DivergenceError for `d` (throws pybind11::error_already_set).
[[noreturn]] void raise_divergence(const Divergence& d);

// Throws pybind11::error_already_set when Ctrl-C (or another signal handler) raised in Python.
// Call with the GIL held.
void check_signals();

}  // namespace clothlab::py_bindings
