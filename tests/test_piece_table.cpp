// What only the piece tables promise: few pieces where runs merge, a
// refusal past their budget, maps that change exactly at the events the
// sweep handles, and the solver's choice of them once a 2D run is long (checked on scenes crowded
// with corners, T-junctions and mirrors in line). Their answers against brute force from every
// lattice point of every mirror are in test_next_hit_conformance.cpp.
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "shoot/piece_table.hpp"
#include "support/brute_force_shot.hpp"
#include "support/lattice_segments.hpp"
#include "support/piece_table_states.hpp"
#include "support/portable_random.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <sstream>
#include <type_traits>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

LatticeScene random_lattice(std::mt19937_64& rng, int range, int n) {
    auto pick = [&](int lo, int hi) { return test::pick(rng, lo, hi); };
    LatticeScene ls;
    ls.dim = 2;
    for (int i = 0; i < n; ++i) {
        LatticeElement e;
        e.axis = pick(0, 1);
        e.absorber = pick(0, 6) == 0;
        const int t = 1 - e.axis;
        e.lo[e.axis] = e.hi[e.axis] = pick(-range, range);
        int a = pick(-range, range), b = pick(-range, range);
        if (a == b) ++b;
        e.lo[t] = std::min(a, b);
        e.hi[t] = std::max(a, b);
        ls.elements.push_back(e);
    }
    return ls;
}

} // namespace

TEST_CASE("piece tables merge runs into few pieces", "[pieces]") {
    // A 4 x 6 box: from each wall in each direction the next wall is one of
    // two, split at the single line through a corner, so each (mirror,
    // direction) has at most a handful of pieces.
    const LatticeScene ls = test::lattice_box(4, 6);
    const UniformGrid<std::int64_t, 2> grid(ls);
    const auto table = PieceTable<std::int64_t>::build(grid, 1000);
    REQUIRE(table);
    CHECK(table->size() <= 4 * 4 * 5);
    // No piece leads back to its own mirror at t = 0; leaving wall 0 towards
    // +x+y from its foot meets wall 1 at t = 4 and flips x.
    bool first_row = true;
    table->for_each_row([&](const PieceTable<std::int64_t>::Row& row) {
        CHECK_FALSE((row.next == row.element && row.t0 == 0 &&
                     row.kind == PieceTable<std::int64_t>::Kind::reflect));
        if (!first_row) return;
        first_row = false;
        CHECK(row.element == 0);
        CHECK(row.negative == 0);
        CHECK(row.from == 0);
        CHECK(row.next == 1);
        CHECK(row.t0 == 4);
        CHECK(row.flip == 1u);
    });
}

TEST_CASE("piece tables refuse beyond their budget", "[pieces]") {
    std::mt19937_64 rng(5);
    const LatticeScene ls = random_lattice(rng, 50, 200);
    const UniformGrid<std::int64_t, 2> grid(ls);
    CHECK_FALSE(PieceTable<std::int64_t>::build(grid, 100));
}

// Nested mirrors on one line, each overlapping all the others: on every line
// of the ray they are one group at one depth, which the sweep revisits at
// each of their ends. The maps must come out right past the groups' short
// skips, and the work, quadratic in the pile, must end in a refusal under
// the engine's budget instead of a long build.
TEMPLATE_TEST_CASE("piece tables answer on mirrors piled on one line or refuse in bounded work",
                   "[pieces]", std::int64_t, Integer) {
    auto pile = [](int k, int size) {
        LatticeScene ls = test::lattice_box(size, size);
        for (int i = 0; i < k; ++i) test::add_segment(ls, 0, size / 2, 1 + i, size - 1 - i);
        // Crossed in the middle: a T-junction and a crossing with the pile.
        test::add_segment(ls, 1, size / 2, size / 2, size - 1);
        test::add_segment(ls, 1, size / 2 + 1, 1, size - 1);
        return ls;
    };
    const LatticeScene small = pile(30, 80);
    const UniformGrid<TestType, 2> grid(small);
    const auto table = PieceTable<TestType>::build(grid, 1'000'000);
    REQUIRE(table);
    test::require_tables_answer(
        small, *table, [&](const TestType(&p)[2], unsigned d) { return grid.shoot(p, d); });
    if constexpr (std::is_same_v<TestType, std::int64_t>) {
        // 1,000 piled mirrors have about 12 pieces each, far below the
        // engine's budget of 64 a mirror: only the work limit refuses them.
        const LatticeScene big = pile(1000, 4000);
        const UniformGrid<TestType, 2> big_grid(big);
        CHECK_FALSE(PieceTable<TestType>::build(big_grid, 64 * big.elements.size() + 1024));
        CHECK(PieceTable<TestType>::build(big_grid, ~std::size_t{0}));
    }
}

// A long wall under a row of short mirrors: leaving the wall, the ray meets
// one mirror or passes between two, so the wall's slot has hundreds of
// pieces. Every level of the search on a long slot (the block index at
// fixed width over 16 or 32 blocks, and the binary search past 32) must find
// the piece brute force agrees with, at every lattice point of the wall.
TEMPLATE_TEST_CASE("piece tables answer on long walls as brute force does", "[pieces]",
                   std::int64_t, int128_t, Integer) {
    for (const int mirrors : {12, 100, 150}) {
        LatticeScene ls;
        ls.dim = 2;
        auto add = [&](int axis, int c, int lo, int hi) { test::add_segment(ls, axis, c, lo, hi); };
        const int length = 4 * mirrors;
        add(1, 0, 0, length); // the wall y = 0
        for (int k = 1; k < mirrors; ++k) add(0, 4 * k, 1 + k % 3, 2 + k % 3);
        const UniformGrid<TestType, 2> grid(ls);
        const auto table = PieceTable<TestType>::build(grid, 1'000'000);
        REQUIRE(table);
        std::size_t longest = 0;
        for (unsigned d = 0; d < 4; ++d) longest = std::max(longest, table->pieces(0, d).size());
        // 12 mirrors: up to 16 blocks; 100: 17 to 32; 150: more than 32.
        CHECK(longest > (mirrors > 120 ? 256u : mirrors > 80 ? 128u : 8u));
        if (mirrors == 100) CHECK(longest <= 256u);
        for (int x = 0; x <= length; ++x)
            for (unsigned d = 0; d < 4; ++d) {
                const TestType p[2] = {TestType(x), TestType(0)};
                const Shot<TestType> want = test::brute_force_shot<TestType, 2>(ls, p, d),
                                     got = table->shoot(p, d, 0);
                INFO(mirrors << " mirrors, x = " << x << ", direction " << d);
                REQUIRE(got.escape == want.escape);
                if (want.escape) continue;
                REQUIRE(got.t == want.t);
                REQUIRE(got.flip == want.flip);
            }
    }
}

// Short mirrors whose ends many rays pass just beside, joined at corners,
// T-junctions and in line, some one-sided or absorbing, in a box: the build
// reads an open run's map from the element whose end the neighbouring
// position's ray meets, and must agree with the grid shot on every state.
TEMPLATE_TEST_CASE("piece tables answer beside corners and T-junctions as the grid shoots",
                   "[pieces]", std::int64_t, Integer) {
    std::mt19937_64 rng(23);
    const int scenes = std::is_same_v<TestType, Integer> ? 15 : 60;
    for (int k = 0; k < scenes; ++k) {
        const int size = test::pick(rng, 8, 40);
        LatticeScene ls;
        ls.dim = 2;
        auto add = [&](int axis, int c, int lo, int hi) { test::add_segment(ls, axis, c, lo, hi); };
        add(0, 0, 0, size);
        add(0, size, 0, size);
        add(1, 0, 0, size);
        add(1, size, 0, size);
        for (int i = test::pick(rng, 1, 3 * size); i > 0; --i) {
            const int axis = test::pick(rng, 0, 1), c = test::pick(rng, 1, size - 1);
            const int lo = test::pick(rng, 1, size - 2),
                      hi = std::min(size - 1, lo + test::pick(rng, 1, 3));
            add(axis, c, lo, hi);
            // A corner, a T-junction or a mirror in line at one of its ends.
            const int end = test::pick(rng, 0, 1) ? lo : hi, join = test::pick(rng, 0, 3);
            if (join == 0) add(1 - axis, end, c, std::min(size - 1, c + 2));
            if (join == 1) add(1 - axis, end, std::max(1, c - 2), std::min(size - 1, c + 2));
            if (join == 2) add(axis, c, hi, std::min(size - 1, hi + 2));
            if (test::pick(rng, 0, 5) == 0) ls.elements.back().absorber = true;
        }
        test::make_one_sided<2>(rng, ls, 25);
        const UniformGrid<TestType, 2> grid(ls);
        const auto table = PieceTable<TestType>::build(grid, 1'000'000);
        REQUIRE(table);
        INFO("scene " << k);
        test::require_tables_answer(
            ls, *table, [&](const TestType(&p)[2], unsigned d) { return grid.shoot(p, d); });
    }
}

namespace {

// A box the ray circles for about 4 x 10^6 reflections, and `outside`
// mirrors below it that it never reaches but that count as elements.
Scene long_box(int outside) {
    std::ostringstream text;
    text << "dim 2\nmirror x 0 y 0 1000000\nmirror x 1000003 y 0 1000000\n"
            "mirror y 0 x 0 1000003\nmirror y 1000000 x 0 1000003\n";
    for (int k = 1; k <= outside; ++k) text << "mirror y -" << k << " x 0 1\n";
    text << "ray 1 2 1 1\ntarget 2 2\n"; // x + y stays odd along the ray
    return read_scene(text.str());
}

} // namespace

TEST_CASE("a 2D run steps on the grid for max(2^14, 32 n) reflections, then on the tables",
          "[pieces][lattice]") {
    // The ski-rental phase of lattice_engine.cpp: long enough to stay
    // instant for short questions, short enough that a long run is not
    // paying the grid's slower steps for long (docs/piece-tables.md).
    auto run = [](const Scene& scene, std::uint64_t steps) {
        SolveOptions options;
        options.engine = Engine::lattice;
        options.max_steps = steps;
        const Answer a = solve(scene, options);
        CHECK(a.reason == Reason::limit);
        CHECK(a.reflections == steps);
        return a.shooter;
    };
    // 4 elements: the floor of 2^14 reflections.
    const Scene small = long_box(0);
    CHECK(run(small, 16000) == ShooterUsed::grid);
    CHECK(run(small, 17000) == ShooterUsed::pieces);
    // 1,000 elements: 32,000 reflections (64 a mirror would wait for 64,000).
    const Scene crowded = long_box(996);
    CHECK(run(crowded, 30000) == ShooterUsed::grid);
    CHECK(run(crowded, 34000) == ShooterUsed::pieces);
}
