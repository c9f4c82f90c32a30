// The slide box (docs/induction.md, "Two states stepping to one"): the box
// [0, w] x [0, h] of mirrors with a diagonal mirror of length sqrt(2)
// leaving the floor at (x0, 0), and a ray from `start` along (1, 1). A ray
// sliding down the diagonal's line meets the floor alone at (x0, 0), one
// arriving there along (1, -1) is sent back: two states step to one.
#pragma once

#include "orthoray/scene.hpp"

namespace orthoray::test {

inline Scene slide_box(const Integer& w, const Integer& h, const Integer& x0, const Rational& x,
                       const Rational& y, const Vector& target) {
    Scene s;
    s.add_diagonal(ElementKind::mirror, Rational(x0), 0, Rational(x0 + 1), 1);
    s.add_mirror(0, 0, {{0, Rational(h)}});
    s.add_mirror(0, Rational(w), {{0, Rational(h)}});
    s.add_mirror(1, 0, {{0, Rational(w)}});
    s.add_mirror(1, Rational(h), {{0, Rational(w)}});
    s.ray().start = {x, y, 0};
    s.ray().direction = {1, 1, 0};
    s.target() = target;
    return s;
}

} // namespace orthoray::test
