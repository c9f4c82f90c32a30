// The `square` family: billiards in the unit square with a generic start.
#include "generate/box_faces.hpp"
#include "orthoray/generate.hpp"

#include <stdexcept>

namespace orthoray {

// Unfolded across its walls the square becomes the grid of unit cells and the
// trajectory the line q (x - x0) = p (y - y0). The ray meets a corner iff the
// line passes an integer point (a, b), iff q a - p b = q x0 - p y0; with
// x0 = 1/2, y0 = 1/2 + 1/(4|p| + 1) the right side is (q - p)/2 - p/(4|p| + 1),
// within (0, 1/4) of a multiple of 1/2, never an integer: no corner, ever.
// A state repeats when the unfolded point has moved by an even vector (2a, 2b)
// (an even number of walls crossed on each axis restores both the position
// and the direction), first after t (p', q') = (2p', 2q') with p' = |p|/g,
// q' = |q|/g, g = gcd(p, q): 2p' vertical and 2q' horizontal walls, a period
// of 2 (p' + q') reflections. A folded point (x, y) is on the trajectory iff
// q' (+-x - x0) - p' (+-y - y0) is an even integer for some signs; the
// target (1/2, 1/P), P a prime above 2 (4|p| + 1), puts P in the denominator
// of that sum (P divides neither p' nor any other denominator), so never.
GeneratedScene generate_square(const Integer& p, const Integer& q) {
    if (p == 0 || q == 0)
        throw std::invalid_argument("found the direction (" + p.get_str() + ", " + q.get_str() +
                                    "), expected nonzero components p and q");
    GeneratedScene out;
    Scene& scene = out.scene;
    scene.dim = 2;
    generate::add_box_faces(scene, {Rational(1), Rational(1)});
    const Integer abs_p = abs(p);
    scene.ray().start =
        Vector{Rational(1, 2), Rational(1, 2) + Rational(1, Integer(4 * abs_p + 1)), 0};
    scene.ray().start[1].canonicalize();
    scene.ray().direction = Vector{Rational(p), Rational(q), 0};
    Integer prime;
    const Integer above = 2 * (4 * abs_p + 1);
    mpz_nextprime(prime.get_mpz_t(), above.get_mpz_t());
    scene.target() = Vector{Rational(1, 2), Rational(1, prime), 0};
    Integer g;
    mpz_gcd(g.get_mpz_t(), p.get_mpz_t(), q.get_mpz_t());
    const Integer period = 2 * (abs_p / g + abs(q) / g);
    out.expect = Expectation{Reason::cycle, period};
    out.notes.push_back("square: the unit square, direction (p, q) = (" + p.get_str() + ", " +
                        q.get_str() + "), a start whose line avoids every corner");
    out.notes.push_back("closed form: a cycle of period 2 (p + q) / gcd(p, q) = " +
                        period.get_str() + "; the target is on no unfolded copy of the line");
    return out;
}

} // namespace orthoray
