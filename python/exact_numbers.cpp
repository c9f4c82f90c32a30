#include "exact_numbers.hpp"

#include "orthoray/parse.hpp"

#include <string>

namespace orthoray::python {

// Through hexadecimal: Python limits decimal conversions of ints to 4300
// digits (int_max_str_digits), but not those in a power-of-two base.
py::int_ to_python(const Integer& value) {
    const std::string digits = value.get_str(16);
    PyObject* result = PyLong_FromString(digits.c_str(), nullptr, 16);
    if (!result) throw py::error_already_set();
    return py::reinterpret_steal<py::int_>(result);
}

namespace {

// A Python int as an Integer, through hex() for the same reason.
Integer integer_from(const py::handle& value) {
    // Looked up once and never released: a static py::object would be
    // destroyed after the interpreter, at exit.
    static const py::object& hex = *new py::object(py::module_::import("builtins").attr("hex"));
    std::string text = hex(value).cast<std::string>(); // "0x1f" or "-0x1f"
    const bool negative = text.starts_with('-');
    Integer magnitude(text.substr(negative ? 3 : 2), 16);
    return negative ? Integer(-magnitude) : magnitude;
}

} // namespace

py::object to_python(const Rational& value) {
    // Looked up once and never released: a static py::object would be
    // destroyed after the interpreter, at exit.
    static const py::object& fraction =
        *new py::object(py::module_::import("fractions").attr("Fraction"));
    return fraction(to_python(Integer(value.get_num())), to_python(Integer(value.get_den())));
}

py::tuple to_python(const Vector& point, int dim) {
    py::tuple out(static_cast<std::size_t>(dim));
    for (int j = 0; j < dim; ++j) out[static_cast<std::size_t>(j)] = to_python(point[j]);
    return out;
}

Rational rational_from(const py::handle& value, const char* what) {
    // A bool is an int to Python, but True as a coordinate is surely a slip.
    if (py::isinstance<py::bool_>(value))
        throw py::type_error(std::string(what) +
                             ": found a bool, expected an int, a fractions.Fraction or a string "
                             "like '7/2'");
    if (py::isinstance<py::float_>(value))
        throw py::type_error(std::string(what) +
                             ": expected an int, a fractions.Fraction or a string like '7/2'; "
                             "floats are inexact, write 0.5 as Fraction(1, 2) or '0.5'");
    if (py::isinstance<py::int_>(value)) return Rational(integer_from(value));
    if (py::hasattr(value, "numerator") && py::hasattr(value, "denominator")) {
        const py::object numerator = value.attr("numerator"),
                         denominator = value.attr("denominator");
        if (!py::isinstance<py::int_>(numerator) || !py::isinstance<py::int_>(denominator))
            throw py::type_error(std::string(what) + ": expected a rational with int parts");
        const Integer d = integer_from(denominator);
        if (d == 0) throw py::value_error(std::string(what) + ": a zero denominator");
        Rational r(integer_from(numerator), d);
        r.canonicalize();
        return r;
    }
    if (py::isinstance<py::str>(value)) {
        const std::string text = value.cast<std::string>();
        NumberToken n = read_number(text);
        if (n.status != NumberToken::Status::ok)
            throw py::value_error(std::string(what) + ": found '" + text +
                                  "', expected a number (integer, fraction like 7/2, or "
                                  "decimal like 0.125) with a nonzero denominator");
        n.value.canonicalize();
        return n.value;
    }
    throw py::type_error(std::string(what) +
                         ": expected an int, a fractions.Fraction or a string like '7/2'");
}

Vector vector_from(const py::handle& values, int dim, const char* what) {
    if (!py::isinstance<py::sequence>(values) || py::isinstance<py::str>(values) ||
        static_cast<int>(py::len(values)) != dim)
        throw py::value_error(std::string(what) + ": expected a sequence of " +
                              std::to_string(dim) + " numbers");
    const py::sequence items = py::reinterpret_borrow<py::sequence>(values);
    Vector v;
    for (int j = 0; j < dim; ++j) v[j] = rational_from(items[static_cast<std::size_t>(j)], what);
    return v;
}

} // namespace orthoray::python
