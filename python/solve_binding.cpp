// orthoray.solve and orthoray.verify, and the Answer they return: the same
// fields as `orthoray solve --json` (the library's answer_json, read back as
// a dict, so the two front ends cannot differ), exact integers as Python
// ints. Solving releases the GIL; a signal whose handler raises (Ctrl-C's
// KeyboardInterrupt, or the caller's own) stops the run as a limit, and
// the exception is raised then, carrying the partial answer.
#include "bindings.hpp"
#include "exact_numbers.hpp"
#include "python_monitor.hpp"
#include "solved_scene.hpp"

#include "output_file.hpp"

#include "orthoray/answer_json.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"

#include <pybind11/stl.h>

#include <chrono>
#include <cstdio>
#include <sstream>

namespace orthoray::python {
namespace {

Engine engine_from(const std::string& name) {
    const auto it = engine_names().find(name);
    if (it == engine_names().end())
        throw py::value_error("engine: found '" + name +
                              "', expected auto, lattice, induction, reference or graph");
    return it->second;
}

// Writes the certificate as the command line writes every file
// (cli/output_file.hpp): through a temporary file of a name of its own
// beside the target, renamed into place once complete, so a reader never
// sees half of one, however many writers race; a device or a FIFO is
// written in place. A path refused before any work is a ValueError, a
// write that fails an OSError.
class CertificateFile {
public:
    CertificateFile(const std::string& path, const Scene& scene, CertificateFormat format)
        : out_(open(path)), writer_(out_->stream(), scene, format) {}
    CertificateWriter& writer() { return writer_; }
    void commit() {
        try {
            out_->commit();
        } catch (const cli::WriteError& e) {
            raise_write_error(e);
        }
    }
    // With the GIL held.
    [[noreturn]] static void raise_write_error(const cli::WriteError& e) {
        PyErr_SetString(PyExc_OSError, e.what());
        throw py::error_already_set();
    }

private:
    static std::unique_ptr<cli::OutputFile> open(const std::string& path) {
        try {
            return std::make_unique<cli::OutputFile>(path, std::vector<std::string>{},
                                                     "certificate");
        } catch (const cli::UsageError& e) {
            throw py::value_error(e.what());
        }
    }
    std::unique_ptr<cli::OutputFile> out_;
    CertificateWriter writer_;
};

// `scene` is a copy: the run goes on without the GIL, while another Python
// thread may change the caller's Scene.
SolvedScene solve_scene(Scene scene, const std::string& engine,
                        std::optional<std::uint64_t> max_steps, std::optional<double> timeout,
                        std::optional<std::string> certificate, const std::string& format,
                        const py::object& min_intensity) {
    require_ray_and_target(scene);
    SolveOptions options;
    options.engine = engine_from(engine);
    options.max_steps = max_steps;
    if (!min_intensity.is_none()) {
        const Rational eps = rational_from(min_intensity, "min_intensity");
        if (eps.get_den() != 1 || eps < 0)
            throw py::value_error("min_intensity: expected a natural number (0, 1, 2, ...)");
        if (options.engine == Engine::graph || options.engine == Engine::induction)
            throw py::value_error("min_intensity: the intensity question has its own branch "
                                  "search; use engine auto, lattice or reference");
        options.min_intensity = eps.get_num();
    }
    PythonMonitor monitor(timeout);
    options.monitor = &monitor;
    if (format != "text" && format != "jsonl")
        throw py::value_error("certificate_format: found '" + format + "', expected text or jsonl");
    std::optional<CertificateFile> file;
    if (certificate) {
        if (options.engine == Engine::graph)
            throw py::value_error("certificate: the graph engine writes none; use another engine");
        file.emplace(*certificate, scene,
                     format == "jsonl" ? CertificateFormat::jsonl : CertificateFormat::text);
        file->writer().attach(options);
    }
    const auto begin = std::chrono::steady_clock::now();
    Answer answer;
    try {
        py::gil_scoped_release released;
        answer = solve(scene, options);
        if (file) file->writer().finish(answer);
    } catch (const cli::WriteError& e) { // the GIL is back: `released` is gone
        CertificateFile::raise_write_error(e);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    if (file) file->commit();
    SolvedScene solved{
        scene,   answer,
        engine,  max_steps,
        timeout, '{' + answer_json_members(answer, engine_name(answer, engine), seconds) + '}'};
    if (monitor.interrupted()) {
        // Ctrl-C: a KeyboardInterrupt that says where the answer is.
        if (monitor.interrupt().matches(PyExc_KeyboardInterrupt)) {
            py::object error = py::module_::import("builtins")
                                   .attr("KeyboardInterrupt")("orthoray: interrupted; the partial "
                                                              "answer is this exception's .answer");
            error.attr("answer") = py::cast(solved);
            PyErr_SetObject(PyExc_KeyboardInterrupt, error.ptr());
            throw py::error_already_set();
        }
        // Another handler's exception goes through as it was raised,
        // carrying the partial answer too where it can hold an attribute.
        if (PyObject_SetAttrString(monitor.interrupt().value().ptr(), "answer",
                                   py::cast(solved).ptr()) != 0)
            PyErr_Clear();
        monitor.raise_if_interrupted();
    }
    return solved;
}

} // namespace

void bind_solve(py::module_& m) {
    py::class_<SolvedScene>(m, "Answer",
                            R"(What solve() found: the fields of `orthoray solve --json`.

answer ('yes', 'no' or 'unknown'), reason, reflections (an exact int), and
as they apply tail, period, limit, targets (the illumination question) and
what ran (engine, arithmetic, ...). as_dict() gives them all; an answer
shows its picture in a notebook.)")
        .def("as_dict", [](const SolvedScene& s) { return s.fields(); })
        .def("__getitem__",
             [](const SolvedScene& s, const std::string& key) {
                 const py::dict fields = s.fields();
                 if (!fields.contains(key)) throw py::key_error(key);
                 return fields[py::str(key)];
             })
        .def("__getattr__",
             [](const SolvedScene& s, const std::string& key) -> py::object {
                 const py::dict fields = s.fields();
                 if (fields.contains(key)) return fields[py::str(key)];
                 // tail, period, limit, targets when they do not apply
                 static const char* optional[] = {"tail", "period", "limit", "targets"};
                 for (const char* name : optional)
                     if (key == name) return py::none();
                 throw py::attribute_error("Answer has no field '" + key + "'");
             })
        .def_property_readonly("decided", [](const SolvedScene& s) { return s.answer.decided(); })
        .def("svg", &SolvedScene::svg, "The scene and the path (or branches) as SVG.")
        .def("_repr_svg_", &SolvedScene::svg)
        .def("__repr__", [](const SolvedScene& s) { return "<orthoray.Answer " + s.json + ">"; });

    m.def("solve", &solve_scene, py::arg("scene"), py::kw_only(), py::arg("engine") = "auto",
          py::arg("max_steps") = py::none(), py::arg("timeout") = py::none(),
          py::arg("certificate") = py::none(), py::arg("certificate_format") = "text",
          py::arg("min_intensity") = py::none(),
          R"(Decide the scene exactly, as `orthoray solve` does.

engine: auto, lattice, induction, reference or graph. max_steps and timeout
(seconds) end the run as a limit (answer 'unknown', reason 'limit'), with
what was proven so far. certificate: a path to write the certificate to
(certificate_format 'text' or 'jsonl'); verify() checks it. min_intensity:
an int EPS asks the intensity question instead (docs/intensity.md: is each
target reached with intensity above EPS? every ray needs an intensity);
each lit target then carries its 'intensity'.)");

    m.def(
        "verify",
        [](Scene scene, const std::string& certificate) { // a copy: the GIL is released
            require_ray_and_target(scene);
            const std::unique_ptr<std::istream> in = open_file_stream(certificate);
            Verdict verdict;
            {
                py::gil_scoped_release released;
                verdict = verify_certificate(scene, *in, certificate);
            }
            return py::make_tuple(verdict.valid, verdict.message);
        },
        py::arg("scene"), py::arg("certificate"),
        "Check a certificate file against the scene with the independent verifier: "
        "(valid, message).");
}

} // namespace orthoray::python
