// The `box`, `coprime-box` and `coprime-cuboid` families: a closed mirror
// box, by default shot from the corner 0 along (1, ..., 1), where billiards
// in a rectangle give the answer in closed form (docs/generate.md).
#include "generate/box_faces.hpp"
#include "orthoray/generate.hpp"

#include <stdexcept>

namespace orthoray {
namespace {

Integer lcm(const Integer& a, const Integer& b) {
    Integer r;
    mpz_lcm(r.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return r;
}

// The 45-degree ray from the corner 0 of the box with sides a_j, unfolded by
// reflecting the box across its walls, is the line t (1, ..., 1). It crosses
// a wall x_j = (multiple of a_j) at every t that some a_j divides, and one
// such t is one reflection however many walls meet there (an edge or a corner
// reflects once, negating every component it meets). It first meets a point
// where every coordinate is a wall, a corner, at T = lcm(a_j); so the
// reflections before that corner are the t in (0, T) some a_j divides,
// counted by inclusion-exclusion:
//     sum_j (T / a_j - 1) - sum_{i<j} (T / lcm(a_i, a_j) - 1)
// (the triple term T / T - 1 is 0). Folded back, coordinate j of that corner
// is a_j when T / a_j is odd (an odd number of walls crossed) and 0 otherwise.
struct CornerOrbit {
    Integer reflections;
    Vector corner;
};

CornerOrbit corner_orbit(const std::vector<Integer>& sides) {
    Integer T = 1;
    for (const Integer& a : sides) T = lcm(T, a);
    CornerOrbit orbit;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        orbit.reflections += T / sides[i] - 1;
        for (std::size_t j = i + 1; j < sides.size(); ++j)
            orbit.reflections -= T / lcm(sides[i], sides[j]) - 1;
        const bool odd = Integer(T / sides[i]) % 2 != 0;
        orbit.corner[i] = odd ? Rational(sides[i]) : Rational(0);
    }
    return orbit;
}

const char* target_name(BoxFamily::Target target) {
    switch (target) {
    case BoxFamily::Target::reached:
        return "the corner the ray reaches";
    case BoxFamily::Target::far:
        return "the corner opposite the start";
    case BoxFamily::Target::generic:
        return "a point on no line x +- y = integer";
    case BoxFamily::Target::point:
        return "a given point";
    }
    return "";
}

} // namespace

GeneratedScene generate_box(const BoxFamily& f) {
    const int dim = static_cast<int>(f.sides.size());
    if (dim != 2 && dim != 3)
        throw std::invalid_argument("found " + std::to_string(dim) +
                                    " sides for a box, expected 2 or 3");
    for (const Integer& a : f.sides)
        if (a < 1)
            throw std::invalid_argument("found the side " + a.get_str() +
                                        ", expected a positive integer");
    GeneratedScene out;
    Scene& scene = out.scene;
    scene.dim = dim;
    std::vector<Rational> sides(f.sides.begin(), f.sides.end());
    generate::add_box_faces(scene, sides);
    if (f.direction && (*f.direction)[0] == 0 && (*f.direction)[1] == 0 && (*f.direction)[2] == 0)
        throw std::invalid_argument("found the direction 0, expected a nonzero vector");
    const bool from_corner = !f.start && !f.direction;
    for (int j = 0; j < dim; ++j) {
        scene.ray().start[j] = f.start ? (*f.start)[j] : Rational(0);
        scene.ray().direction[j] = f.direction ? (*f.direction)[j] : Rational(1);
    }
    const CornerOrbit orbit = corner_orbit(f.sides);
    switch (f.target) {
    case BoxFamily::Target::reached:
        scene.target() = orbit.corner;
        break;
    case BoxFamily::Target::far:
        for (int j = 0; j < dim; ++j) scene.target()[j] = sides[static_cast<std::size_t>(j)];
        break;
    case BoxFamily::Target::generic:
        scene.target() = Vector{Rational(1, 2), Rational(1, 3), dim == 3 ? Rational(1, 5) : 0};
        break;
    case BoxFamily::Target::point:
        scene.target() = f.target_point;
        break;
    }
    if (!from_corner && f.target == BoxFamily::Target::reached) {
        // The closed form is for the 45-degree ray from the corner 0; this
        // ray may reach that corner or none (run solve to know).
        out.notes.push_back("box; target: the corner the 45-degree ray from the corner 0 "
                            "reaches; this ray starts or moves otherwise, so it is not known to "
                            "reach it");
        return out;
    }
    out.notes.push_back(std::string("box; target: ") + target_name(f.target));
    if (!from_corner || f.target == BoxFamily::Target::point) return out;

    // From the reached corner every component flips and the ray retraces its
    // path to 0, where it flips again: a cycle through the N + 1 reflections
    // out and the N + 1 back, passing no other corner and no point off the
    // lines x +- y = integer.
    if (scene.target() == orbit.corner) {
        out.expect = Expectation{Reason::hit, orbit.reflections};
        out.notes.push_back("closed form: the corner is reached after N reflections, N = "
                            "sum (T/a_j - 1) - sum (T/lcm(a_i, a_j) - 1), T = lcm of the sides");
    } else {
        out.expect = Expectation{Reason::cycle, 2 * (orbit.reflections + 1)};
        out.notes.push_back("closed form: a cycle of period 2 (N + 1), N = sum (T/a_j - 1) - "
                            "sum (T/lcm(a_i, a_j) - 1), T = lcm of the sides");
    }
    return out;
}

GeneratedScene generate_coprime_box(unsigned k, BoxFamily::Target target) {
    if (k < 1 || k > 4096)
        throw std::invalid_argument("found k = " + std::to_string(k) +
                                    ", expected a whole number from 1 to 4096");
    BoxFamily f;
    const Integer two_k = Integer(1) << k;
    f.sides = {two_k + 1, two_k};
    f.target = target;
    GeneratedScene out = generate_box(f);
    out.notes.insert(out.notes.begin(), "coprime-box k = " + std::to_string(k) +
                                            ": sides 2^k + 1 and 2^k are coprime, so the ray "
                                            "meets a corner only after 2^(k+1) - 1 reflections");
    return out;
}

GeneratedScene generate_coprime_cuboid(unsigned k, BoxFamily::Target target) {
    if (k < 2 || k > 4096)
        throw std::invalid_argument("found k = " + std::to_string(k) +
                                    ", expected a whole number from 2 to 4096");
    BoxFamily f;
    const Integer two_k = Integer(1) << k;
    f.sides = {two_k + 1, two_k, two_k - 1};
    f.target = target;
    GeneratedScene out = generate_box(f);
    out.notes.insert(out.notes.begin(),
                     "coprime-cuboid k = " + std::to_string(k) +
                         ": sides 2^k + 1, 2^k, 2^k - 1 are pairwise coprime, so the ray meets a "
                         "corner only after T = 2^k (4^k - 1) and about 3 * 4^k edge or wall "
                         "reflections");
    return out;
}

} // namespace orthoray
