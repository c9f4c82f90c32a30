// Closed forms from billiards in a rectangle, checked on many sizes,
// including sizes far beyond 64 bits where the answer still comes quickly.
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;

namespace {

// The closed mirror box [0, m] x [0, n].
Scene box(const Integer& m, const Integer& n) {
    Scene s;
    s.dim = 2;
    s.add_mirror(0, 0, {{0, n}});
    s.add_mirror(0, m, {{0, n}});
    s.add_mirror(1, 0, {{0, m}});
    s.add_mirror(1, n, {{0, m}});
    return s;
}

Answer solve_with(const Scene& s, Engine engine = Engine::lattice,
                  Arithmetic arithmetic = Arithmetic::automatic) {
    SolveOptions o;
    o.engine = engine;
    o.arithmetic = arithmetic;
    return solve(s, o);
}

Integer gcd(const Integer& a, const Integer& b) {
    Integer g;
    mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return g;
}

// Unfolded, the 45-degree ray from (0,0) is the diagonal; it first meets a
// lattice point of the box's reflection lattice mZ x nZ at (l, l), l =
// lcm(m, n), having crossed l/m - 1 vertical and l/n - 1 horizontal walls in
// between: m/g + n/g - 2 reflections. The corner it lands on is x = m when
// l/m = n/g is odd (else 0), y = n when m/g is odd (else 0). There it
// reverses and retraces its path to (0,0), so the other two corners are never
// reached: a cycle of period 2 (m/g + n/g - 1).
void check_box_corner(const Integer& m, const Integer& n, Arithmetic arithmetic) {
    INFO("m = " << m << ", n = " << n);
    const Integer g = gcd(m, n);
    const Integer k = m / g + n / g - 2;
    const bool x_far = Integer(n / g) % 2 != 0, y_far = Integer(m / g) % 2 != 0;
    Scene s = box(m, n);
    s.ray().start = {0, 0, 0};
    s.ray().direction = {1, 1, 0};
    s.target() = {x_far ? m : Integer(0), y_far ? n : Integer(0), 0};
    Answer a = solve_with(s, Engine::lattice, arithmetic);
    REQUIRE(a.reason == Reason::hit);
    REQUIRE(a.reflections == k);

    // The two corners other than the start and the one reached: never reached.
    for (const Integer& x : {Integer(0), m})
        for (const Integer& y : {Integer(0), n}) {
            if ((x == 0 && y == 0) || ((x == m) == x_far && (y == n) == y_far)) continue;
            s.target() = {x, y, 0};
            a = solve_with(s, Engine::lattice, arithmetic);
            REQUIRE(a.reason == Reason::cycle);
            REQUIRE(a.reflections == 2 * (k + 1));
        }
}

} // namespace

TEST_CASE("45-degree corner shot in an m x n box", "[closed-form]") {
    for (int m = 1; m <= 40; ++m)
        for (int n = 1; n <= 40; ++n) check_box_corner(m, n, Arithmetic::automatic);
    for (int m = 1; m <= 12; ++m)
        for (int n = 1; n <= 12; ++n) check_box_corner(m, n, Arithmetic::wide);
}

TEST_CASE("corner shot in boxes beyond 64 bits", "[closed-form][big]") {
    const Integer big = Integer(1) << 100;
    for (int a = 1; a <= 9; ++a)
        for (int b = 1; b <= 9; ++b) {
            check_box_corner(a * big, b * big, Arithmetic::automatic);
            check_box_corner(a * big + a, b * big + b, Arithmetic::automatic); // g = big + 1
        }
    Scene s = box(3 * big, 5 * big);
    s.ray().direction = {1, 1, 0};
    s.target() = {3 * big, 5 * big, 0};
    CHECK(solve_with(s).arithmetic == ArithmeticUsed::int128); // 5 * 2^100 < 2^123
    CHECK(solve_with(box(3, 5)).arithmetic == ArithmeticUsed::int64);
    const Integer huge = Integer(1) << 130;
    for (int a = 1; a <= 5; ++a)
        for (int b = 1; b <= 5; ++b) check_box_corner(a * huge, b * huge, Arithmetic::automatic);
    s = box(3 * huge, 5 * huge);
    s.ray().direction = {1, 1, 0};
    s.target() = {3 * huge, 5 * huge, 0};
    CHECK(solve_with(s).arithmetic == ArithmeticUsed::gmp);
}

TEST_CASE("the reference tracer agrees with the closed form", "[closed-form]") {
    for (int m = 1; m <= 9; ++m)
        for (int n = 1; n <= 9; ++n) {
            Integer g = gcd(m, n), k = m / g + n / g - 2;
            Scene s = box(m, n);
            s.ray().direction = {1, 1, 0};
            s.target() = {Integer(n / g) % 2 != 0 ? m : 0, Integer(m / g) % 2 != 0 ? n : 0, 0};
            Answer a = solve_with(s, Engine::reference);
            REQUIRE(a.reason == Reason::hit);
            REQUIRE(a.reflections == k);
        }
}

// In the unit square, unfolding turns the ray into a line of slope q/p on the
// torus R^2 / 2Z^2; it closes after time 2 (least, as gcd(p, q) = 1),
// crossing 2p vertical and 2q horizontal walls: period 2(p + q). The start is
// generic when q x0 - p y0 is not an integer: then the line misses every
// corner, so a corner target is never reached.
TEST_CASE("rational slope in the unit square has period 2(p + q)", "[closed-form]") {
    for (const Integer& side : {Integer(1), Integer(Integer(1) << 80)}) {
        for (int p = 1; p <= 25; ++p)
            for (int q = 0; q <= 25; ++q) {
                if (gcd(p, q) != 1) continue;
                INFO("side " << side << ", direction (" << p << ", " << q << ")");
                Scene s = box(side, side);
                Rational x0(1, 3), y0(2, 7);
                if (Rational(q * x0 - p * y0).get_den() == 1) y0 = Rational(3, 11);
                s.ray().start = {x0 * side, y0 * side, 0};
                s.ray().direction = {p, q, 0};
                s.target() = {0, 0, 0};
                const Answer a = solve_with(s);
                REQUIRE(a.reason == Reason::cycle);
                REQUIRE(a.reflections == 2 * (p + q));
                // Negated components are the same billiard run backwards.
                s.ray().direction = {-p, -q, 0};
                REQUIRE(solve_with(s).reflections == 2 * (p + q));
            }
    }
}

// A 3D corner shot in an a x b x c box: unfolded, the ray (t, t, t) first
// meets a corner of the lattice aZ x bZ x cZ at t = l = lcm(a, b, c), and
// before that reflects once at each t in (0, l) that is a multiple of a, b or
// c (an edge or a vertex, crossed at one t, is one reflection). With
// pairwise coprime sides that count is ab + bc + ca - a - b - c.
TEST_CASE("3D corner shot in a box", "[closed-form]") {
    const int sides[][3] = {{1, 2, 3}, {2, 3, 5}, {3, 4, 5}, {5, 7, 9}, {2, 4, 6}, {4, 6, 9}};
    for (const auto& d : sides) {
        Scene s;
        s.dim = 3;
        for (int axis = 0; axis < 3; ++axis) {
            std::vector<std::pair<Rational, Rational>> extent;
            for (int j = 0; j < 3; ++j)
                if (j != axis) extent.push_back({0, d[j]});
            s.add_mirror(axis, 0, extent);
            s.add_mirror(axis, d[axis], extent);
        }
        s.ray().direction = {1, 1, 1};
        int l = 1;
        while (l % d[0] || l % d[1] || l % d[2]) ++l;
        int reflections = 0;
        for (int t = 1; t < l; ++t) reflections += t % d[0] == 0 || t % d[1] == 0 || t % d[2] == 0;
        bool coprime = gcd(d[0], d[1]) == 1 && gcd(d[1], d[2]) == 1 && gcd(d[0], d[2]) == 1;
        if (coprime)
            CHECK(reflections == d[0] * d[1] + d[1] * d[2] + d[2] * d[0] - d[0] - d[1] - d[2]);
        for (int j = 0; j < 3; ++j) s.target()[j] = (l / d[j]) % 2 ? d[j] : 0;
        Answer a = solve_with(s);
        INFO(d[0] << " x " << d[1] << " x " << d[2]);
        REQUIRE(a.reason == Reason::hit);
        REQUIRE(a.reflections == reflections);
        REQUIRE(solve_with(s, Engine::reference).reflections == reflections);
    }
}
