// The grids' counting policy (shoot/shot_counter.hpp) counts what it claims,
// so that bench/grid_average's figures mean what docs/average-case.md says:
// - uniform grid: the cells walked are the distinct cells the ray passes
//   through from its start up to its first hit (the ray at t + 1/2, t = 0,
//   1, ..., lies inside one cell: walls are at integer coordinates), and
//   the members tested are, summed over those cells, the elements acting on
//   the direction whose closed box meets the cell's closed box: both found
//   here by brute force over every element, not by the grid's own lists;
// - cross-section grid: one cell when the ray's line meets some element's
//   shadow, none only when the ray meets nothing, and every element met at
//   the hit among the members scanned and box-tested;
// - counting changes no answer, and take() starts the counts again.
#include "shoot/cross_section_grid.hpp"
#include "shoot/uniform_grid.hpp"
#include "support/brute_force_shot.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

using Int = std::int64_t;

// floor(a / b) for b > 0.
Int floor_of(Int a, Int b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// The cells and members a uniform grid with cell sides h (corner lo) walks
// from p, a point inside the scene's bounding box, up to parameter `last`
// (the hit's t, or the box's exit when the ray escapes).
template <int M>
ShotCounts walked_by_brute_force(const LatticeScene& ls, const Int (&lo)[M], const Int (&h)[M],
                                 const Int (&p)[M], unsigned negative, Int last) {
    ShotCounts counts;
    std::set<std::vector<Int>> seen;
    for (Int t = 0; t < last; ++t) {
        // The ray at t + 1/2, doubled to stay in integers: 2p + sigma (2t + 1).
        std::vector<Int> cell(M);
        for (int j = 0; j < M; ++j) {
            const Int twice = 2 * p[j] + (((negative >> j) & 1u) ? -(2 * t + 1) : 2 * t + 1);
            cell[j] = floor_of(twice - 2 * lo[j], 2 * h[j]);
        }
        if (!seen.insert(cell).second) continue;
        ++counts.cells;
        for (const LatticeElement& e : ls.elements) {
            if (!e.acts_on(negative)) continue;
            bool meets = true;
            for (int j = 0; j < M; ++j)
                meets = meets && e.lo[j] <= lo[j] + (cell[j] + 1) * h[j] &&
                        lo[j] + cell[j] * h[j] <= e.hi[j];
            counts.members += meets;
        }
    }
    return counts;
}

// Shots from random points inside a closed mirror box with obstacles (some
// one-sided, some absorbers), at several grid densities.
template <int M>
void check_uniform_grid_counts(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uint64_t shots = 0, walked = 0; // the walks must not be trivial
    for (int scene = 0; scene < 12; ++scene) {
        LatticeScene ls = test::random_box_scene<M>(rng, test::pick(rng, 1, 40), 200);
        test::make_one_sided<M>(rng, ls, 30);
        const std::int64_t density = test::pick(rng, 1, 16), per = test::pick(rng, 1, 4);
        const UniformGrid<Int, M> plain(ls, density, {}, per);
        const UniformGrid<Int, M, Counting> counted(ls, density, {}, per);
        Int lo[M], h[M];
        for (int j = 0; j < M; ++j) {
            lo[j] = 0; // the box [0, 200]^M bounds every element
            h[j] = counted.cell_side(j);
        }
        for (int shot = 0; shot < 40; ++shot) {
            Int p[M];
            for (int j = 0; j < M; ++j) p[j] = test::pick(rng, 1, 199);
            const unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
            const Shot<Int> got = counted.shoot(p, negative);
            const ShotCounts counts = counted.counter().take();
            const Shot<Int> want = plain.shoot(p, negative);
            REQUIRE(got.escape == want.escape);
            REQUIRE(got.t == want.t);
            REQUIRE(got.flip == want.flip);
            Int last = got.t;
            if (got.escape) { // one-sided walls let it out: it walks to the grid's edge
                last = 1000;
                for (int j = 0; j < M; ++j) {
                    const Int edge = (201 + h[j] - 1) / h[j] * h[j]; // n_j cells of side h_j
                    last = std::min(last, ((negative >> j) & 1u) ? p[j] : Int(edge - p[j]));
                }
            }
            const ShotCounts brute = walked_by_brute_force<M>(ls, lo, h, p, negative, last);
            INFO("scene " << scene << ", shot " << shot << ", direction " << negative);
            CHECK(counts.cells == brute.cells);
            CHECK(counts.members == brute.members);
            CHECK(counts.box_tests <= counts.members);
            CHECK(counted.counter().take().members == 0);
            ++shots;
            walked += brute.cells;
        }
    }
    CHECK(walked > 2 * shots);
}

} // namespace

TEST_CASE("the uniform grid counts the cells it walks and the members in them", "[shoot]") {
    check_uniform_grid_counts<2>(101);
    check_uniform_grid_counts<3>(202);
}

TEST_CASE("the cross-section grid counts its one cell and scans every element met", "[shoot]") {
    std::mt19937_64 rng(303);
    for (int scene = 0; scene < 20; ++scene) {
        int range = 0;
        LatticeScene ls = test::random_lattice_scene<3>(rng, 30, range);
        const CrossSectionGrid<Int, 3, Counting> counted(ls, test::pick(rng, 1, 8));
        for (int shot = 0; shot < 60; ++shot) {
            Int p[3];
            test::random_query_point<Int, 3>(rng, ls, range, 1, p);
            const unsigned negative = static_cast<unsigned>(test::pick(rng, 0, 7));
            const Shot<Int> got = counted.shoot(p, negative);
            const ShotCounts counts = counted.counter().take();
            const Shot<Int> want = test::brute_force_shot<Int, 3>(ls, p, negative);
            REQUIRE(got.escape == want.escape);
            // The line a_j = x_j - sigma_j sigma_0 x_0 meets an element's
            // shadow box when some element's box spans it.
            bool in_some_shadow = false;
            std::uint64_t met = 0;
            for (const LatticeElement& e : ls.elements) {
                bool inside = true;
                for (int j = 1; j < 3; ++j) {
                    const Int r = (((negative >> j) ^ negative) & 1u) ? -1 : 1;
                    const Int a = p[j] - r * p[0];
                    const Int x_lo = r * from_integer<Int>(e.lo[0]),
                              x_hi = r * from_integer<Int>(e.hi[0]);
                    inside = inside && from_integer<Int>(e.lo[j]) - std::max(x_lo, x_hi) <= a &&
                             a <= from_integer<Int>(e.hi[j]) - std::min(x_lo, x_hi);
                }
                in_some_shadow = in_some_shadow || inside;
                if (want.escape) continue;
                bool holds = true;
                for (int j = 0; j < 3; ++j) {
                    const Int x = ((negative >> j) & 1u) ? p[j] - want.t : p[j] + want.t;
                    holds =
                        holds && from_integer<Int>(e.lo[j]) <= x && x <= from_integer<Int>(e.hi[j]);
                }
                met += holds; // on its plane too: lo == hi on the normal axis
            }
            INFO("scene " << scene << ", shot " << shot << ", direction " << negative);
            if (!want.escape) CHECK(in_some_shadow);
            CHECK(counts.cells == (in_some_shadow ? 1u : counts.cells));
            CHECK(counts.cells <= 1);
            if (counts.cells == 0) CHECK(want.escape);
            CHECK(counts.members >= met);
            CHECK(counts.box_tests >= met);
            CHECK(counts.box_tests <= counts.members);
        }
    }
}
