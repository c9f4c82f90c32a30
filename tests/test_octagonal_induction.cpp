// The induction engine on octagonal mazes (docs/induction.md, "Octagonal
// mazes"): closed forms of the diamond and the right isosceles triangle far
// beyond simulation, and agreement with the reference tracer on thousands
// of seeded random octagonal scenes.
#include "support/case_count.hpp"
#include "support/octagonal_families.hpp"
#include "support/portable_random.hpp"
#include "support/random_octagonal.hpp"

#include "orthoray/exchange.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/pieces.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

using namespace orthoray;

namespace {

Answer induce_scene(const Scene& scene) {
    SolveOptions o;
    o.engine = Engine::induction;
    return solve(scene, o);
}

using test::diamond;
using test::shoot;
using test::triangle;

} // namespace

TEST_CASE("diamond: a generic orbit closes after 2(|p| + |q|) reflections",
          "[octagonal][induction]") {
    // Rotating by 45 degrees, (p, q) = primitive (a + b, b - a), turns the
    // diamond into a square with axis-parallel walls, whose unfolding is a
    // torus of side 4n: the orbit closes after the displacement 4n (p, q),
    // which crosses 2|p| vertical and 2|q| horizontal walls. The start
    // (1/2, 1/2) is on no line through two corners of the unfolding.
    const Integer n("1000000000000000000");
    for (const Integer& m : {Integer("1000000000000000001"), Integer("999999999999999999999")}) {
        Scene s = diamond(n);
        shoot(s, Rational(1, 2), Rational(1, 2), 1,
              m); // m odd: (p, q) = ((m + 1) / 2, (m - 1) / 2)
        const Answer a = induce_scene(s);
        CHECK(a.engine == EngineUsed::induction);
        CHECK(a.reason == Reason::cycle);
        CHECK(a.reflections == 2 * m);
    }
    Scene s = diamond(n);
    shoot(s, Rational(1, 2), Rational(1, 2), 2, 3); // (5, 1)
    CHECK(induce_scene(s).reflections == 12);
}

TEST_CASE("diamond: axis and diagonal directions on the double cover", "[octagonal][induction]") {
    const Integer n("1000000000000000000");
    // Along (1, 0) from (x0, y0): (n - y0, y0), (n - y0, -y0), (-n + y0, -y0),
    // (-n + y0, y0) and back: the target (0, -y0) is on the third segment.
    Scene s = diamond(n);
    shoot(s, 5, 7, 1, 0);
    s.target() = {0, -7, 0};
    Answer a = induce_scene(s);
    CHECK(a.engine == EngineUsed::induction);
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 2);
    s.target() = {1, 2, 0};
    a = induce_scene(s);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 4);
    // Along (1, 1) the ray meets the walls x + y = +-n head on and goes back
    // and forth: period 2, half the period of its lift (the twin of x).
    shoot(s, 5, 7, 1, 1);
    a = induce_scene(s);
    CHECK(a.engine == EngineUsed::induction);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 2);
}

TEST_CASE("right isosceles triangle: 2|a| + 2|b| + |a + b| + |a - b| reflections",
          "[octagonal][induction]") {
    // The triangle tiles the plane by reflections in the lines x, y in nZ
    // and x +- y in 2nZ + n, with translations 2n Z^2: a generic orbit closes
    // after the displacement 2n (a, b), which crosses 2|a|, 2|b|, |a + b|
    // and |a - b| of those lines.
    const Integer n("1000000000000000000");
    for (const auto& [a, b] : {std::pair<Integer, Integer>{1, 2},
                               {3, 7},
                               {-5, 2},
                               {Integer(1), Integer("3000000000000000001")}}) {
        Scene s = triangle(n);
        shoot(s, Rational(1, 3), Rational(1, 7), a, b);
        const Answer answer = induce_scene(s);
        INFO("direction " << a << " " << b);
        CHECK(answer.engine == EngineUsed::induction);
        CHECK(answer.reason == Reason::cycle);
        CHECK(answer.reflections ==
              2 * abs(a) + 2 * abs(b) + Integer(abs(a + b)) + Integer(abs(a - b)));
    }
}

TEST_CASE("induction agrees with the reference tracer on random octagonal trajectories",
          "[octagonal][induction][property][slow]") {
    // Answer, reason, reflections and tail. Scenes whose step map is not
    // one to one (a ray sliding along a diagonal into a vertex) are decided
    // by the walk between special states (rho_walk.hpp), tails included;
    // any scene the induction does not take goes to the reference tracer,
    // and must say so.
    std::mt19937_64 rng(14'301);
    test::RandomOctagonalShape shape;
    const int cases = test::case_count(7500);
    int scenes = 0, induced = 0, cycles = 0, hits = 0, escapes = 0, absorbed = 0;
    int walked = 0, tails = 0; // induced without an exchange (of a third); cycles after a tail
    SolveOptions reference;
    reference.engine = Engine::reference;
    reference.max_steps = 200'000;
    for (int i = 0; i < cases; ++i) {
        shape.max_elements = 2 + i % 10;
        shape.box = 3 + i % 5;
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.single_trajectory() || !s.has_diagonal()) continue;
        ++scenes;
        INFO("case " << i << "\n" << write_scene(s));
        const Answer want = solve(s, reference);
        REQUIRE(want.decided());
        const Answer got = induce_scene(s);
        if (i % 10 == 0) { // GMP throughout, as on huge scenes
            SolveOptions wide;
            wide.engine = Engine::induction;
            wide.arithmetic = Arithmetic::wide;
            const Answer on_gmp = solve(s, wide);
            CHECK(on_gmp.reason == want.reason);
            CHECK(on_gmp.reflections == want.reflections);
        }
        CHECK(got.reason == want.reason);
        CHECK(got.reflections == want.reflections);
        CHECK(got.tail == want.tail);
        if (got.engine != EngineUsed::induction) {
            CHECK(got.engine == EngineUsed::reference);
            continue;
        }
        ++induced;
        // Only a walk finds a tail (a bijection's orbits are cycles); one
        // scene in three is asked whether it had an exchange at all.
        if (got.reason == Reason::cycle && got.tail > 0) ++tails;
        if (i % 3 == 0 && !exchange_of(s)) ++walked;
        switch (got.reason) {
        case Reason::hit:
            ++hits;
            break;
        case Reason::escape:
            ++escapes;
            break;
        case Reason::absorbed:
            ++absorbed;
            break;
        default:
            ++cycles;
        }
    }
    // Every scene is decided by induction, those without a bijective
    // exchange (or without a reflection) by the walk, and every outcome is
    // common: 5,000 induced in all, a few dozen cycles after a tail.
    WARN("induced " << induced << " of " << scenes << ", " << walked
                    << " of a third without an exchange, " << tails << " cycles after a tail");
    CHECK(induced == scenes);
    CHECK(walked > cases / 30);
    CHECK(tails > cases / 400);
    CHECK(induced >= cases * 2 / 3);
    CHECK(hits > cases / 20);
    CHECK(escapes > cases / 50);
    CHECK(absorbed > cases / 50);
    CHECK(cycles > cases / 20);
}

TEST_CASE("a 45-degree billiard with a ray sliding into the wall: tail and period as traced",
          "[octagonal][induction]") {
    // The box [0, w] x [0, h] with a diagonal mirror of length sqrt(2)
    // leaving the bottom wall at (x0, 0), and a ray along (1, 1). A ray
    // sliding down the mirror's line meets the wall alone at (x0, 0), one
    // arriving there along (1, -1) is sent back: both leave along (-1, 1).
    // The orbits run hundreds of reflections, some after a tail; the walk
    // between the collisions must find the reference tracer's tail and
    // period exactly.
    std::mt19937_64 rng(14'304);
    const int cases = test::case_count(120);
    int tails = 0;
    for (int i = 0; i < cases; ++i) {
        const int w = test::pick(rng, 50, 400), h = test::pick(rng, 50, 400);
        const int x0 = test::pick(rng, 1, w - 2);
        const int x = test::pick(rng, 1, w - 1), y = test::pick(rng, 1, h - 1);
        const Scene s = test::slide_box(w, h, x0, x, y, {Rational(2 * w), 0, 0});
        INFO("case " << i << "\n" << write_scene(s));
        SolveOptions reference;
        reference.engine = Engine::reference;
        const Answer want = solve(s, reference), got = induce_scene(s);
        CHECK(got.engine == EngineUsed::induction);
        CHECK(got.reason == want.reason);
        CHECK(got.reflections == want.reflections);
        CHECK(got.tail == want.tail);
        if (want.tail > 0) ++tails;
    }
    CHECK(tails > cases / 20);
}

TEST_CASE("the octagonal exchange is a bijection of its states", "[octagonal][induction]") {
    // exchange_of on the cover: the domains and the images tile [0, N), and
    // inducing it alone gives the solver's answer for escapes, absorptions
    // and hits (a cycle's period may be twice the physical one there).
    std::mt19937_64 rng(14'302);
    test::RandomOctagonalShape shape;
    const int cases = test::case_count(400);
    int checked = 0;
    for (int i = 0; i < cases; ++i) {
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.single_trajectory() || !s.has_diagonal() || s.has_one_sided()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const auto exchange = exchange_of(s);
        if (!exchange) continue;
        std::vector<std::pair<Integer, Integer>> domains, images;
        for (const ExchangePiece& p : exchange->pieces) {
            domains.emplace_back(p.start, p.length);
            images.emplace_back(p.image, p.length);
        }
        std::sort(images.begin(), images.end());
        Integer at = 0, image_at = 0;
        for (std::size_t j = 0; j < domains.size(); ++j) {
            REQUIRE(domains[j].first == at);
            REQUIRE(images[j].first == image_at);
            at += domains[j].second;
            image_at += images[j].second;
        }
        CHECK(at == exchange->size);
        CHECK(image_at == exchange->size);
        const InducedOrbit orbit = induce(*exchange);
        const Answer a = induce_scene(s);
        if (orbit.event != ExchangeEvent::none && a.reflections > 0)
            CHECK(a.reflections == orbit.offset + 1);
        ++checked;
    }
    CHECK(checked > cases / 4);
}

TEST_CASE("a stretch of mirror under an absorber carries no states of the octagonal exchange",
          "[octagonal][induction]") {
    // A ray that meets a mirror and an absorber at one point is absorbed, so
    // no state leaves from there: the wall x = 20 under the absorber is the
    // same as a wall cut around it. Counting that stretch's mirror alone (a
    // mutant of the builder's line cutting did) adds states and pieces that
    // nothing maps onto, and changes no answer: only the exchange shows it.
    const std::string box = "dim 2\nmirror x 0 y 0 20\nmirror y 0 x 0 20\nmirror y 20 x 0 20\n"
                            "mirror / 7 7 11 11\nabsorber x 20 y 12 14\nray 6 5 -1 -3\n"
                            "target 19 1/3\n";
    const Scene covered = read_scene(box + "mirror x 20 y 0 20\n");
    const Scene cut = read_scene(box + "mirror x 20 y 0 12\nmirror x 20 y 14 20\n");
    const auto a = exchange_of(covered), b = exchange_of(cut);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->size == b->size);
    CHECK(a->pieces.size() == b->pieces.size());
    std::ostringstream text_a, text_b;
    write_exchange(*a, text_a, ExchangeFormat::json);
    write_exchange(*b, text_b, ExchangeFormat::json);
    CHECK(text_a.str() == text_b.str());
    const Answer answer = induce_scene(covered);
    CHECK(answer.reason == Reason::cycle);
    CHECK(answer.reflections == 8);
}

TEST_CASE("octagonal induction answers a scene scaled by 10^17 or 10^40 as the scene itself",
          "[octagonal][induction]") {
    // Motion commutes with homotheties: the same answer on 128-bit and on
    // GMP integers, far from the small numbers of the random scenes.
    std::mt19937_64 rng(14'303);
    test::RandomOctagonalShape shape;
    const int cases = test::case_count(400);
    int compared = 0;
    for (int i = 0; i < cases; ++i) {
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.single_trajectory() || !s.has_diagonal()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const Answer small = induce_scene(s);
        for (const char* factor :
             {"100000000000000003", "10000000000000000000000000000000000000007"}) {
            const Rational f{Integer(factor)};
            Scene big = s;
            for (Element& e : big.elements)
                for (int j = 0; j < 2; ++j) {
                    e.lo[j] *= f;
                    e.hi[j] *= f;
                }
            for (int j = 0; j < 2; ++j) {
                big.ray().start[j] = big.ray().start[j] * f + 7; // and translated
                big.target()[j] = big.target()[j] * f + 7;
            }
            for (Element& e : big.elements)
                for (int j = 0; j < 2; ++j) {
                    e.lo[j] += 7;
                    e.hi[j] += 7;
                }
            const Answer a = induce_scene(big);
            CHECK(a.reason == small.reason);
            CHECK(a.reflections == small.reflections);
            CHECK(a.tail == small.tail);
            CHECK(a.engine == small.engine);
        }
        ++compared;
    }
    CHECK(compared > cases / 2);
}

TEST_CASE("the piece tables of a diagonal scene are the cover's first-return map",
          "[octagonal][induction]") {
    // `orthoray pieces`: one line a transversal and a piece, as many pieces
    // as the exchange has before x and the marks are cut out.
    Scene s = diamond(5);
    shoot(s, 0, 0, 1, 2);
    std::ostringstream out;
    const PieceTableSummary summary = write_piece_tables(s, out);
    CHECK(summary.available);
    CHECK(summary.pieces > 0);
    const std::string text = out.str();
    std::size_t pieces = 0;
    for (std::size_t at = text.find("\npiece "); at != std::string::npos;
         at = text.find("\npiece ", at + 1))
        ++pieces;
    CHECK(pieces == summary.pieces);
    CHECK(text.find("sheet") != std::string::npos);
    CHECK(exchange_of(s)->pieces.size() >= summary.pieces);
}

TEST_CASE("the default engine simulates a short octagonal orbit and induces a long one",
          "[octagonal][induction]") {
    // The diamond of side 10^18 with direction (1, m), m odd: period 2m
    // (the closed form above). m = 5 closes after 10 reflections, within the
    // simulation's budget; m = 10^18 + 1 would take 2 * 10^18 reflections,
    // so the default engine must hand it to the induction.
    const Integer n("1000000000000000000");
    Scene s = diamond(n);
    shoot(s, Rational(1, 2), Rational(1, 2), 1, 5);
    Answer a = solve(s);
    CHECK(a.engine == EngineUsed::lattice);
    CHECK(a.reflections == 10);
    const Integer m("1000000000000000001");
    shoot(s, Rational(1, 2), Rational(1, 2), 1, m);
    a = solve(s);
    CHECK(a.engine == EngineUsed::induction);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 2 * m);
    // With a cap within the budget it only simulates.
    SolveOptions capped;
    capped.max_steps = 1000;
    a = solve(s, capped);
    CHECK(a.engine == EngineUsed::lattice);
    CHECK(a.reason == Reason::limit);
    CHECK(a.reflections == 1000);
}

TEST_CASE("induction honours --max-steps where the octagonal simulation would stop",
          "[octagonal][induction]") {
    // Period 2 * 8501 = 17002: Brent's detector, which every simulation of
    // a diagonal scene runs, sees it at reflection 2^15 + 17002 = 49770.
    Scene s = diamond(Integer(1000));
    shoot(s, Rational(1, 2), Rational(1, 2), 1, 8501);
    for (const std::uint64_t cap : {20000u, 49769u, 49770u, 60000u}) {
        INFO("cap " << cap);
        SolveOptions induced, simulated;
        induced.engine = Engine::induction;
        simulated.engine = Engine::lattice;
        induced.max_steps = simulated.max_steps = cap;
        const Answer a = solve(s, induced), b = solve(s, simulated);
        CHECK(a.reason == b.reason);
        CHECK(a.reflections == b.reflections);
        CHECK(a.reason == (cap >= 49770 ? Reason::cycle : Reason::limit));
    }
}
