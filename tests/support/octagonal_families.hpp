// Octagonal scenes with closed forms or known shapes, shared by the
// octagonal tests: the diamond |x| + |y| = n, the right triangle
// x, y >= 0, x + y <= n, and the slide box (docs/induction.md, "Two
// states stepping to one"): the box [0, w] x [0, h] of mirrors with a
// diagonal mirror of length sqrt(2) leaving the floor at (x0, 0), where a
// ray sliding down the diagonal's line meets the floor alone and one
// arriving along (1, -1) is sent back, so two states step to one.
#pragma once

#include "orthoray/scene.hpp"

namespace orthoray::test {

// The diamond |x| + |y| = n: four diagonal mirrors.
inline Scene diamond(const Integer& n) {
    Scene s;
    const Rational m(n);
    s.add_diagonal(ElementKind::mirror, 0, m, m, 0);
    s.add_diagonal(ElementKind::mirror, -m, 0, 0, m);
    s.add_diagonal(ElementKind::mirror, 0, -m, m, 0);
    s.add_diagonal(ElementKind::mirror, -m, 0, 0, -m);
    s.target() = {2 * m, 2 * m, 0}; // outside: never reached
    return s;
}

// The triangle x, y >= 0, x + y <= n: two axis mirrors and a diagonal.
inline Scene triangle(const Integer& n) {
    Scene s;
    const Rational m(n);
    s.add_mirror(0, 0, {{0, m}});
    s.add_mirror(1, 0, {{0, m}});
    s.add_diagonal(ElementKind::mirror, 0, m, m, 0);
    s.target() = {2 * m, 2 * m, 0};
    return s;
}

// The ray from (x, y) along (a, b).
inline void shoot(Scene& s, const Rational& x, const Rational& y, const Integer& a,
                  const Integer& b) {
    s.ray().start = {x, y, 0};
    s.ray().direction = {Rational(a), Rational(b), 0};
}

inline Scene slide_box(const Integer& w, const Integer& h, const Integer& x0, const Rational& x,
                       const Rational& y, const Vector& target) {
    Scene s;
    s.add_diagonal(ElementKind::mirror, Rational(x0), 0, Rational(x0 + 1), 1);
    s.add_mirror(0, 0, {{0, Rational(h)}});
    s.add_mirror(0, Rational(w), {{0, Rational(h)}});
    s.add_mirror(1, 0, {{0, Rational(w)}});
    s.add_mirror(1, Rational(h), {{0, Rational(w)}});
    shoot(s, x, y, 1, 1);
    s.target() = target;
    return s;
}

} // namespace orthoray::test
