// The state-count bounds: hand-counted values, and the theorem that no
// trajectory visits more states than either bound, on every generated
// instance and on the property tests' random scenes.
#include "orthoray/bounds.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"

#include "lattice/lattice_scene.hpp"
#include "support/case_count.hpp"
#include "support/random_scene.hpp"

#include <catch2/catch.hpp>

#include <optional>
#include <set>
#include <vector>

using namespace orthoray;

namespace {

// visited <= refined <= lattice for one scene, when it is decided.
void check_theorem(const Scene& scene, std::uint64_t max_steps = 2'000'000) {
    SolveOptions o;
    o.max_steps = max_steps;
    const Answer a = solve(scene, o);
    const StateBounds b = compute_bounds(scene, false);
    const std::optional<Integer> visited = states_visited(a);
    INFO(write_scene(scene) << "answer " << to_string(a.reason) << ' ' << a.reflections
                            << ", lattice " << b.lattice_states << ", refined "
                            << b.refined_states);
    CHECK(b.refined_states <= b.lattice_states);
    if (!visited) return;
    CHECK(*visited <= b.refined_states);
}

} // namespace

TEST_CASE("bounds of the 3 x 5 box, counted by hand", "[bounds]") {
    BoxFamily f;
    f.sides = {3, 5};
    const StateBounds b = compute_bounds(generate_box(f).scene);
    CHECK(b.dim == 2);
    CHECK(b.scale[0] == 1);
    CHECK(b.scale[1] == 1);
    CHECK(b.elements == 4);
    // The perimeter has 2 (3 + 5) = 16 integer points (the corners once).
    CHECK(b.points == 16);
    CHECK(b.lattice_states == 64);
    // G = 2 gcd(3, 5) = 2: only the 8 points with x + y even, in each direction.
    CHECK(b.line_modulus[0] == 2);
    CHECK(b.refined_states == 32);
    CHECK(b.magnitude_bits == 3);
    REQUIRE(b.pieces);
    CHECK(*b.pieces > 0);
}

TEST_CASE("the line modulus uses offset differences, so it does not depend on the origin",
          "[bounds]") {
    // The box [10, 16] x [4, 10]: offsets differ by 6 on both axes, G = 12.
    Scene s;
    s.dim = 2;
    s.add_mirror(0, 10, {{4, 10}});
    s.add_mirror(0, 16, {{4, 10}});
    s.add_mirror(1, 4, {{10, 16}});
    s.add_mirror(1, 10, {{10, 16}});
    s.ray().start = {11, 5, 0};
    s.ray().direction = {1, 1, 0};
    s.target() = {0, 0, 0};
    const StateBounds b = compute_bounds(s);
    CHECK(b.points == 24);
    CHECK(b.line_modulus[0] == 12);
    // d = sx (x - 10) - sy (y - 4) = 0 (mod 12) at the start; on each side and
    // direction it leaves 1 residue of 12 of the 7 positions.
    CHECK(b.refined_states < b.lattice_states / 4);
    check_theorem(s);
}

TEST_CASE("overlapping and crossing mirrors count each point once in 2D", "[bounds]") {
    Scene s;
    s.dim = 2;
    s.add_mirror(0, 0, {{0, 4}});
    s.add_mirror(0, 0, {{2, 6}});  // overlaps the first: the union is y in [0, 6]
    s.add_mirror(1, 3, {{-2, 2}}); // crosses x = 0 at (0, 3)
    s.ray().start = {1, 0, 0};
    s.ray().direction = {1, 1, 0};
    const StateBounds b = compute_bounds(s);
    CHECK(b.points == 7 + 5 - 1);
}

TEST_CASE("3D bounds count each surface point once", "[bounds]") {
    BoxFamily f;
    f.sides = {2, 3, 4};
    const StateBounds b = compute_bounds(generate_box(f).scene);
    CHECK(b.dim == 3);
    // The 3 x 4 x 5 grid of the 2 x 3 x 4 box minus its 1 x 2 x 3 interior.
    CHECK(b.points == 3 * 4 * 5 - 1 * 2 * 3);
    CHECK(b.lattice_states == 8 * b.points);
    CHECK(b.refined_states < b.lattice_states);
    CHECK_FALSE(b.pieces);
}

TEST_CASE("states_visited counts reflection states", "[bounds]") {
    Answer a;
    a.reason = Reason::cycle;
    a.reflections = 10;
    CHECK(*states_visited(a) == 10);
    a.reason = Reason::absorbed;
    CHECK(*states_visited(a) == 11);
    a.reason = Reason::limit;
    CHECK_FALSE(states_visited(a));
}

TEST_CASE("no orbit exceeds the bounds: every family", "[bounds]") {
    for (int m = 1; m <= 9; ++m)
        for (int n = 1; n <= 9; ++n)
            for (auto t : {BoxFamily::Target::reached, BoxFamily::Target::generic}) {
                BoxFamily f;
                f.sides = {m, n};
                f.target = t;
                check_theorem(generate_box(f).scene);
            }
    for (int a = 1; a <= 4; ++a)
        for (int c = 1; c <= 4; ++c) {
            BoxFamily f;
            f.sides = {a, 3, c};
            f.target = BoxFamily::Target::far;
            check_theorem(generate_box(f).scene);
        }
    for (unsigned k = 1; k <= 12; ++k)
        check_theorem(generate_coprime_box(k, BoxFamily::Target::far).scene);
    for (unsigned k = 2; k <= 5; ++k)
        check_theorem(generate_coprime_cuboid(k, BoxFamily::Target::far).scene);
    for (int p = 1; p <= 8; ++p)
        for (int q = -8; q <= 8; ++q)
            if (q != 0) check_theorem(generate_square(p, q).scene);
    for (int length = 1; length <= 30; length += 7)
        check_theorem(generate_hallway(length, Rational(2, 3)).scene);
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        RandomFamily f;
        f.dim = seed % 2 ? 2 : 3;
        f.mirrors = static_cast<std::int64_t>(seed % 15);
        f.range = 30;
        f.denominator = static_cast<std::int64_t>(seed % 3) + 1;
        f.absorbers = seed % 4 == 0 ? Rational(1, 5) : Rational(0);
        f.box = seed % 3 != 0;
        f.direction_size = 3;
        f.seed = seed;
        if (seed % 2 == 0) f.target_after = 7;
        check_theorem(generate_random(f).scene);
    }
}

TEST_CASE("no orbit exceeds the bounds: the property tests' random scenes", "[bounds]") {
    std::mt19937_64 rng(4242);
    for (int i = 0; i < test::case_count(400); ++i) {
        test::RandomSceneShape shape;
        shape.dim = i % 2 ? 3 : 2;
        shape.max_denominator = i % 3 + 1;
        Scene s = test::random_scene(rng, shape);
        s.target() = test::random_point(rng, shape);
        check_theorem(s);
    }
}

namespace {

// Every (integer point on an element, direction) of a lattice scene, one by
// one: the brute-force count the closed formulas of lib/src/bounds must match
// (2D) or stay above (3D, where the refined count is an upper bound). The
// invariants are evaluated from their definition (docs/bounds.md), with the
// origin at the smallest mirror offset of each axis rather than the first,
// which must not matter.
struct BruteCount {
    Integer states, refined;
};

BruteCount brute_force(const Scene& scene) {
    const lattice::LatticeScene ls = lattice::make_lattice(scene);
    const int M = ls.dim;
    std::array<std::optional<Integer>, 3> origin;
    for (const auto& e : ls.elements)
        if (!e.absorber && (!origin[e.axis] || e.lo[e.axis] < *origin[e.axis]))
            origin[e.axis] = e.lo[e.axis];
    std::array<Integer, 3> g;
    for (const auto& e : ls.elements)
        if (!e.absorber)
            mpz_gcd(g[e.axis].get_mpz_t(), g[e.axis].get_mpz_t(),
                    Integer(e.lo[e.axis] - *origin[e.axis]).get_mpz_t());
    auto invariant = [&](const lattice::Coords& x, unsigned s, int k, int j) {
        const int sk = (s >> k) & 1u ? -1 : 1, sj = (s >> j) & 1u ? -1 : 1;
        return Integer(sk * (x[k] - origin[k].value_or(0)) - sj * (x[j] - origin[j].value_or(0)));
    };
    std::set<std::pair<std::vector<Integer>, unsigned>> all;
    for (const auto& e : ls.elements) {
        lattice::Coords x = e.lo;
        while (true) {
            for (unsigned s = 0; s < (1u << M); ++s)
                all.insert({std::vector<Integer>(x.begin(), x.begin() + M), s});
            int j = 0;
            while (j < M && x[j] == e.hi[j]) x[j] = e.lo[j], ++j;
            if (j == M) break;
            ++x[j];
        }
    }
    BruteCount count;
    count.states = static_cast<unsigned long>(all.size());
    for (const auto& [point, s] : all) {
        lattice::Coords x;
        for (int j = 0; j < M; ++j) x[j] = point[static_cast<std::size_t>(j)];
        bool keeps = true;
        for (int k = 0; k < M; ++k)
            for (int j = k + 1; j < M; ++j) {
                Integer G;
                mpz_gcd(G.get_mpz_t(), g[k].get_mpz_t(), g[j].get_mpz_t());
                G *= 2;
                const Integer d =
                    invariant(x, s, k, j) - invariant(ls.start, ls.start_direction, k, j);
                keeps = keeps && (G == 0 ? d == 0 : Integer(d % G) == 0);
            }
        if (keeps) ++count.refined;
    }
    return count;
}

} // namespace

TEST_CASE("bounds equal (2D) or exceed (3D) a brute-force count of the states", "[bounds][slow]") {
    std::mt19937_64 rng(77);
    for (int i = 0; i < test::case_count(400); ++i) {
        test::RandomSceneShape shape;
        shape.dim = i % 2 ? 3 : 2;
        shape.max_denominator = i % 4 < 2 ? 1 : 2;
        shape.max_direction = 2;
        Scene s = test::random_scene(rng, shape);
        const StateBounds b = compute_bounds(s, false);
        const BruteCount brute = brute_force(s);
        INFO(write_scene(s));
        CHECK(b.lattice_states == brute.states);
        if (b.dim < 3)
            CHECK(b.refined_states == brute.refined);
        else
            CHECK(b.refined_states >= brute.refined);
        CHECK(b.refined_states <= b.lattice_states);
    }
}

TEST_CASE("the state graph's states fit the lattice bound", "[bounds][slow]") {
    // explore_state_graph (Boost.Graph) enumerates the mirror states on its own;
    // it leaves absorbers out, so its count is at most the bound (equal
    // without absorbers), and the states reachable from the start are at most
    // the refined bound.
    std::mt19937_64 rng(78);
    int explored = 0;
    const int cases = test::case_count(200);
    for (int i = 0; i < cases; ++i) {
        test::RandomSceneShape shape;
        shape.dim = i % 2 ? 3 : 2;
        shape.max_denominator = 1;
        Scene s = test::random_scene(rng, shape);
        s.target() = test::random_point(rng, shape);
        const std::optional<StateGraphReport> graph = explore_state_graph(s, 20'000);
        if (!graph) continue;
        const StateBounds b = compute_bounds(s, false);
        INFO(write_scene(s));
        bool absorbers = false;
        for (const Element& e : s.elements)
            absorbers = absorbers || e.kind == ElementKind::absorber;
        if (!absorbers)
            CHECK(Integer(static_cast<unsigned long>(graph->states)) == b.lattice_states);
        else
            CHECK(Integer(static_cast<unsigned long>(graph->states)) <= b.lattice_states);
        CHECK(Integer(static_cast<unsigned long>(graph->reachable)) <= b.refined_states);
        ++explored;
    }
    CHECK(explored > cases / 2);
}
