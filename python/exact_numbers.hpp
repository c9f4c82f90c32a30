// Exact numbers across the Python boundary: orthoray's integers become
// Python ints and its rationals fractions.Fraction, through hexadecimal
// text (Python caps decimal conversions at 4300 digits), so nothing is
// rounded or refused however large; Python ints, Fractions and
// strings in the .scene number syntax come in. Floats are refused: a
// decision must not depend on a binary rounding the user did not see.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <pybind11/pybind11.h>

namespace orthoray::python {

namespace py = pybind11;

py::int_ to_python(const Integer& value);
py::object to_python(const Rational& value);
// The first `dim` coordinates, as a tuple of Fractions.
py::tuple to_python(const Vector& point, int dim);

// int, fractions.Fraction or str ("7/2", "0.125"); TypeError otherwise,
// ValueError for a malformed string. `what` names the argument.
Rational rational_from(const py::handle& value, const char* what);
// A sequence of `dim` numbers.
Vector vector_from(const py::handle& values, int dim, const char* what);

} // namespace orthoray::python
