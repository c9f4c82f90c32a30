#include "bounds/line_invariant.hpp"

#include "lattice/lattice_int.hpp" // floor_div, floor_mod

namespace orthoray::bounds {
namespace {

using lattice::floor_div;
using lattice::floor_mod;

bool congruent(const Integer& a, const Integer& b, const Integer& G) {
    return G == 0 ? a == b : Integer((a - b) % G) == 0;
}

} // namespace

Integer count_congruent(const Integer& lo, const Integer& hi, const Integer& r, const Integer& G) {
    if (hi < lo) return 0;
    if (G == 0) return lo <= r && r <= hi ? 1 : 0;
    return floor_div(hi - r, G) - floor_div(lo - 1 - r, G);
}

Integer count_congruent_both(const Integer& lo, const Integer& hi, const Integer& r1,
                             const Integer& G1, const Integer& r2, const Integer& G2) {
    if (G1 == 0) return congruent(r1, r2, G2) ? count_congruent(lo, hi, r1, 0) : Integer(0);
    if (G2 == 0) return congruent(r2, r1, G1) ? count_congruent(lo, hi, r2, 0) : Integer(0);
    // x = r1 + G1 t with G1 t = r2 - r1 (mod G2): solvable iff g = gcd(G1, G2)
    // divides r2 - r1, and then t = (r2 - r1)/g * (G1/g)^-1 (mod G2/g), one
    // class modulo lcm(G1, G2) = G1 G2 / g.
    const Integer g = gcd(G1, G2), d = r2 - r1;
    if (Integer(d % g) != 0) return 0;
    const Integer m = G2 / g, a = G1 / g;
    Integer inverse = 0, t = 0;
    if (m != 1) {
        mpz_invert(inverse.get_mpz_t(), a.get_mpz_t(), m.get_mpz_t());
        t = floor_mod(Integer(d / g) * inverse, m);
    }
    return count_congruent(lo, hi, r1 + G1 * t, G1 * m);
}

bool LineInvariant::holds(const lattice::Coords& x, unsigned s, int k, int j) const {
    return congruent(value(x, s, k, j), start[k][j], modulus[k][j]);
}

bool LineInvariant::holds(const lattice::Coords& x, unsigned s) const {
    for (int k = 0; k < dim; ++k)
        for (int j = k + 1; j < dim; ++j)
            if (!holds(x, s, k, j)) return false;
    return true;
}

LineInvariant line_invariant(const lattice::LatticeScene& ls) {
    LineInvariant inv;
    inv.dim = ls.dim;
    std::array<bool, 3> seen{};
    std::array<Integer, 3> g;
    for (const lattice::LatticeElement& e : ls.elements) {
        if (e.absorber) continue; // absorbers do not reflect: they change no invariant
        const Integer& c = e.lo[e.axis];
        if (!seen[e.axis]) {
            seen[e.axis] = true;
            inv.origin[e.axis] = c;
        }
        g[e.axis] = gcd(g[e.axis], c - inv.origin[e.axis]);
    }
    for (int k = 0; k < ls.dim; ++k)
        for (int j = 0; j < ls.dim; ++j)
            if (j != k) {
                inv.modulus[k][j] = 2 * gcd(g[k], g[j]);
                inv.start[k][j] = inv.value(ls.start, ls.start_direction, k, j);
            }
    return inv;
}

} // namespace orthoray::bounds
