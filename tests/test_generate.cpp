// The instance families: byte-for-byte determinism, and every closed-form or
// constructed expectation held against the solver over many parameters (and
// every instance within the state-count bounds).
#include "orthoray/bounds.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

using namespace orthoray;

namespace {

// FNV-1a, 64 bits: a hash whose value the test can pin on every platform.
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : text) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// The expectation, written and read back, against the default engine (and,
// for small runs, the reference tracer).
void check_expectation(const GeneratedScene& g, bool with_reference = false) {
    const std::string text = write_generated(g);
    INFO(text);
    const std::optional<Expectation> expect = read_expectation(text);
    REQUIRE(expect);
    CHECK(expect->reason == g.expect->reason);
    CHECK(expect->reflections == g.expect->reflections);
    const Scene scene = read_scene(text);
    const Answer a = solve(scene);
    CHECK(to_string(a.reason) == std::string(to_string(expect->reason)));
    CHECK(a.reflections == expect->reflections);
    // The theorem of docs/bounds.md, on every instance generated here too.
    const StateBounds bounds = compute_bounds(scene, false);
    CHECK(*states_visited(a) <= bounds.refined_states);
    CHECK(bounds.refined_states <= bounds.lattice_states);
    if (with_reference) {
        SolveOptions o;
        o.engine = Engine::reference;
        const Answer r = solve(scene, o);
        CHECK(r.reason == expect->reason);
        CHECK(r.reflections == expect->reflections);
    }
}

} // namespace

TEST_CASE("uniform() gives the same numbers everywhere", "[generate]") {
    std::mt19937_64 rng(2026);
    std::string drawn;
    for (int i = 0; i < 8; ++i) drawn += std::to_string(uniform(rng, -5, 1000)) + ' ';
    // Pinned: std::mt19937_64's sequence is fixed by the standard, the range
    // reduction is ours.
    CHECK(drawn == "502 347 786 97 635 510 259 786 ");
    CHECK(uniform(rng, 7, 7) == 7);
    CHECK_THROWS_AS(uniform(rng, 2, 1), std::invalid_argument);
}

TEST_CASE("generated text is deterministic and pinned", "[generate]") {
    BoxFamily box;
    box.sides = {3, 5};
    const std::string box_text = write_generated(generate_box(box), {"orthoray generate box"});
    CHECK(box_text ==
          "# orthoray generate box\n"
          "# box; target: the corner the ray reaches\n"
          "# closed form: the corner is reached after N reflections, N = sum (T/a_j - 1) - "
          "sum (T/lcm(a_i, a_j) - 1), T = lcm of the sides\n"
          "# expect: yes hit 6\n"
          "dim 2\n"
          "mirror x 0 y 0 5\n"
          "mirror x 3 y 0 5\n"
          "mirror y 0 x 0 3\n"
          "mirror y 5 x 0 3\n"
          "ray 0 0 1 1\n"
          "target 3 5\n");

    RandomFamily f;
    f.dim = 3;
    f.mirrors = 12;
    f.denominator = 4;
    f.absorbers = Rational(1, 5);
    f.box = true;
    f.target_after = 5;
    f.seed = 99;
    const std::string a = write_generated(generate_random(f));
    CHECK(a == write_generated(generate_random(f)));
    f.seed = 100;
    CHECK(a != write_generated(generate_random(f)));
    // A change here means every generated random scene changed: say so in
    // docs/generate.md, then update the pin.
    CHECK(fnv1a(a) == 0xb62a3e43b96c8f33ull);
}

TEST_CASE("box from the corner: closed form over many sizes", "[generate]") {
    for (int m = 1; m <= 13; ++m)
        for (int n = 1; n <= 13; ++n)
            for (auto target :
                 {BoxFamily::Target::reached, BoxFamily::Target::far, BoxFamily::Target::generic}) {
                BoxFamily f;
                f.sides = {m, n};
                f.target = target;
                check_expectation(generate_box(f), m + n < 10);
            }
    for (int a = 1; a <= 6; ++a)
        for (int b = 1; b <= 6; ++b)
            for (int c = 1; c <= 6; ++c)
                for (auto target : {BoxFamily::Target::reached, BoxFamily::Target::far}) {
                    BoxFamily f;
                    f.sides = {a, b, c};
                    f.target = target;
                    check_expectation(generate_box(f), a + b + c < 8);
                }
}

TEST_CASE("box with a given start or target has no expectation", "[generate]") {
    BoxFamily f;
    f.sides = {4, 6};
    f.start = Vector{1, 0, 0};
    CHECK_FALSE(generate_box(f).expect);
    f.start.reset();
    f.target = BoxFamily::Target::point;
    f.target_point = Vector{1, 1, 0};
    CHECK_FALSE(generate_box(f).expect);
    f.direction = Vector{0, 0, 0};
    CHECK_THROWS_AS(generate_box(f), std::invalid_argument);
    f.direction.reset();
    f.sides = {4, 0};
    CHECK_THROWS_AS(generate_box(f), std::invalid_argument);
}

TEST_CASE("coprime boxes and cuboids: exponential orbits, closed form", "[generate]") {
    for (unsigned k = 1; k <= 14; ++k)
        for (auto target : {BoxFamily::Target::reached, BoxFamily::Target::far}) {
            const GeneratedScene g = generate_coprime_box(k, target);
            if (target == BoxFamily::Target::reached)
                CHECK(g.expect->reflections == (Integer(1) << (k + 1)) - 1);
            check_expectation(g);
        }
    for (unsigned k = 2; k <= 6; ++k) {
        const GeneratedScene g = generate_coprime_cuboid(k, BoxFamily::Target::reached);
        const Integer a = (Integer(1) << k) + 1, b = Integer(1) << k, c = b - 1;
        CHECK(g.expect->reflections == a * b + b * c + a * c - a - b - c);
        check_expectation(g);
        check_expectation(generate_coprime_cuboid(k, BoxFamily::Target::far));
    }
}

TEST_CASE("unit square: period 2 (p + q) / gcd", "[generate]") {
    for (int p = -9; p <= 9; ++p)
        for (int q = -9; q <= 9; ++q) {
            if (p == 0 || q == 0) continue;
            check_expectation(generate_square(p, q), std::abs(p) + std::abs(q) < 6);
        }
    check_expectation(generate_square(1000003, 999999));
    CHECK_THROWS_AS(generate_square(0, 1), std::invalid_argument);
}

TEST_CASE("hallway: floor(1/2 + slope * length) reflections", "[generate]") {
    for (int length = 1; length <= 40; length += 3)
        for (const Rational& slope : {Rational(1, 10), Rational(1, 3), Rational(2, 7), Rational(1),
                                      Rational(5, 2), Rational(1, 2)})
            check_expectation(generate_hallway(length, slope), length < 10);
    check_expectation(generate_hallway(Rational(7, 2), Rational(3, 4)), true);
    check_expectation(generate_hallway(100000, Rational(1, 7)));
    CHECK(generate_hallway(20, Rational(1, 2)).expect->reflections == 10);
    CHECK_THROWS_AS(generate_hallway(1, 0), std::invalid_argument);
}

TEST_CASE("random with the target on the trajectory: the constructed answer", "[generate]") {
    int checked = 0;
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        RandomFamily f;
        f.dim = seed % 3 == 0 ? 3 : 2;
        f.mirrors = static_cast<std::int64_t>(seed % 25);
        f.range = seed % 2 ? 50 : 1 << 20;
        f.denominator = static_cast<std::int64_t>(seed % 4) + 1;
        f.absorbers = seed % 5 == 0 ? Rational(1, 4) : Rational(0);
        f.box = seed % 4 != 1;
        f.target_after = static_cast<std::int64_t>(seed % 30);
        f.direction_size = static_cast<std::int64_t>(seed % 7) + 1;
        f.seed = seed;
        const GeneratedScene g = generate_random(f);
        REQUIRE(g.expect);
        CHECK(g.expect->reason == Reason::hit);
        CHECK(g.expect->reflections <= *f.target_after);
        check_expectation(g, seed % 10 == 0);
        ++checked;
    }
    CHECK(checked == 60);
}

TEST_CASE("random without a target on the trajectory has no expectation", "[generate]") {
    RandomFamily f;
    f.mirrors = 5;
    const GeneratedScene g = generate_random(f);
    CHECK_FALSE(g.expect);
    CHECK_FALSE(read_expectation(write_generated(g)));
    f.dim = 4;
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
}

TEST_CASE("read_expectation reads what write_generated writes, and nothing else", "[generate]") {
    CHECK(read_expectation("# expect: no cycle 16\ndim 2\n")->reflections == 16);
    CHECK(read_expectation("# expect: no escape 3\n")->reason == Reason::escape);
    CHECK(read_expectation("# expect: no absorbed 0\n")->reason == Reason::absorbed);
    CHECK_FALSE(read_expectation("# expect: yes cycle 16\n"));
    CHECK_FALSE(read_expectation("# expect: no hit 1\n"));
    CHECK_FALSE(read_expectation("# expect: yes hit many\n"));
    CHECK_FALSE(read_expectation("dim 2\n"));
}

namespace {

struct KindCounts {
    std::size_t mirrors = 0, absorbers = 0, splitters = 0, plus = 0, minus = 0;
};

KindCounts count_kinds(const Scene& scene) {
    KindCounts c;
    for (const Element& e : scene.elements) {
        c.mirrors += e.kind == ElementKind::mirror;
        c.absorbers += e.kind == ElementKind::absorber;
        c.splitters += e.kind == ElementKind::splitter;
        c.plus += e.side == Side::plus;
        c.minus += e.side == Side::minus;
    }
    return c;
}

} // namespace

TEST_CASE("random with splitters, one-sided elements, rays and targets: as asked, and "
          "deterministic",
          "[generate][optics]") {
    RandomFamily f;
    f.mirrors = 40;
    f.splitters = 1;
    f.one_sided = 1;
    f.rays = 3;
    f.targets = 4;
    f.seed = 11;
    const GeneratedScene all = generate_random(f);
    const KindCounts every = count_kinds(all.scene);
    CHECK(every.splitters == 40);
    CHECK(every.plus + every.minus == 40);
    CHECK(every.plus > 5); // both sides are drawn
    CHECK(every.minus > 5);
    CHECK(all.scene.rays.size() == 3);
    CHECK(all.scene.targets.size() == 4);
    CHECK_FALSE(all.expect);
    for (const Ray& r : all.scene.rays)
        for (int j = 0; j < 2; ++j) {
            CHECK(r.start[j] >= 0);
            CHECK(r.start[j] <= f.range);
            CHECK(r.direction[j] != 0);
        }

    // Fractions: an absorber never splits, the kinds come near the chances
    // asked (400 draws each; the bounds are 5 standard deviations wide), and
    // the box's faces stay two-sided mirrors.
    f.mirrors = 400;
    f.absorbers = Rational(1, 4);
    f.splitters = Rational(1, 2);
    f.one_sided = Rational(1, 3);
    f.box = true;
    const GeneratedScene mixed = generate_random(f);
    const KindCounts some = count_kinds(mixed.scene);
    CHECK(mixed.scene.elements.size() == 404);
    CHECK(some.absorbers > 100 - 44);
    CHECK(some.absorbers < 100 + 44);
    CHECK(some.splitters > 150 - 50);
    CHECK(some.splitters < 150 + 50);
    CHECK(some.plus + some.minus > 133 - 48);
    CHECK(some.plus + some.minus < 133 + 48);
    for (std::size_t i = 0; i < 4; ++i) {
        CHECK(mixed.scene.elements[i].kind == ElementKind::mirror);
        CHECK_FALSE(mixed.scene.elements[i].one_sided());
    }
    const std::string text = write_generated(mixed, {"orthoray generate random ..."});
    CHECK(text.find("# kinds of the random elements: " + std::to_string(some.mirrors - 4) +
                    " mirrors, " + std::to_string(some.splitters) + " splitters, " +
                    std::to_string(some.absorbers) + " absorbers; " +
                    std::to_string(some.plus + some.minus) + " one-sided\n") != std::string::npos);
    CHECK(text.find("# 3 rays, 4 targets: the illumination question") != std::string::npos);

    // Same seed, same bytes; the text reads back to the same scene.
    CHECK(text == write_generated(generate_random(f), {"orthoray generate random ..."}));
    f.seed = 12;
    CHECK(text != write_generated(generate_random(f), {"orthoray generate random ..."}));
    const Scene back = read_scene(text);
    CHECK(write_scene(back) == write_scene(mixed.scene));
    CHECK(back.rays.size() == 3);
    CHECK(back.targets.size() == 4);

    // Left at their defaults the new options draw nothing: the scene is the
    // one the seed gave before they existed (the pinned hash above, too).
    RandomFamily plain;
    plain.mirrors = 30;
    RandomFamily explicit_defaults = plain;
    explicit_defaults.splitters = 0;
    explicit_defaults.rays = 1;
    CHECK(write_generated(generate_random(plain)) ==
          write_generated(generate_random(explicit_defaults)));
}

TEST_CASE("random optics scenes: both illumination engines agree on them", "[generate][optics]") {
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        RandomFamily f;
        f.dim = seed % 3 == 0 ? 3 : 2;
        f.mirrors = 6;
        f.range = 12;
        f.box = true;
        f.splitters = Rational(1, 2);
        f.one_sided = Rational(1, 3);
        f.rays = 1 + static_cast<std::int64_t>(seed % 2);
        f.targets = 1 + static_cast<std::int64_t>(seed % 3);
        f.direction_size = 2;
        f.seed = seed;
        const Scene scene = read_scene(write_generated(generate_random(f)));
        INFO(write_scene(scene));
        const Answer found = solve(scene);
        SolveOptions graph;
        graph.engine = Engine::graph;
        const Answer built = solve(scene, graph);
        REQUIRE(found.decided());
        REQUIRE(built.decided());
        CHECK(found.reason == built.reason);
        REQUIRE(found.targets.size() == scene.targets.size());
        REQUIRE(built.targets.size() == scene.targets.size());
        for (std::size_t t = 0; t < scene.targets.size(); ++t) {
            CHECK(found.targets[t].status == built.targets[t].status);
            CHECK(found.targets[t].reflections == built.targets[t].reflections);
            CHECK(found.targets[t].ray == built.targets[t].ray);
        }
    }
}

TEST_CASE("random one-sided trajectory with the target on it: the constructed answer",
          "[generate][optics]") {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        RandomFamily f;
        f.dim = seed % 4 == 0 ? 3 : 2;
        f.mirrors = 10;
        f.range = 40;
        f.box = seed % 5 != 0;
        f.one_sided = Rational(1, 2);
        f.target_after = static_cast<std::int64_t>(seed % 12);
        f.seed = seed;
        const GeneratedScene g = generate_random(f);
        REQUIRE(g.expect);
        CHECK(g.expect->reflections <= *f.target_after);
        check_expectation(g, true);
    }
    RandomFamily f;
    f.target_after = 3;
    f.splitters = Rational(1, 2);
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
    f.splitters = 0;
    f.targets = 2;
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
    f.target_after.reset();
    f.rays = 0;
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
    f.rays = 1;
    f.one_sided = Rational(3, 2);
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
}

TEST_CASE("random octagonal scenes: diagonals as asked, the constructed answer",
          "[generate][octagonal][slow]") {
    // The generator builds its answer with the reference tracer, which the
    // state graph shares its step with; the octagonal lattice engine and
    // the octagonal induction share neither, so the four must agree.
    std::size_t diagonals = 0, elements = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        RandomFamily f;
        f.mirrors = 10;
        f.range = 40;
        f.denominator = 1 + seed % 2;
        f.box = seed % 5 != 0;
        f.diagonals = Rational(1, 2);
        f.one_sided = seed % 3 == 0 ? Rational(1, 3) : Rational(0);
        f.target_after = static_cast<std::int64_t>(seed % 12);
        f.seed = seed;
        const GeneratedScene g = generate_random(f);
        REQUIRE(g.expect);
        const std::string text = write_generated(g);
        INFO(text);
        const Scene scene = read_scene(text);
        for (const Element& e : scene.elements) {
            diagonals += e.is_diagonal();
            ++elements;
            for (int j = 0; j < 2; ++j) CHECK((0 <= e.lo[j] && e.hi[j] <= f.range));
        }
        for (const Engine engine :
             {Engine::reference, Engine::graph, Engine::lattice, Engine::induction}) {
            SolveOptions o;
            o.engine = engine;
            const Answer a = solve(scene, o);
            CAPTURE(static_cast<int>(engine));
            CHECK(a.reason == g.expect->reason);
            CHECK(a.reflections == g.expect->reflections);
        }
    }
    // About half of the random elements (the box's faces are axis mirrors).
    CHECK(diagonals > elements / 4);
    RandomFamily f;
    f.diagonals = Rational(1, 2);
    f.dim = 3;
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
    f.dim = 2;
    f.diagonals = Rational(3, 2);
    CHECK_THROWS_AS(generate_random(f), std::invalid_argument);
}
