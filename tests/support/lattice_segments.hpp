// Hand-built 2D lattice scenes for the piece tables' tests: a segment at a
// time, or the closed box of four walls.
#pragma once

#include "lattice/lattice_scene.hpp"

namespace orthoray::test {

// Adds the 2D mirror on the line x_axis = c over [lo, hi].
inline void add_segment(lattice::LatticeScene& ls, int axis, int c, int lo, int hi) {
    lattice::LatticeElement e;
    e.axis = axis;
    e.lo[axis] = e.hi[axis] = c;
    e.lo[1 - axis] = lo;
    e.hi[1 - axis] = hi;
    ls.elements.push_back(e);
}

// The mirror box [0, a] x [0, b]: walls x = 0, x = a, y = 0, y = b, in that
// order (elements 0 to 3).
inline lattice::LatticeScene lattice_box(int a, int b) {
    lattice::LatticeScene ls;
    ls.dim = 2;
    add_segment(ls, 0, 0, 0, b);
    add_segment(ls, 0, a, 0, b);
    add_segment(ls, 1, 0, 0, a);
    add_segment(ls, 1, b, 0, a);
    return ls;
}

} // namespace orthoray::test
