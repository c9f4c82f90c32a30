// orthoray.Scene: loading, parsing and building scenes of every element kind
// of the spec (mirrors, absorbers, splitters; one-sided axis elements; 2D
// diagonals; several rays and targets), and writing them back as .scene
// text or JSON. Bad input raises orthoray.InputError with file, line and
// column; everything else is the library's.
#include "bindings.hpp"
#include "exact_numbers.hpp"

#include "orthoray/parse.hpp"
#include "orthoray/render.hpp"

#include <pybind11/stl.h>

#include <sstream>

namespace orthoray::python {
namespace {

ElementKind kind_from(const std::string& kind) {
    if (kind == "mirror") return ElementKind::mirror;
    if (kind == "absorber") return ElementKind::absorber;
    if (kind == "splitter") return ElementKind::splitter;
    throw py::value_error("kind: found '" + kind + "', expected mirror, absorber or splitter");
}

int axis_from(const std::string& axis, int dim) {
    if (axis.size() == 1 && axis[0] >= 'x' && axis[0] < 'x' + dim) return axis[0] - 'x';
    throw py::value_error("axis: found '" + axis + "', expected " +
                          (dim == 2 ? "x or y" : "x, y or z"));
}

Side side_from(const std::string& side) {
    if (side.empty()) return Side::both;
    if (side == "+") return Side::plus;
    if (side == "-") return Side::minus;
    throw py::value_error("side: found '" + side + "', expected '', '+' or '-'");
}

// An element as a dict: kind, and either axis/offset/extent/side or
// diagonal/from/to, the way JSON scenes write it (docs/scene-json.md).
py::dict element_dict(const Element& e, int dim) {
    py::dict d;
    d["kind"] = to_string(e.kind);
    if (e.is_diagonal()) {
        d["diagonal"] = diagonal_sign(e.diagonal);
        d["from"] = to_python(e.from(), 2);
        d["to"] = to_python(e.to(), 2);
        return d;
    }
    d["axis"] = std::string(1, axis_name(e.axis));
    d["side"] = side_sign(e.side);
    d["offset"] = to_python(e.offset());
    py::dict extent;
    for (int j = 0; j < dim; ++j)
        if (j != e.axis)
            extent[py::str(std::string(1, axis_name(j)))] =
                py::make_tuple(to_python(e.lo[j]), to_python(e.hi[j]));
    d["extent"] = extent;
    return d;
}

std::string scene_svg(const Scene& scene) {
    SceneRenderer renderer(scene);
    std::ostringstream out;
    renderer.write_svg(out);
    return out.str();
}

} // namespace

void require_ray_and_target(const Scene& scene) {
    if (scene.rays.empty() || scene.targets.empty())
        throw py::value_error("the scene needs at least one ray and one target");
}

void bind_scene(py::module_& m) {
    py::class_<Scene>(m, "Scene", R"(A scene: elements, rays and targets (docs/scene-format.md).

Build one in code (Scene(dim), then add, add_diagonal, add_ray, add_target),
or read one: Scene.load(path), Scene.parse(text), Scene.parse_json(text).
Numbers are exact: pass ints, fractions.Fraction or strings like '7/2'.)")
        .def(py::init([](int dim) {
                 if (dim != 2 && dim != 3) throw py::value_error("dim: expected 2 or 3");
                 Scene s;
                 s.dim = dim;
                 s.rays.clear();
                 s.targets.clear();
                 return s;
             }),
             py::arg("dim") = 2)
        .def_static(
            "load",
            [](const std::string& path, const std::string& format) {
                if (format != "auto" && format != "json" && format != "scene" && format != "grid")
                    throw py::value_error("format: found '" + format +
                                          "', expected auto, scene, json or grid");
                const SceneFormat f = format == "json"    ? SceneFormat::json
                                      : format == "scene" ? SceneFormat::text
                                      : format == "grid"  ? SceneFormat::grid
                                                          : SceneFormat::automatic;
                return load_scene(path, f);
            },
            py::arg("path"), py::arg("format") = "auto",
            "Read a .scene or JSON file, or a grid maze (.grid, docs/grid-mazes.md) as its scene "
            "('-' is standard input); format 'auto' goes by the name.")
        .def_static(
            "parse",
            [](const std::string& text, const std::string& name) { return read_scene(text, name); },
            py::arg("text"), py::arg("name") = "<string>", "Read .scene text.")
        .def_static(
            "parse_json",
            [](const std::string& text, const std::string& name) {
                return read_scene_json(text, name);
            },
            py::arg("text"), py::arg("name") = "<string>", "Read a JSON scene.")
        .def_readonly("dim", &Scene::dim)
        .def(
            "add",
            [](Scene& s, const std::string& kind, const std::string& axis, const py::handle& offset,
               const py::sequence& extent, const std::string& side) {
                const int a = axis_from(axis, s.dim);
                if (static_cast<int>(extent.size()) != s.dim - 1)
                    throw py::value_error("extent: expected " + std::to_string(s.dim - 1) +
                                          " (lo, hi) pairs, one for each other axis in order");
                std::vector<std::pair<Rational, Rational>> ranges;
                for (const py::handle pair : extent) {
                    const Vector r = vector_from(pair, 2, "extent");
                    if (!(r[0] < r[1])) throw py::value_error("extent: expected lo < hi");
                    ranges.emplace_back(r[0], r[1]);
                }
                s.add(kind_from(kind), a, rational_from(offset, "offset"), ranges, side_from(side));
            },
            py::arg("kind"), py::arg("axis"), py::arg("offset"), py::arg("extent"),
            py::arg("side") = "",
            "Add an axis-aligned element: add('mirror', 'x', 3, [(0, 5)]); side '+' or '-' "
            "makes it one-sided.")
        .def(
            "add_diagonal",
            [](Scene& s, const std::string& kind, const py::sequence& from,
               const py::sequence& to) {
                if (s.dim != 2) throw py::value_error("diagonal elements are 2D only");
                const Vector a = vector_from(from, 2, "from"), b = vector_from(to, 2, "to");
                try {
                    s.add_diagonal(kind_from(kind), a[0], a[1], b[0], b[1]);
                } catch (const std::invalid_argument&) {
                    throw py::value_error("expected from.x < to.x on a line of slope +1 or -1");
                }
            },
            py::arg("kind"), py::arg("from_"), py::arg("to"),
            "Add a 2D diagonal element from (x0, y0) to (x1, y1), x0 < x1, slope +1 or -1.")
        .def(
            "add_ray",
            [](Scene& s, const py::sequence& start, const py::sequence& direction) {
                Ray r;
                r.start = vector_from(start, s.dim, "start");
                r.direction = vector_from(direction, s.dim, "direction");
                bool zero = true;
                for (int j = 0; j < s.dim; ++j) zero = zero && r.direction[j] == 0;
                if (zero) throw py::value_error("direction: expected a nonzero direction");
                s.rays.push_back(r);
            },
            py::arg("start"), py::arg("direction"))
        .def(
            "add_target",
            [](Scene& s, const py::sequence& point) {
                s.targets.push_back(vector_from(point, s.dim, "target"));
            },
            py::arg("point"))
        .def_property_readonly("elements",
                               [](const Scene& s) {
                                   py::list out;
                                   for (const Element& e : s.elements)
                                       out.append(element_dict(e, s.dim));
                                   return out;
                               })
        .def_property_readonly("rays",
                               [](const Scene& s) {
                                   py::list out;
                                   for (const Ray& r : s.rays)
                                       out.append(py::make_tuple(to_python(r.start, s.dim),
                                                                 to_python(r.direction, s.dim)));
                                   return out;
                               })
        .def_property_readonly("targets",
                               [](const Scene& s) {
                                   py::list out;
                                   for (const Vector& t : s.targets)
                                       out.append(to_python(t, s.dim));
                                   return out;
                               })
        .def("text", &write_scene, "The scene as .scene text.")
        .def("json", &write_scene_json, "The scene as JSON text.")
        .def("svg", &scene_svg, "The scene alone, drawn as SVG.")
        .def("_repr_svg_", &scene_svg)
        .def("__repr__", [](const Scene& s) {
            return "<orthoray.Scene dim " + std::to_string(s.dim) + ", " +
                   std::to_string(s.elements.size()) + " elements, " +
                   std::to_string(s.rays.size()) + " rays, " + std::to_string(s.targets.size()) +
                   " targets>";
        });
}

} // namespace orthoray::python
