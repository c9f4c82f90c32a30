// The scene model: axis-aligned mirrors, absorbers and beam splitters, each
// two-sided or one-sided, and one or more rays and targets. The motion rules
// that act on it are in docs/semantics.md.
#pragma once

#include "orthoray/number.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
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

// A 2D element may also lie on a diagonal (docs/octagonal.md): `rising`
// has slope +1 (written '/'), `falling` slope -1 (written '\').
enum class Diagonal : std::uint8_t { none, rising, falling };

// A closed, axis-aligned piece of the hyperplane x[axis] = offset. It is
// stored as a closed box [lo, hi] whose extent along `axis` is the single
// value `offset` (lo[axis] == hi[axis] == offset), so "q lies on the element"
// is just "lo <= q <= hi on every axis".
//
// Or, in 2D, a closed diagonal segment: `diagonal` says which, `axis` is -1
// (an element has no normal axis then) and [lo, hi] is the segment's
// bounding box, lo.x < hi.x, the same length on both axes. A rising one runs
// from lo to hi, a falling one from (lo.x, hi.y) to (hi.x, lo.y). Diagonal
// elements are always two-sided.
struct Element {
    ElementKind kind = ElementKind::mirror;
    int axis = 0;
    Side side = Side::both;
    Diagonal diagonal = Diagonal::none;
    Vector lo, hi;
    int line = 0; // where it was declared in its file (0 when built in code)
    // Optional attenuation (docs/intensity.md), rationals in [0, 1]; absent
    // means 1 and is written back absent. A mirror or a splitter may carry a
    // reflectance, only a splitter a transmittance, an absorber neither.
    std::optional<Rational> reflectance, transmittance;

    bool is_diagonal() const { return diagonal != Diagonal::none; }
    // Axis-aligned elements only.
    const Rational& offset() const { return lo[axis]; }
    bool one_sided() const { return side != Side::both; }
    // The diagonal's endpoints, in the order a file writes them (x rising).
    Vector from() const;
    Vector to() const;
    // Whether q lies on the closed element (either kind).
    bool contains(const Vector& q) const;
    // Whether a diagonal acts on a ray along v: v is not parallel to it.
    bool diagonal_acts_on(const Vector& v) const {
        return diagonal == Diagonal::rising ? v[0] != v[1] : v[0] != -v[1];
    }
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
    // Optional starting intensity, a natural number (docs/intensity.md);
    // only `solve --min-intensity` reads it.
    std::optional<Integer> intensity;
    int column = 0; // of its `ray` keyword, or of its JSON object (0 likewise)
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
    // Some element lies on a diagonal (an octagonal maze, docs/octagonal.md).
    bool has_diagonal() const;
    // Every number in lowest terms. GMP compares and hashes rationals
    // correctly only so; the readers and the builders below keep them so,
    // but code may set a ray's start to Rational(2, 4) directly.
    bool in_lowest_terms() const;
    void to_lowest_terms();

    // Builders for code and tests; `extent` lists the other axes' [lo, hi]
    // pairs in axis order (x before y before z).
    void add(ElementKind kind, int axis, const Rational& offset,
             const std::vector<std::pair<Rational, Rational>>& extent, Side side = Side::both);
    // A diagonal element from (x0, y0) to (x1, y1): x0 < x1 and |y1 - y0| =
    // x1 - x0 (std::invalid_argument otherwise); 2D scenes only.
    void add_diagonal(ElementKind kind, const Rational& x0, const Rational& y0, const Rational& x1,
                      const Rational& y1);
    void add_mirror(int axis, const Rational& offset,
                    const std::vector<std::pair<Rational, Rational>>& extent) {
        add(ElementKind::mirror, axis, offset, extent);
    }
    void add_absorber(int axis, const Rational& offset,
                      const std::vector<std::pair<Rational, Rational>>& extent) {
        add(ElementKind::absorber, axis, offset, extent);
    }
};

// A scene a function cannot take, though it is well formed: diagonal
// elements where only axis-aligned ones are handled, say. The command line
// reports it as bad input (exit 2), with this message.
class UnsupportedScene : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws UnsupportedScene("WHAT does not take diagonal elements ...") when
// the scene has any.
void refuse_diagonals(const Scene& scene, const std::string& what);

// 'x', 'y', 'z'.
char axis_name(int axis);
// "mirror", "absorber", "splitter".
const char* to_string(ElementKind kind);
// "", "+", "-": what follows the axis letter in a file.
const char* side_sign(Side side);
// "/", "\\": how a file writes a diagonal ("" for none).
const char* diagonal_sign(Diagonal diagonal);

// The scene in the .scene text format; read_scene(write_scene(s)) == s.
std::string write_scene(const Scene& scene);

// The scene as JSON (docs/scene-json.md); read_scene_json(write_scene_json(s)) == s.
std::string write_scene_json(const Scene& scene);

} // namespace orthoray
