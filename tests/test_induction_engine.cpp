// The induction engine against simulation: the same answer, reason and
// reflection count on thousands of random 2D scenes and on every family
// with a closed form, and far beyond what simulation can reach.
#include "support/case_count.hpp"
#include "support/random_scene.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace orthoray;

namespace {

std::string summary(const Answer& a) {
    return std::string(to_string(a.reason)) + " " + a.reflections.get_str();
}

Answer solve_with(const Scene& scene, Engine engine, Arithmetic arithmetic = Arithmetic::automatic,
                  std::optional<std::uint64_t> cap = std::nullopt) {
    SolveOptions o;
    o.engine = engine;
    o.arithmetic = arithmetic;
    o.max_steps = cap;
    return solve(scene, o);
}

struct Tally {
    int scenes = 0, induced = 0, referenced = 0; // referenced: the reference decided too
    int capped = 0;                              // also decided under two caps
    int by_reason[5] = {};
};

// Simulation decides the scene within a generous cap (random scenes are
// small); induction must give the same answer, on every integer path.
void check_scene(const Scene& scene, Tally& tally) {
    INFO("scene:\n" << write_scene(scene));
    const Answer simulated = solve_with(scene, Engine::lattice, Arithmetic::automatic, 1'000'000);
    REQUIRE(simulated.decided());
    const Answer reference = solve_with(scene, Engine::reference, Arithmetic::automatic, 5'000);
    if (reference.decided()) REQUIRE(summary(reference) == summary(simulated));
    const Answer induced = solve_with(scene, Engine::induction);
    REQUIRE(summary(induced) == summary(simulated));
    for (Arithmetic wider : {Arithmetic::int128, Arithmetic::wide})
        REQUIRE(summary(solve_with(scene, Engine::induction, wider)) == summary(simulated));
    // The default engine too, with the tables (and so the induction) at once.
    SolveOptions o;
    o.shooter = Shooter::pieces;
    REQUIRE(summary(solve(scene, o)) == summary(simulated));
    ++tally.scenes;
    if (induced.engine != EngineUsed::induction) return;
    ++tally.induced;
    // A cap one below what the answer needs, and one at it: the limit the
    // simulation reaches there, told by the induction without stepping to
    // it (so with the induction's name), and then the answer. (A cap of 1
    // is met on the grid, at the first reflection, before the induction.)
    const std::uint64_t needed =
        simulated.reflections.get_ui() + (simulated.reason == Reason::cycle ? 1 : 0);
    if (tally.induced % 4 == 0 && needed >= 3) {
        for (const std::uint64_t cap : {needed - 1, needed}) {
            const Answer capped = solve_with(scene, Engine::induction, Arithmetic::automatic, cap);
            REQUIRE(summary(capped) ==
                    summary(solve_with(scene, Engine::lattice, Arithmetic::automatic, cap)));
            CHECK(capped.engine == EngineUsed::induction);
        }
        ++tally.capped;
    }
    tally.referenced += reference.decided();
    ++tally.by_reason[static_cast<int>(induced.reason)];
}

// Scenes until `count` of them were decided by induction (most random
// scenes answer within their first two segments, before it starts).
void run_family(std::uint64_t seed, int count, test::RandomSceneShape shape, Tally& tally) {
    std::mt19937_64 rng(seed);
    shape.box_percent = 90;
    const int goal = tally.induced + count;
    for (int attempt = 0; tally.induced < goal && attempt < 10 * count; ++attempt) {
        Scene scene = test::random_scene(rng, shape);
        scene.target() = test::random_target(rng, scene, shape);
        check_scene(scene, tally);
    }
}

} // namespace

TEST_CASE("induction agrees with simulation and the reference on random 2D scenes",
          "[induction][property][slow]") {
    Tally tally;
    // Rational and integral coordinates, crowded scenes, long thin ones.
    run_family(7001, test::case_count(2000), {2, 12, 6, 3, 3}, tally);
    run_family(7002, test::case_count(1500), {2, 12, 6, 1, 2}, tally);
    run_family(7003, test::case_count(1000), {2, 30, 10, 2, 5}, tally);
    run_family(7004, test::case_count(500), {2, 6, 3, 4, 7}, tally);
    WARN("induced " << tally.induced << " of " << tally.scenes << " (the reference decided "
                    << tally.referenced << " of them); hit/escape/absorbed/cycle "
                    << tally.by_reason[0] << "/" << tally.by_reason[1] << "/" << tally.by_reason[2]
                    << "/" << tally.by_reason[3]);
    CHECK(tally.induced == test::case_count(2000) + test::case_count(1500) +
                               test::case_count(1000) + test::case_count(500));
    CHECK(tally.referenced > tally.induced * 9 / 10);
    CHECK(tally.capped > tally.induced / 8);
    for (Reason r : {Reason::hit, Reason::escape, Reason::absorbed, Reason::cycle})
        CHECK(tally.by_reason[static_cast<int>(r)] > test::case_count(100));
}

TEST_CASE("induction agrees with simulation on random mirror mazes in a box",
          "[induction][property]") {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        RandomFamily family;
        family.mirrors = 5 + static_cast<std::int64_t>(seed % 40);
        family.range = 50 + static_cast<std::int64_t>(seed * 7);
        family.box = true;
        family.absorbers = seed % 3 == 0 ? Rational(1, 10) : Rational(0);
        family.denominator = 1 + static_cast<std::int64_t>(seed % 3);
        family.target_after = static_cast<std::int64_t>(seed * 13 % 200);
        family.seed = seed;
        const GeneratedScene generated = generate_random(family);
        INFO("seed " << seed);
        const Answer simulated = solve_with(generated.scene, Engine::lattice);
        const Answer induced = solve_with(generated.scene, Engine::induction);
        REQUIRE(summary(induced) == summary(simulated));
        if (generated.expect)
            REQUIRE(summary(induced) == std::string(to_string(generated.expect->reason)) + " " +
                                            generated.expect->reflections.get_str());
    }
}

TEST_CASE("induction meets the families' closed forms", "[induction]") {
    for (unsigned k = 1; k <= 20; ++k) {
        for (auto target :
             {BoxFamily::Target::reached, BoxFamily::Target::far, BoxFamily::Target::generic}) {
            const GeneratedScene g = generate_coprime_box(k, target);
            REQUIRE(g.expect);
            INFO("coprime box k = " << k);
            REQUIRE(summary(solve_with(g.scene, Engine::induction)) ==
                    std::string(to_string(g.expect->reason)) + " " +
                        g.expect->reflections.get_str());
        }
    }
    for (int a = 1; a <= 9; ++a)
        for (int b = 1; b <= 9; ++b)
            for (auto target :
                 {BoxFamily::Target::reached, BoxFamily::Target::far, BoxFamily::Target::generic}) {
                BoxFamily family;
                family.sides = {a, b};
                family.target = target;
                const GeneratedScene g = generate_box(family);
                INFO("box " << a << " x " << b);
                const Answer induced = solve_with(g.scene, Engine::induction);
                REQUIRE(summary(induced) == summary(solve_with(g.scene, Engine::lattice)));
                if (g.expect)
                    REQUIRE(summary(induced) == std::string(to_string(g.expect->reason)) + " " +
                                                    g.expect->reflections.get_str());
            }
    for (int length = 1; length <= 40; length += 3)
        for (int den = 1; den <= 7; ++den) {
            const GeneratedScene g = generate_hallway(length, Rational(den + 1, 2 * den + 1));
            INFO("hallway " << length << ", slope " << den + 1 << "/" << 2 * den + 1);
            REQUIRE(g.expect);
            REQUIRE(summary(solve_with(g.scene, Engine::induction)) ==
                    std::string(to_string(g.expect->reason)) + " " +
                        g.expect->reflections.get_str());
        }
    for (int p = 1; p <= 12; ++p)
        for (int q = 1; q <= 12; ++q) {
            const GeneratedScene g = generate_square(p, q);
            INFO("square " << p << " " << q);
            REQUIRE(summary(solve_with(g.scene, Engine::induction)) ==
                    std::string(to_string(g.expect->reason)) + " " +
                        g.expect->reflections.get_str());
        }
}

namespace {

// The m x n mirror box from the corner 0 at 45 degrees reaches a corner
// after m/g + n/g - 2 reflections (g = gcd(m, n)).
Integer box_corner_reflections(const Integer& m, const Integer& n) {
    Integer g;
    mpz_gcd(g.get_mpz_t(), m.get_mpz_t(), n.get_mpz_t());
    return m / g + n / g - 2;
}

} // namespace

TEST_CASE("induction decides huge boxes and hallways", "[induction]") {
    const Integer two61 = Integer(1) << 61;
    const Integer e18("1000000000000000000");
    for (const auto& [m, n] : std::vector<std::pair<Integer, Integer>>{
             {two61 + 1, two61}, {two61 - 1, e18}, {e18 + 7, two61 + 3}, {e18 * 3, e18 * 2 + 1}}) {
        BoxFamily family;
        family.sides = {m, n};
        const GeneratedScene g = generate_box(family);
        INFO("box " << m.get_str() << " x " << n.get_str());
        // Stepping 10^18 reflections would take centuries (the speed itself
        // is measured in bench/, not here).
        const Answer a = solve_with(g.scene, Engine::induction);
        REQUIRE(a.reason == Reason::hit);
        REQUIRE(a.reflections == box_corner_reflections(m, n));
        REQUIRE(a.engine == EngineUsed::induction);
    }
    // The hallway: y = 0 and y = 1 for x in [0, 10^30], slope just under
    // 1/2, so about 5 * 10^29 reflections; then the ray escapes past the end.
    const Integer e30 = Integer(e18) * Integer("1000000000000");
    const GeneratedScene hallway = generate_hallway(Rational(e30), Rational(e30 - 1, 2 * e30));
    REQUIRE(hallway.expect);
    const Answer hit = solve_with(hallway.scene, Engine::induction);
    REQUIRE(summary(hit) == "hit " + hallway.expect->reflections.get_str());
    Scene away = hallway.scene;
    away.target() = Vector{Rational(-1), Rational(-1)};
    const Answer escape = solve_with(away, Engine::induction);
    REQUIRE(summary(escape) == "escape " + hallway.expect->reflections.get_str());
}

TEST_CASE("induction when every mirror lies on an axis: w itself is invariant", "[induction]") {
    // Mirrors on x = 0 and y = 0 only: the modulus G = gcd(2c) is 0, so each
    // transversal holds at most the one state with the orbit's w.
    Scene scene;
    scene.dim = 2;
    scene.add(ElementKind::mirror, 0, 0, {{-5, 5}});
    scene.add(ElementKind::mirror, 1, 0, {{-5, 5}});
    scene.ray().direction = Vector{-1, -1, 0};
    for (int sx = -2; sx <= 4; ++sx)
        for (int sy = -2; sy <= 4; ++sy)
            for (const Vector& target : {Vector{7, 8, 0}, Vector{-2, -1, 0}, Vector{1, 1, 0}}) {
                scene.ray().start = Vector{sx, sy, 0};
                scene.target() = target;
                INFO("start " << sx << " " << sy);
                REQUIRE(summary(solve_with(scene, Engine::induction)) ==
                        summary(solve_with(scene, Engine::reference)));
            }
}
