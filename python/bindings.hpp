// The parts of the orthoray Python module, each registered by its file.
#pragma once

#include <pybind11/pybind11.h>

namespace orthoray::python {

namespace py = pybind11;

void bind_scene(py::module_& m); // scene_binding.cpp
void bind_solve(py::module_& m); // solve_binding.cpp
void bind_tools(py::module_& m); // tools_binding.cpp: generate, bounds, render

} // namespace orthoray::python
