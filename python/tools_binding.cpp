// generate, bounds and render for Python, and an answer's picture: thin
// calls into the library, drawing the way `orthoray render` does (the path
// of one two-sided trajectory, else every branch with its targets marked).
#include "bindings.hpp"
#include "exact_numbers.hpp"
#include "python_monitor.hpp"
#include "solved_scene.hpp"

#include "orthoray/bounds.hpp"
#include "orthoray/build_info.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/render.hpp"

#include <pybind11/stl.h>

#include <sstream>

namespace orthoray::python {
namespace {

// The path's points to the renderer, and the last direction, which says
// where an escaping ray leaves the picture.
class PathToPicture : public PathSink {
public:
    explicit PathToPicture(SceneRenderer& renderer) : renderer_(renderer) {}
    void visit(const Vector& point, const Vector& direction) override {
        renderer_.visit(point, direction);
        last_direction_ = direction;
    }
    const Vector& last_direction() const { return last_direction_; }

private:
    SceneRenderer& renderer_;
    Vector last_direction_;
};

// Draws the scene decided with `options` (its path capped at `max_path`
// reflections; the answer in the caption is decided without that cap).
std::string draw(const Scene& scene, SolveOptions options, const Answer& decided,
                 std::uint64_t max_path) {
    SceneRenderer renderer(scene);
    renderer.add_caption(std::string("answer ") + answer_word(decided) + ", reason " +
                         to_string(decided.reason) + ", reflections " +
                         decided.reflections.get_str());
    if (!scene.single_trajectory() || scene.has_one_sided()) {
        walk_branches(scene, renderer, max_path, options.monitor);
        renderer.mark_targets(decided.targets);
    } else {
        PathToPicture path(renderer);
        options.path = &path;
        options.max_steps = max_path;
        const Answer drawn = solve(scene, options);
        renderer.finish({drawn.reason, path.last_direction()});
    }
    std::ostringstream out;
    renderer.write_svg(out);
    return out.str();
}

py::dict bounds_dict(const StateBounds& b) {
    py::dict d;
    d["dim"] = b.dim;
    d["octagonal"] = b.octagonal;
    d["directions"] = b.directions;
    d["rays"] = b.rays;
    d["elements"] = b.elements;
    d["input_bits"] = b.input_bits;
    d["state_bits"] = b.state_bits;
    d["points"] = to_python(b.points);
    d["lattice_states"] = to_python(b.lattice_states);
    d["refined_states"] = to_python(b.refined_states);
    if (b.pieces) d["pieces"] = *b.pieces;
    return d;
}

} // namespace

py::dict SolvedScene::fields() const {
    // Looked up once and never released: a static py::object would be
    // destroyed after the interpreter, at exit.
    static const py::object& loads = *new py::object(py::module_::import("json").attr("loads"));
    // Integers through GMP and hex, not int(): Python refuses decimal text
    // of more than 4300 digits, and a count of reflections can be longer.
    static const py::object& exact_int = *new py::object(
        py::cpp_function([](const std::string& digits) { return to_python(Integer(digits, 10)); }));
    return loads(json, py::arg("parse_int") = exact_int);
}

std::string SolvedScene::svg() const {
    SolveOptions options;
    options.engine = Engine::automatic;
    PythonMonitor monitor(timeout);
    options.monitor = &monitor;
    std::string picture;
    {
        py::gil_scoped_release released;
        picture = draw(scene, options, answer, max_steps.value_or(100'000));
    }
    monitor.raise_if_interrupted();
    return picture;
}

void bind_tools(py::module_& m) {
    m.def(
        "render",
        [](Scene scene, std::uint64_t max_path, std::optional<double> timeout) {
            // A copy, run without the GIL: another thread may change the original.
            require_ray_and_target(scene);
            SolveOptions options;
            PythonMonitor monitor(timeout);
            options.monitor = &monitor;
            std::string picture;
            {
                py::gil_scoped_release released;
                const Answer decided = solve(scene, options);
                picture = draw(scene, options, decided, max_path);
            }
            monitor.raise_if_interrupted();
            return picture;
        },
        py::arg("scene"), py::kw_only(), py::arg("max_path") = 100'000,
        py::arg("timeout") = py::none(),
        "The scene with its path (or branches) as an SVG string, decided as solve() decides "
        "it; at most max_path reflections are drawn.");

    m.def(
        "bounds",
        [](Scene scene) { // a copy, run without the GIL
            require_ray_and_target(scene);
            StateBounds b;
            {
                py::gil_scoped_release released;
                b = compute_bounds(scene);
            }
            return bounds_dict(b);
        },
        py::arg("scene"),
        "The state-count bounds of docs/bounds.md: lattice_states (points * 2^M) and the "
        "refined count, exact ints.");

    m.def(
        "generate_random",
        [](int dim, std::int64_t mirrors, std::int64_t range, bool box, std::uint64_t seed) {
            RandomFamily family;
            family.dim = dim;
            family.mirrors = mirrors;
            family.range = range;
            family.box = box;
            family.seed = seed;
            return generate_random(family).scene;
        },
        py::kw_only(), py::arg("dim") = 2, py::arg("mirrors") = 20, py::arg("range") = 1000,
        py::arg("box") = false, py::arg("seed") = 1,
        "A random scene, the same for the same arguments as `orthoray generate random`.");

    m.def(
        "generate_box",
        [](const py::sequence& sides) {
            BoxFamily family;
            family.sides.clear();
            for (const py::handle side : sides) {
                const Rational r = rational_from(side, "sides");
                if (r.get_den() != 1) throw py::value_error("sides: expected integers");
                family.sides.push_back(Integer(r.get_num()));
            }
            if (family.sides.size() < 2 || family.sides.size() > 3)
                throw py::value_error("sides: expected 2 or 3 positive integers");
            for (const Integer& side : family.sides)
                if (side <= 0) throw py::value_error("sides: expected positive integers");
            return generate_box(family).scene;
        },
        py::arg("sides"),
        "The mirror box [0, a] x [0, b] (x [0, c]) shot from the corner along (1, 1(, 1)) at "
        "the corner it reaches, as `orthoray generate box`.");

    m.def("build_info", [] {
        const BuildInfo info = build_info();
        py::dict d;
        d["orthoray"] = info.orthoray;
        d["commit"] = info.commit;
        d["gmp"] = info.gmp;
        d["boost"] = info.boost;
        d["compiler"] = info.compiler;
        d["build_type"] = info.build_type;
        return d;
    });
}

} // namespace orthoray::python
