// The scene model: axis-aligned mirrors and absorbers, one ray, one target.
// The motion rules that act on it are in docs/semantics.md.
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

enum class ElementKind : std::uint8_t { mirror, absorber };

// A closed, axis-aligned piece of the hyperplane x[axis] = offset. It is
// stored as a closed box [lo, hi] whose extent along `axis` is the single
// value `offset` (lo[axis] == hi[axis] == offset), so "q lies on the element"
// is just "lo <= q <= hi on every axis".
struct Element {
    ElementKind kind = ElementKind::mirror;
    int axis = 0;
    Vector lo, hi;
    int line = 0; // where it was declared in its file (0 when built in code)

    const Rational& offset() const { return lo[axis]; }
};

struct Scene {
    int dim = 2;
    std::vector<Element> elements;
    Vector start, direction, target;

    // Builders for code and tests; `extent` lists the other axes' [lo, hi]
    // pairs in axis order (x before y before z).
    void add(ElementKind kind, int axis, const Rational& offset,
             const std::vector<std::pair<Rational, Rational>>& extent);
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

// The scene in the .scene text format; read_scene(write_scene(s)) == s.
std::string write_scene(const Scene& scene);

// The scene as JSON (docs/scene-json.md); read_scene_json(write_scene_json(s)) == s.
std::string write_scene_json(const Scene& scene);

} // namespace orthoray
