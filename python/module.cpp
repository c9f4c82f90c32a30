// The orthoray Python module (docs/python.md): the library's scenes,
// solve, certificates, generate, bounds and pictures, for notebooks.
#include "bindings.hpp"

#include "orthoray/parse.hpp"
#include "orthoray/version.hpp"

PYBIND11_MODULE(orthoray, m) {
    namespace py = pybind11;
    m.doc() = "Exact ray tracing among axis-aligned and diagonal mirrors, with certificates.";
    m.attr("__version__") = orthoray::version;

    // Bad input: a ValueError that also says where, like the command line's
    // FILE:LINE:COL message (which is its str()).
    static py::exception<orthoray::InputError> input_error(m, "InputError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const orthoray::InputError& e) {
            py::object error = py::reinterpret_borrow<py::object>(input_error)(e.what());
            error.attr("file") = e.file();
            error.attr("line") = e.line();
            error.attr("column") = e.column();
            error.attr("message") = e.message();
            PyErr_SetObject(input_error.ptr(), error.ptr());
        } catch (const orthoray::UnsupportedScene& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });

    orthoray::python::bind_scene(m);
    orthoray::python::bind_solve(m);
    orthoray::python::bind_tools(m);
}
