// The geometry the octagonal exchange is built on (docs/induction.md,
// "Octagonal mazes"): the scene scaled to integers, the eight symmetries of
// the square that carry the start direction to every direction the ray can
// take, the transverse coordinate w in which every reflection is a
// translation, and an exact brute-force shot.
//
// Scaling. Let v = (a, b) be the start direction as a primitive integer
// vector and D the lcm of the scene's denominators. Every coordinate is
// multiplied by F = 2 D K, K the lcm of the nonzero ones among |a|, |b|,
// |a - b|, |a + b|. The 2 makes the crossing of a '/' and a '\' line
// integral; K makes every state of the orbit integral (a state on a line
// sits at a position (w - w0) / kappa, kappa one of those four numbers, see
// below). Scaling changes no answer: the motion is invariant under
// homotheties.
#pragma once

#include "induction/interval_stabbing.hpp"
#include "lattice/lattice_int.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace orthoray::induction::octagonal {

// The dihedral group of the square as signed permutation matrices m; index
// 0 is the identity. A state's *sheet* g says its direction is g v.
struct Symmetry {
    int m[2][2];
};
const std::array<Symmetry, 8>& symmetries();
int compose(int r, int g); // the index of r * g
int inverse(int g);

// A line of the arrangement: x = c (vertical), y = c (horizontal), y - x = c
// (rising, '/'), y + x = c (falling, '\'). A point's position on it is its y
// on a vertical line, its x otherwise.
enum class Orientation : std::uint8_t { vertical, horizontal, rising, falling };

template <class Int>
using Point = std::array<Int, 2>;

template <class Int>
struct Segment {
    Orientation orientation;
    Int c, lo, hi; // the line's constant, and the closed range of positions
    bool absorber = false;
    const Element* element = nullptr;
};

template <class Int>
Int line_constant(Orientation o, const Point<Int>& p) {
    switch (o) {
    case Orientation::vertical:
        return p[0];
    case Orientation::horizontal:
        return p[1];
    case Orientation::rising:
        return p[1] - p[0];
    case Orientation::falling:
        return p[1] + p[0];
    }
    return p[0];
}
template <class Int>
const Int& position(Orientation o, const Point<Int>& p) {
    return o == Orientation::vertical ? p[1] : p[0];
}
template <class Int>
Point<Int> point_on(Orientation o, const Int& c, const Int& pos) {
    switch (o) {
    case Orientation::vertical:
        return {c, pos};
    case Orientation::horizontal:
        return {pos, c};
    case Orientation::rising:
        return {pos, Int(pos + c)};
    case Orientation::falling:
        return {pos, Int(c - pos)};
    }
    return {pos, c};
}
// The linear part of the reflection in a line of this orientation: it fixes
// the line's direction, so q - R q is the same for every q on the line.
int reflection_of(Orientation o);

// The first point where a ray meets an acting segment: t = num / den > 0.
template <class Int>
struct Shot {
    bool found = false;
    Int num, den;
    std::size_t segment = 0;
};

template <class Int>
struct OctagonalScene {
    std::vector<Segment<Int>> segments;
    Point<Int> start, target;
    Int a, b;          // v, primitive
    Integer scale;     // F
    Integer magnitude; // the largest |coordinate| after scaling
    // acting[g][s]: segment s acts on a ray along direction g v.
    std::array<std::vector<std::uint8_t>, 8> acting;
    std::array<Point<Int>, 8> direction; // g v
    // Per sheet, the acting segments by the range of cross(g v, p) over
    // their points p: only those whose range holds the ray's value can meet it.
    std::array<IntervalStabbing<Int>, 8> crossing_lines;

    Vector direction_vector(int g) const; // g v as scene numbers
    // w(q, g) = cross(v, g^-1 q): constant along the ray, translated by every
    // reflection on a line (the sheet becomes R g).
    Int w(const Point<Int>& q, int g) const;
    // The sheet of direction d (the first g with g v = d).
    int sheet_of(const Point<Int>& d) const;
    // The point q + (num / den) d, which must be integral.
    Point<Int> advance(const Point<Int>& q, int g, const Shot<Int>& shot, bool backwards) const;
    // The first acting segment along direction g v (or -g v) from q, t > 0.
    Shot<Int> shoot(const Point<Int>& q, int g, bool backwards = false) const;
    // The segments containing q that act on g v.
    std::vector<const Segment<Int>*> acting_at(const Point<Int>& q, int g) const;
};

// The scene's numbers scaled and converted; `magnitude_of` first tells the
// caller which integer type the scene needs.
Integer octagonal_magnitude(const Scene& scene);
template <class Int>
OctagonalScene<Int> make_octagonal(const Scene& scene);

// The direction leaving q after an event, from the rule of
// engine/event_rule (the one place it lives), and the symmetry R taking the
// incoming direction to it: a line reflection where only one orientation
// acts (so that w is translated), else the first element of the group that
// fits. Nothing when the ray is absorbed there.
template <class Int>
struct Outcome {
    bool absorbed = false;
    int sheet = 0; // R g
};
template <class Int>
Outcome<Int> outcome_at(const OctagonalScene<Int>& scene,
                        const std::vector<const Segment<Int>*>& acting, int g);

} // namespace orthoray::induction::octagonal
