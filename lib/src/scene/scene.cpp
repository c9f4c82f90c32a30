// Building scenes in code, and writing them back as .scene text.
#include "orthoray/scene.hpp"

#include <algorithm>
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

const char* diagonal_sign(Diagonal diagonal) {
    return diagonal == Diagonal::rising ? "/" : diagonal == Diagonal::falling ? "\\" : "";
}

Vector Element::from() const {
    return {lo[0], diagonal == Diagonal::falling ? hi[1] : lo[1], Rational(0)};
}

Vector Element::to() const {
    return {hi[0], diagonal == Diagonal::falling ? lo[1] : hi[1], Rational(0)};
}

bool Element::contains(const Vector& q) const {
    for (int j = 0; j < 3; ++j)
        if (q[j] < lo[j] || hi[j] < q[j]) return false;
    // In its box, a diagonal's points are those on its line.
    if (diagonal == Diagonal::rising) return q[1] - q[0] == lo[1] - lo[0];
    if (diagonal == Diagonal::falling) return q[0] + q[1] == lo[0] + hi[1];
    return true;
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

void refuse_diagonals(const Scene& scene, const std::string& what) {
    for (const Element& e : scene.elements)
        if (e.is_diagonal())
            throw UnsupportedScene(what + " does not take diagonal elements (the one on line " +
                                   std::to_string(e.line) + "); docs/octagonal.md says what does");
}

bool Scene::has_diagonal() const {
    for (const Element& e : elements)
        if (e.is_diagonal()) return true;
    return false;
}

void Scene::add_diagonal(ElementKind kind, const Rational& x0, const Rational& y0,
                         const Rational& x1, const Rational& y1) {
    if (dim != 2) throw std::invalid_argument("Scene::add_diagonal: diagonals are 2D only");
    const Rational run = x1 - x0, rise = y1 - y0;
    if (!(x0 < x1) || (rise != run && rise != -run))
        throw std::invalid_argument("Scene::add_diagonal: not a segment of slope +1 or -1");
    Element e;
    e.kind = kind;
    e.axis = -1;
    e.diagonal = rise == run ? Diagonal::rising : Diagonal::falling;
    e.lo = {x0, std::min(y0, y1), Rational(0)};
    e.hi = {x1, std::max(y0, y1), Rational(0)};
    for (int j = 0; j < 2; ++j) {
        e.lo[j].canonicalize();
        e.hi[j].canonicalize();
    }
    elements.push_back(e);
}

namespace {

// (An integer, as most coordinates are, needs no gcd: it costs a GMP call
// and an allocation per number, on every solve.)
bool lowest(const Rational& q) {
    if (is_integer(q)) return true;
    return sgn(q.get_den()) > 0 && Integer(gcd(q.get_num(), q.get_den())) == 1;
}

// Calls f on every number of the scene.
template <class S, class F>
void each_number(S& scene, F f) {
    for (auto& e : scene.elements)
        for (int j = 0; j < 3; ++j) {
            f(e.lo[j]);
            f(e.hi[j]);
        }
    for (auto& r : scene.rays)
        for (int j = 0; j < 3; ++j) {
            f(r.start[j]);
            f(r.direction[j]);
        }
    for (auto& t : scene.targets)
        for (int j = 0; j < 3; ++j) f(t[j]);
}

} // namespace

bool Scene::in_lowest_terms() const {
    bool all = true;
    each_number(*this, [&](const Rational& q) { all = all && lowest(q); });
    return all;
}

void Scene::to_lowest_terms() {
    each_number(*this, [](Rational& q) { q.canonicalize(); });
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

namespace {

// The optional trailing attributes of an element (docs/intensity.md); none
// when absent, so scenes without them are written as before.
void write_attenuation(std::ostream& out, const Element& e) {
    if (e.reflectance) out << " reflectance " << to_string(*e.reflectance);
    if (e.transmittance) out << " transmittance " << to_string(*e.transmittance);
}

} // namespace

std::string write_scene(const Scene& scene) {
    std::ostringstream out;
    out << "dim " << scene.dim << '\n';
    for (const Element& e : scene.elements) {
        if (e.is_diagonal()) {
            const Vector a = e.from(), b = e.to();
            out << to_string(e.kind) << ' ' << diagonal_sign(e.diagonal) << ' ' << to_string(a[0])
                << ' ' << to_string(a[1]) << ' ' << to_string(b[0]) << ' ' << to_string(b[1]);
            write_attenuation(out, e);
            out << '\n';
            continue;
        }
        out << to_string(e.kind) << ' ' << axis_name(e.axis) << side_sign(e.side) << ' '
            << to_string(e.offset());
        for (int j = 0; j < scene.dim; ++j)
            if (j != e.axis)
                out << ' ' << axis_name(j) << ' ' << to_string(e.lo[j]) << ' '
                    << to_string(e.hi[j]);
        write_attenuation(out, e);
        out << '\n';
    }
    for (const Ray& ray : scene.rays) {
        out << "ray";
        for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(ray.start[j]);
        for (int j = 0; j < scene.dim; ++j) out << ' ' << to_string(ray.direction[j]);
        if (ray.intensity) out << " intensity " << ray.intensity->get_str();
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
