// The checkers' own reading of how elements act on a ray (docs/optics.md,
// spec optics.md "Motion"): the first acting event in plain rationals and
// the directions that may leave it. Written apart from the engines'
// lib/src/engine/event_rule.cpp on purpose: a certificate is trusted only
// if a second, independent reading of the rules agrees with it.
#pragma once

#include "orthoray/number.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <vector>

namespace orthoray::certify {

// What the ray from a point meets first (at the smallest t > 0), counting
// only elements that act on it: an element seen from its back, or from
// within its plane, is invisible.
struct Event {
    bool met = false;
    Rational t;
    bool absorbed = false;       // an acting absorber is at the event point
    std::array<bool, 3> flip{};  // axes that reflect: an acting mirror of that normal
    std::array<bool, 3> split{}; // axes that split: acting splitters and no mirror
    // 2D diagonals (docs/octagonal.md), by slope (0: '/', 1: '\'): the
    // slopes where an acting diagonal lies, and where an acting diagonal
    // mirror lies.
    std::array<bool, 2> slope{}, slope_mirror{};
    // How many orientations (normal axes and slopes) act at the point: with
    // a diagonal among two or more, the ray goes back the way it came.
    int orientations = 0;
};

// Does the element act on a ray moving along v? Its normal component must
// be nonzero, and a one-sided element sees only rays coming from its sign's
// side (`+`: v_k < 0, `-`: v_k > 0). A diagonal's normal is (1, -1) for '/'
// and (1, 1) for '\', and it has no sides.
bool acts_on(const Element& element, const Vector& v);

Event first_met(const Scene& scene, const Vector& p, const Vector& v);

// The directions leaving the event (empty after an absorption): v with the
// reflecting axes negated, and any subset of the splitting axes besides.
// The first is the one with no splitting axis negated. Where a diagonal
// acts: -v if another orientation acts too; else v mirrored in the
// diagonal's line, after v itself when only splitters lie there.
std::vector<Vector> outgoing(const Vector& v, const Event& event, int dim);

} // namespace orthoray::certify
