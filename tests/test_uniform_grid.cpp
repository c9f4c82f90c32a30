// The grid's next-hit answer equals a brute-force scan over all elements,
// for random lattice scenes and rays that start on cell walls, on elements
// and outside the bounding box, on both integer types.
#include "shoot/uniform_grid.hpp"
#include "support/brute_force_shot.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

template <class Int, int M>
void check_random_shots(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    for (int scene_index = 0; scene_index < 200; ++scene_index) {
        LatticeScene ls;
        ls.dim = M;
        const int range = pick(2, 30), n = pick(1, 40);
        for (int i = 0; i < n; ++i) {
            LatticeElement e;
            e.axis = pick(0, M - 1);
            e.absorber = pick(0, 5) == 0;
            for (int j = 0; j < M; ++j) {
                int a = pick(-range, range), b = pick(-range, range);
                e.lo[j] = std::min(a, b);
                e.hi[j] = j == e.axis ? e.lo[j] : Integer(std::max(a, b) + (a == b));
            }
            ls.elements.push_back(e);
        }
        const UniformGrid<Int, M> grid(ls);
        for (int shot = 0; shot < 200; ++shot) {
            Int p[M];
            for (int j = 0; j < M; ++j) p[j] = pick(-range - 3, range + 3);
            if (pick(0, 2) == 0) { // start on an element
                const LatticeElement& e = ls.elements[pick(0, n - 1)];
                for (int j = 0; j < M; ++j)
                    p[j] = from_integer<Int>(pick(0, 1) ? e.lo[j] : e.hi[j]);
            }
            const unsigned negative = static_cast<unsigned>(pick(0, (1 << M) - 1));
            const Shot<Int> got = grid.shoot(p, negative),
                            want = test::brute_force_shot<Int, M>(ls, p, negative);
            REQUIRE(got.escape == want.escape);
            if (want.escape) continue;
            REQUIRE(got.t == want.t);
            REQUIRE(got.flip == want.flip);
            REQUIRE(got.absorber == want.absorber);
        }
    }
}

} // namespace

TEST_CASE("uniform grid matches brute force in 1D, 2D and 3D", "[grid]") {
    check_random_shots<std::int64_t, 1>(1);
    check_random_shots<std::int64_t, 2>(2);
    check_random_shots<std::int64_t, 3>(3);
    check_random_shots<Integer, 2>(4);
    check_random_shots<Integer, 3>(5);
}
