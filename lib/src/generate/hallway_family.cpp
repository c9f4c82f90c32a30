// The `hallway` family: two long parallel mirrors and a ray of small slope.
#include "orthoray/generate.hpp"

#include <stdexcept>

namespace orthoray {

// Unfolded across the mirrors y = 0 and y = 1 the ray from (0, 1/2) with
// slope s is the line Y = 1/2 + s x, and it reflects once for every integer
// Y = 1, 2, ... it reaches while x is in (0, length] (the mirrors are closed,
// so x = length still reflects): N = floor(1/2 + s * length) reflections,
// growing linearly with the length. Past the end nothing is met, so the ray
// goes on in its last direction: folded, y = Y - N when N is even and
// N + 1 - Y when N is odd, and the target is that point at x = length + 1.
GeneratedScene generate_hallway(const Rational& length, const Rational& slope) {
    if (length <= 0)
        throw std::invalid_argument("found the length " + length.get_str() +
                                    ", expected a number above 0");
    if (slope <= 0)
        throw std::invalid_argument("found the slope " + slope.get_str() +
                                    ", expected a number above 0");
    GeneratedScene out;
    Scene& scene = out.scene;
    scene.dim = 2;
    scene.add_mirror(1, 0, {{0, length}});
    scene.add_mirror(1, 1, {{0, length}});
    scene.ray().start = Vector{0, Rational(1, 2), 0};
    scene.ray().direction = Vector{Rational(slope.get_den()), Rational(slope.get_num()), 0};
    const Rational top = Rational(1, 2) + slope * length;
    Integer n;
    mpz_fdiv_q(n.get_mpz_t(), top.get_num_mpz_t(), top.get_den_mpz_t());
    const Rational x = length + 1, y_unfolded = Rational(1, 2) + slope * x;
    const bool even = Integer(n % 2) == 0;
    scene.target() = Vector{x, even ? Rational(y_unfolded - n) : Rational(n + 1 - y_unfolded), 0};
    scene.target()[1].canonicalize();
    out.expect = Expectation{Reason::hit, n};
    out.notes.push_back("hallway: mirrors y = 0 and y = 1 for x in [0, " + to_string(length) +
                        "], slope " + to_string(slope) + " from (0, 1/2)");
    out.notes.push_back("closed form: floor(1/2 + slope * length) = " + n.get_str() +
                        " reflections, then the target on the final ray at x = length + 1");
    return out;
}

} // namespace orthoray
