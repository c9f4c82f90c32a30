// The picture's frame: the exact box a picture shows, and the one place
// where scene coordinates become doubles. Every coordinate is first made
// relative to the frame in exact rationals and only then converted, so
// scenes far from the origin, with 40-digit coordinates or with sides no
// double can hold still draw in the right place.
#pragma once

#include "orthoray/scene.hpp"

#include <array>

namespace orthoray::render {

// Coordinates in normalised units: axis j runs over [0, extent[j]].
using Point3 = std::array<double, 3>;

class Frame {
public:
    // The box around the elements, the rays' starts and the targets; a side of
    // length zero gets the longest side's length. It is padded by 4% of the
    // longest side, or of each side when the sides are scaled separately.
    explicit Frame(const Scene& scene);

    Point3 normalised(const Vector& p) const;
    // A direction component in normalised units.
    double normalised_component(const Rational& v, int axis) const;

    std::array<Rational, 3> lo, hi;
    std::array<double, 3> extent{}; // the longest side is 1
    // The sides differ too much for one scale (more than 8 times), so each
    // axis runs over [0, 1]; the caption says so.
    bool separate_scales = false;

private:
    int dim_;
    std::array<Rational, 3> width_;     // hi - lo
    std::array<double, 3> unit_{};      // normalised units per scene unit
    std::array<bool, 3> exact_ratio_{}; // the side does not fit a double: divide exactly
    mutable Rational difference_;       // reused: a path may have 10^7 points
};

} // namespace orthoray::render
