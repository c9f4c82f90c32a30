// The invariant of the ray's unfolded line (docs/bounds.md), and the
// residue-class counting the bounds are made of.
#pragma once

#include "lattice/lattice_scene.hpp"

#include <array>

namespace orthoray::bounds {

// Integers x in [lo, hi] with x = r (mod G); G = 0 means x = r.
Integer count_congruent(const Integer& lo, const Integer& hi, const Integer& r, const Integer& G);

// Integers x in [lo, hi] with x = r1 (mod G1) and x = r2 (mod G2) (Chinese
// remainder theorem; a modulus 0 means equality).
Integer count_congruent_both(const Integer& lo, const Integer& hi, const Integer& r1,
                             const Integer& G1, const Integer& r2, const Integer& G2);

// With s the direction (+-1 per axis) and o_k the offset of some mirror
// normal to axis k,
//     D_kj(x, s) = s_k (x_k - o_k) - s_j (x_j - o_j)
// is constant along a segment and changes by a multiple of G_kj =
// 2 gcd(g_k, g_j) at a reflection, g_k the gcd of the differences of the
// offsets of the mirrors normal to axis k.
struct LineInvariant {
    int dim = 0;
    lattice::Coords origin;                        // o_k
    std::array<std::array<Integer, 3>, 3> modulus; // G_kj
    std::array<std::array<Integer, 3>, 3> start;   // D_kj of the start state

    static int sign(unsigned mask, int axis) { return (mask >> axis) & 1u ? -1 : 1; }

    Integer value(const lattice::Coords& x, unsigned s, int k, int j) const {
        return sign(s, k) * (x[k] - origin[k]) - sign(s, j) * (x[j] - origin[j]);
    }

    // Whether D_kj of the state (x, s) is the start's (only x_k, x_j matter).
    bool holds(const lattice::Coords& x, unsigned s, int k, int j) const;

    // Whether the state (x, s) keeps every invariant of the start.
    bool holds(const lattice::Coords& x, unsigned s) const;

    // The class of x_j on the plane x_k = c that keeps D_kj in direction s:
    // s_j (x_j - o_j) = s_k (c - o_k) - D_kj(start) (mod G_kj).
    Integer residue(const Integer& c, int k, int j, unsigned s) const {
        return origin[j] + sign(s, j) * (sign(s, k) * (c - origin[k]) - start[k][j]);
    }

    // Positions x_j in [lo, hi] on the plane x_k = c that keep D_kj.
    Integer count(const Integer& c, int k, int j, const Integer& lo, const Integer& hi,
                  unsigned s) const {
        return count_congruent(lo, hi, residue(c, k, j, s), modulus[k][j]);
    }
};

LineInvariant line_invariant(const lattice::LatticeScene& scene);

} // namespace orthoray::bounds
