// The scene model: axis-aligned mirrors, absorbers and beam splitters, each
// two-sided or one-sided, and one or more rays and targets. The motion rules
// that act on it are in docs/semantics.md.
#pragma once

#include "orthoray/number.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace orthoray {

// Points and directions always have three slots; a 2D scene leaves the third
// at zero. This keeps 2D and 3D code the same without templates on the API.
using Vector = std::array<Rational, 3>;

// mirror: reflects; absorber: stops the ray; splitter: a half-silvered
// mirror, the ray goes on through it AND a reflected ray leaves it.
enum class ElementKind : std::uint8_t { mirror, absorber, splitter };

// Which rays an element acts on. A one-sided element is invisible from its
// other side: `plus` acts only on rays arriving from the + side of its plane
// (moving toward -axis, direction component < 0), `minus` only on rays
// arriving from the - side (component > 0). Written `x+` / `x-` in files.
enum class Side : std::uint8_t { both, plus, minus };

// A closed, axis-aligned piece of the hyperplane x[axis] = offset. It is
// stored as a closed box [lo, hi] whose extent along `axis` is the single
// value `offset` (lo[axis] == hi[axis] == offset), so "q lies on the element"
// is just "lo <= q <= hi on every axis".
struct Element {
    ElementKind kind = ElementKind::mirror;
    int axis = 0;
    Side side = Side::both;
    Vector lo, hi;
    int line = 0; // where it was declared in its file (0 when built in code)

    const Rational& offset() const { return lo[axis]; }
    bool one_sided() const { return side != Side::both; }
    // Whether the element acts on a ray whose direction component along the
    // element's axis has this sign (-1, 0 or +1). A ray parallel to the
    // plane (sign 0) is never acted on.
    bool acts_on_sign(int normal_sign) const {
        if (normal_sign == 0) return false;
        if (side == Side::plus) return normal_sign < 0;
        if (side == Side::minus) return normal_sign > 0;
        return true;
    }
};

// A light source: a start point and a direction (any nonzero vector).
struct Ray {
    Vector start, direction;
    int line = 0; // where it was declared in its file (0 when built in code)
};

// A scene has at least one ray and one target; rays and targets are
// numbered from 1 in file order. A scene built in code starts with one ray
// and one target, both at the origin, for the builder to fill in.
struct Scene {
    int dim = 2;
    std::vector<Element> elements;
    std::vector<Ray> rays{Ray{}};
    std::vector<Vector> targets{Vector{}};

    // The first ray and target: all of the problem when the scene is a
    // single trajectory.
    Ray& ray() { return rays.front(); }
    const Ray& ray() const { return rays.front(); }
    Vector& target() { return targets.front(); }
    const Vector& target() const { return targets.front(); }

    // One ray, one target and no splitter: the question of semantics.md
    // (does the ray reach the target?), not the illumination question.
    bool single_trajectory() const;
    // Some element is one-sided: the step map may be non-injective, so a
    // trajectory can enter a cycle after a tail (rho-shaped).
    bool has_one_sided() const;

    // Builders for code and tests; `extent` lists the other axes' [lo, hi]
    // pairs in axis order (x before y before z).
    void add(ElementKind kind, int axis, const Rational& offset,
             const std::vector<std::pair<Rational, Rational>>& extent, Side side = Side::both);
    void add_mirror(int axis, const Rational& offset,
                    const std::vector<std::pair<Rational, Rational>>& extent) {
        add(ElementKind::mirror, axis, offset, extent);
    }
    void add_absorber(int axis, const Rational& offset,
                      const std::vector<std::pair<Rational, Rational>>& extent) {
        add(ElementKind::absorber, axis, offset, extent);
    }
};

// 'x', 'y', 'z'.
char axis_name(int axis);
// "mirror", "absorber", "splitter".
const char* to_string(ElementKind kind);
// "", "+", "-": what follows the axis letter in a file.
const char* side_sign(Side side);

// The scene in the .scene text format; read_scene(write_scene(s)) == s.
std::string write_scene(const Scene& scene);

// The scene as JSON (docs/scene-json.md); read_scene_json(write_scene_json(s)) == s.
std::string write_scene_json(const Scene& scene);

} // namespace orthoray
