// The parts of the orthoray Python module, each registered by its file.
#pragma once

#include "orthoray/scene.hpp"

#include <pybind11/pybind11.h>

namespace orthoray::python {

namespace py = pybind11;

void bind_scene(py::module_& m);
// ValueError unless the scene has a ray and a target (a Scene(dim) starts
// with neither), for every call that runs on it.
void require_ray_and_target(const Scene& scene); // scene_binding.cpp
void bind_solve(py::module_& m);                 // solve_binding.cpp
void bind_tools(py::module_& m);                 // tools_binding.cpp: generate, bounds, render

} // namespace orthoray::python
