// Writes a scene as JSON (docs/scene-json.md): one element a line, so that a
// large scene stays readable and diffs well; rationals as strings in the
// canonical form of to_string, so nothing is rounded.
#include "orthoray/scene.hpp"

#include <sstream>

namespace orthoray {
namespace {

void write_point(std::ostream& out, const Vector& x, int dim) {
    out << '[';
    for (int j = 0; j < dim; ++j) out << (j ? ", \"" : "\"") << to_string(x[j]) << '"';
    out << ']';
}

} // namespace

std::string write_scene_json(const Scene& scene) {
    std::ostringstream out;
    out << "{\n  \"dim\": " << scene.dim << ",\n  \"elements\": [";
    for (std::size_t i = 0; i < scene.elements.size(); ++i) {
        const Element& e = scene.elements[i];
        out << (i ? ",\n" : "\n") << "    {\"kind\": \""
            << (e.kind == ElementKind::mirror ? "mirror" : "absorber") << "\", \"axis\": \""
            << axis_name(e.axis) << "\", \"offset\": \"" << to_string(e.offset())
            << "\", \"extent\": {";
        bool first = true;
        for (int j = 0; j < scene.dim; ++j) {
            if (j == e.axis) continue;
            out << (first ? "\"" : ", \"") << axis_name(j) << "\": [\"" << to_string(e.lo[j])
                << "\", \"" << to_string(e.hi[j]) << "\"]";
            first = false;
        }
        out << "}}";
    }
    out << (scene.elements.empty() ? "],\n" : "\n  ],\n") << "  \"ray\": {\"start\": ";
    write_point(out, scene.ray().start, scene.dim);
    out << ", \"direction\": ";
    write_point(out, scene.ray().direction, scene.dim);
    out << "},\n  \"target\": ";
    write_point(out, scene.target(), scene.dim);
    out << "\n}\n";
    return out.str();
}

} // namespace orthoray
