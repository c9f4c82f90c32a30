// Piece tables answer every next-hit query exactly as the grid does: checked
// on every lattice point of every mirror, in every direction, on random 2D
// scenes with crossings, T-junctions, overlaps and absorbers.
#include "shoot/piece_table.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

LatticeScene random_lattice(std::mt19937_64& rng, int range, int n) {
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
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

template <class Int>
void check_against_grid(std::uint64_t seed, int scenes) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < scenes; ++k) {
        const LatticeScene ls = random_lattice(rng, 4 + k % 12, 1 + k % 25);
        const UniformGrid<Int, 2> grid(ls);
        const auto table = PieceTable<Int>::build(ls, grid, 1'000'000);
        REQUIRE(table);
        for (std::uint32_t m = 0; m < ls.elements.size(); ++m) {
            const LatticeElement& e = ls.elements[m];
            if (e.absorber) continue;
            const int t = 1 - e.axis;
            for (Integer u = e.lo[t]; u <= e.hi[t]; ++u)
                for (unsigned d = 0; d < 4; ++d) {
                    Int p[2] = {from_integer<Int>(e.lo[0]), from_integer<Int>(e.lo[1])};
                    p[t] = from_integer<Int>(u);
                    const Shot<Int> want = grid.shoot(p, d), got = table->shoot(p, d, m);
                    INFO("scene " << k << ", mirror " << m << ", u = " << u << ", direction " << d);
                    REQUIRE(got.escape == want.escape);
                    if (want.escape) continue;
                    REQUIRE(got.absorber == want.absorber);
                    REQUIRE(got.t == want.t);
                    if (want.absorber) continue;
                    REQUIRE(got.flip == want.flip);
                    // The next mirror may differ where several meet, but it
                    // must contain the hit point.
                    const LatticeElement& next = ls.elements[got.mirror];
                    REQUIRE_FALSE(next.absorber);
                    for (int j = 0; j < 2; ++j) {
                        Int x = (d >> j) & 1u ? Int(p[j] - got.t) : Int(p[j] + got.t);
                        REQUIRE(from_integer<Int>(next.lo[j]) <= x);
                        REQUIRE(x <= from_integer<Int>(next.hi[j]));
                    }
                }
        }
    }
}

} // namespace

TEST_CASE("piece tables agree with the grid on every state", "[pieces]") {
    check_against_grid<std::int64_t>(11, 400);
    check_against_grid<Integer>(12, 60);
}

TEST_CASE("piece tables merge runs into few pieces", "[pieces]") {
    // A 4 x 6 box: from each wall in each direction the next wall is one of
    // two, split at the single line through a corner, so each (mirror,
    // direction) has at most a handful of pieces.
    LatticeScene ls;
    ls.dim = 2;
    auto wall = [&](int axis, int c, int lo, int hi) {
        LatticeElement e;
        e.axis = axis;
        e.lo[axis] = e.hi[axis] = c;
        e.lo[1 - axis] = lo;
        e.hi[1 - axis] = hi;
        ls.elements.push_back(e);
    };
    wall(0, 0, 0, 6);
    wall(0, 4, 0, 6);
    wall(1, 0, 0, 4);
    wall(1, 6, 0, 4);
    const UniformGrid<std::int64_t, 2> grid(ls);
    const auto table = PieceTable<std::int64_t>::build(ls, grid, 1000);
    REQUIRE(table);
    CHECK(table->size() <= 4 * 4 * 5);
    std::ostringstream dump;
    table->dump(dump);
    CHECK(dump.str().find("element 0 +x+y from 0: element 0 at t = 0") == std::string::npos);
    CHECK(dump.str().find("element 0 +x+y from 0: element 1 at t = 4, flip x") !=
          std::string::npos);
}

TEST_CASE("piece tables refuse beyond their budget", "[pieces]") {
    std::mt19937_64 rng(5);
    const LatticeScene ls = random_lattice(rng, 50, 200);
    const UniformGrid<std::int64_t, 2> grid(ls);
    CHECK_FALSE(PieceTable<std::int64_t>::build(ls, grid, 100));
}
