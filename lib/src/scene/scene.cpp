// Building scenes in code, and writing them back as .scene text.
#include "orthoray/scene.hpp"

#include <sstream>
#include <stdexcept>

namespace orthoray {

char axis_name(int axis) {
    return static_cast<char>('x' + axis);
}

void Scene::add(ElementKind kind, int axis, const Rational& offset,
                const std::vector<std::pair<Rational, Rational>>& extent) {
    if (axis < 0 || axis >= dim || static_cast<int>(extent.size()) != dim - 1)
        throw std::invalid_argument("Scene::add: axis or extent does not fit the dimension");
    Element e;
    e.kind = kind;
    e.axis = axis;
    // GMP compares rationals correctly only in lowest terms.
    e.lo[axis] = e.hi[axis] = offset;
    e.lo[axis].canonicalize();
    e.hi[axis].canonicalize();
    std::size_t next = 0;
    for (int j = 0; j < dim; ++j) {
        if (j == axis) continue;
        e.lo[j] = extent[next].first;
        e.hi[j] = extent[next].second;
        e.lo[j].canonicalize();
        e.hi[j].canonicalize();
        if (!(e.lo[j] < e.hi[j])) throw std::invalid_argument("Scene::add: empty extent");
        ++next;
    }
    elements.push_back(e);
}

std::string write_scene(const Scene& scene) {
    std::ostringstream out;
    out << "dim " << scene.dim << '\n';
    for (const Element& e : scene.elements) {
        out << (e.kind == ElementKind::mirror ? "mirror " : "absorber ") << axis_name(e.axis) << ' '
            << to_string(e.offset());
        for (int j = 0; j < scene.dim; ++j)
            if (j != e.axis)
                out << ' ' << axis_name(j) << ' ' << to_string(e.lo[j]) << ' '
                    << to_string(e.hi[j]);
        out << '\n';
    }
    out << "ray";
    for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(scene.start[j]);
    for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(scene.direction[j]);
    out << "\ntarget";
    for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(scene.target[j]);
    out << '\n';
    return out.str();
}

} // namespace orthoray
