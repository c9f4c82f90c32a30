// An answer together with what it answers: the scene and the options it was
// solved with, so that its picture can be drawn the way `orthoray render`
// draws it, and its fields as `solve --json` prints them.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>

namespace orthoray::python {

struct SolvedScene {
    Scene scene;
    Answer answer;
    std::string engine;
    std::optional<std::uint64_t> max_steps;
    std::optional<double> timeout;
    std::string json; // the object solve --json prints

    pybind11::dict fields() const; // json, read by Python's json module
    std::string svg() const;       // tools_binding.cpp
};

} // namespace orthoray::python
