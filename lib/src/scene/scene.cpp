// Building scenes in code, and writing them back as .scene text.
#include "orthoray/scene.hpp"

#include <sstream>
#include <stdexcept>

namespace orthoray {

char axis_name(int axis) {
    return static_cast<char>('x' + axis);
}

const char* to_string(ElementKind kind) {
    switch (kind) {
    case ElementKind::mirror:
        return "mirror";
    case ElementKind::absorber:
        return "absorber";
    case ElementKind::splitter:
        return "splitter";
    }
    return "?";
}

const char* side_sign(Side side) {
    return side == Side::plus ? "+" : side == Side::minus ? "-" : "";
}

bool Scene::single_trajectory() const {
    if (rays.size() != 1 || targets.size() != 1) return false;
    for (const Element& e : elements)
        if (e.kind == ElementKind::splitter) return false;
    return true;
}

bool Scene::has_one_sided() const {
    for (const Element& e : elements)
        if (e.one_sided()) return true;
    return false;
}

void Scene::add(ElementKind kind, int axis, const Rational& offset,
                const std::vector<std::pair<Rational, Rational>>& extent, Side side) {
    if (axis < 0 || axis >= dim || static_cast<int>(extent.size()) != dim - 1)
        throw std::invalid_argument("Scene::add: axis or extent does not fit the dimension");
    Element e;
    e.kind = kind;
    e.axis = axis;
    e.side = side;
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
        out << to_string(e.kind) << ' ' << axis_name(e.axis) << side_sign(e.side) << ' '
            << to_string(e.offset());
        for (int j = 0; j < scene.dim; ++j)
            if (j != e.axis)
                out << ' ' << axis_name(j) << ' ' << to_string(e.lo[j]) << ' '
                    << to_string(e.hi[j]);
        out << '\n';
    }
    for (const Ray& ray : scene.rays) {
        out << "ray";
        for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(ray.start[j]);
        for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(ray.direction[j]);
        out << '\n';
    }
    for (const Vector& target : scene.targets) {
        out << "target";
        for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(target[j]);
        out << '\n';
    }
    return out.str();
}

} // namespace orthoray
