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

// The optional attenuation keys (docs/intensity.md), absent when unset.
void write_attenuation(std::ostream& out, const Element& e) {
    if (e.reflectance) out << ", \"reflectance\": \"" << to_string(*e.reflectance) << '"';
    if (e.transmittance) out << ", \"transmittance\": \"" << to_string(*e.transmittance) << '"';
}

} // namespace

std::string write_scene_json(const Scene& scene) {
    std::ostringstream out;
    out << "{\n  \"dim\": " << scene.dim << ",\n  \"elements\": [";
    for (std::size_t i = 0; i < scene.elements.size(); ++i) {
        const Element& e = scene.elements[i];
        if (e.is_diagonal()) {
            out << (i ? ",\n" : "\n") << "    {\"kind\": \"" << to_string(e.kind)
                << "\", \"diagonal\": \"" << (e.diagonal == Diagonal::rising ? "/" : "\\\\")
                << "\", \"from\": ";
            write_point(out, e.from(), 2);
            out << ", \"to\": ";
            write_point(out, e.to(), 2);
            write_attenuation(out, e);
            out << '}';
            continue;
        }
        out << (i ? ",\n" : "\n") << "    {\"kind\": \"" << to_string(e.kind) << "\", \"axis\": \""
            << axis_name(e.axis) << '"';
        if (e.one_sided()) out << ", \"side\": \"" << side_sign(e.side) << '"';
        out << ", \"offset\": \"" << to_string(e.offset()) << "\", \"extent\": {";
        bool first = true;
        for (int j = 0; j < scene.dim; ++j) {
            if (j == e.axis) continue;
            out << (first ? "\"" : ", \"") << axis_name(j) << "\": [\"" << to_string(e.lo[j])
                << "\", \"" << to_string(e.hi[j]) << "\"]";
            first = false;
        }
        out << '}';
        write_attenuation(out, e);
        out << '}';
    }
    out << (scene.elements.empty() ? "],\n" : "\n  ],\n");
    // One ray or target in the single form, several as an array.
    auto write_ray = [&](const Ray& ray) {
        out << "{\"start\": ";
        write_point(out, ray.start, scene.dim);
        out << ", \"direction\": ";
        write_point(out, ray.direction, scene.dim);
        if (ray.intensity) out << ", \"intensity\": \"" << ray.intensity->get_str() << '"';
        out << '}';
    };
    if (scene.rays.size() == 1) {
        out << "  \"ray\": ";
        write_ray(scene.ray());
    } else {
        out << "  \"rays\": [";
        for (std::size_t r = 0; r < scene.rays.size(); ++r) {
            out << (r ? ",\n    " : "\n    ");
            write_ray(scene.rays[r]);
        }
        out << "\n  ]";
    }
    if (scene.targets.size() == 1) {
        out << ",\n  \"target\": ";
        write_point(out, scene.target(), scene.dim);
    } else {
        out << ",\n  \"targets\": [";
        for (std::size_t t = 0; t < scene.targets.size(); ++t) {
            out << (t ? ",\n    " : "\n    ");
            write_point(out, scene.targets[t], scene.dim);
        }
        out << "\n  ]";
    }
    out << "\n}\n";
    return out.str();
}

} // namespace orthoray
