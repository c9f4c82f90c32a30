// The next-hit answer by scanning every element: the oracle for the grid and
// the BVH. Written out in full on purpose (it does not use Shot::record), so
// that it shares no logic with the structures it checks. Elements that do
// not act on the direction (one-sided, seen from their back) are skipped.
#pragma once

#include "shoot/uniform_grid.hpp"

namespace orthoray::test {

template <class Int, int M>
shoot::Shot<Int> brute_force_shot(const lattice::LatticeScene& ls, const Int (&p)[M],
                                  unsigned negative) {
    using lattice::from_integer;
    shoot::Shot<Int> best;
    for (const lattice::LatticeElement& e : ls.elements) {
        if (!e.acts_on(negative)) continue; // seen from its back (one-sided)
        const int a = e.axis;
        const bool neg_a = (negative >> a) & 1u;
        Int c = from_integer<Int>(e.lo[a]);
        Int t = neg_a ? Int(p[a] - c) : Int(c - p[a]);
        if (t <= 0) continue;
        bool on = true;
        for (int j = 0; j < M; ++j) {
            Int x = ((negative >> j) & 1u) ? Int(p[j] - t) : Int(p[j] + t);
            on = on && from_integer<Int>(e.lo[j]) <= x && x <= from_integer<Int>(e.hi[j]);
        }
        if (!on || (!best.escape && best.t < t)) continue;
        if (best.escape || t < best.t) {
            best = shoot::Shot<Int>{};
            best.escape = false;
            best.t = t;
        }
        best.met |= 1u << a;
        if (e.absorber)
            best.absorber = true;
        else
            best.flip |= 1u << a;
    }
    return best;
}

// `got.mirror` is a mirror whose closed box holds the hit point p + t*sigma.
template <class Int, int M>
bool mirror_holds_hit(const lattice::LatticeScene& ls, const shoot::Shot<Int>& got,
                      const Int (&p)[M], unsigned negative) {
    if (got.mirror >= ls.elements.size()) return false;
    const lattice::LatticeElement& e = ls.elements[got.mirror];
    if (e.absorber || ((got.flip >> e.axis) & 1u) == 0) return false;
    for (int j = 0; j < M; ++j) {
        Int x = ((negative >> j) & 1u) ? Int(p[j] - got.t) : Int(p[j] + got.t);
        if (x < lattice::from_integer<Int>(e.lo[j]) || lattice::from_integer<Int>(e.hi[j]) < x)
            return false;
    }
    return true;
}

} // namespace orthoray::test
