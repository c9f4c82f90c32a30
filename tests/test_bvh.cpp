// The bounding volume hierarchy's next-hit answer equals a brute-force scan
// over all elements and the uniform grid's answer, for random lattice scenes
// (coincident and overlapping elements, absorbers) and rays that start on
// elements, on box walls and outside the bounding box, on all integer types.
#include "shoot/bvh.hpp"
#include "shoot/uniform_grid.hpp"
#include "support/brute_force_shot.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

template <class Int, int M>
void require_same(const LatticeScene& ls, const BoundingVolumeHierarchy<Int, M>& bvh,
                  const UniformGrid<Int, M>& grid, const Int (&p)[M], unsigned negative) {
    const Shot<Int> got = bvh.shoot(p, negative),
                    want = test::brute_force_shot<Int, M>(ls, p, negative),
                    other = grid.shoot(p, negative);
    REQUIRE(got.escape == want.escape);
    REQUIRE(other.escape == want.escape);
    if (want.escape) return;
    REQUIRE(got.t == want.t);
    REQUIRE(got.flip == want.flip);
    REQUIRE(got.met == want.met);
    REQUIRE(got.absorber == want.absorber);
    REQUIRE(other.t == want.t);
    REQUIRE(other.flip == want.flip);
    REQUIRE(other.met == want.met);
    REQUIRE(other.absorber == want.absorber);
    if (got.flip != 0) REQUIRE(test::mirror_holds_hit<Int, M>(ls, got, p, negative));
}

// Random scenes (tests/support/random_lattice.hpp) and query points.
template <class Int, int M>
void check_random_shots(std::uint64_t seed, int scenes, int max_elements, int shots,
                        const Integer& scale = 1) {
    std::mt19937_64 rng(seed);
    for (int scene_index = 0; scene_index < scenes; ++scene_index) {
        int range = 0;
        const LatticeScene ls = test::random_lattice_scene<M>(rng, max_elements, range, scale);
        const BoundingVolumeHierarchy<Int, M> bvh(ls);
        const UniformGrid<Int, M> grid(ls);
        REQUIRE(bvh.size() == ls.elements.size());
        REQUIRE(bvh.node_count() >= 1);
        REQUIRE(bvh.node_count() < 2 * ls.elements.size());
        for (int shot = 0; shot < shots; ++shot) {
            Int p[M];
            test::random_query_point<Int, M>(rng, ls, range, scale, p);
            const unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
            require_same<Int, M>(ls, bvh, grid, p, negative);
        }
    }
}

// Follows the trajectory inside a closed box of mirrors with obstacles
// (reflecting on mirrors, passing through absorbers), comparing every step.
template <class Int, int M>
void check_trajectory(std::uint64_t seed, int obstacles, int steps) {
    std::mt19937_64 rng(seed);
    const LatticeScene ls = test::random_box_scene<M>(rng, obstacles);
    const BoundingVolumeHierarchy<Int, M> bvh(ls);
    const UniformGrid<Int, M> grid(ls);
    Int p[M];
    for (int j = 0; j < M; ++j) p[j] = test::pick(rng, 1, 999);
    unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
    for (int step = 0; step < steps; ++step) {
        require_same<Int, M>(ls, bvh, grid, p, negative);
        const Shot<Int> s = bvh.shoot(p, negative);
        if (s.escape) break;
        for (int j = 0; j < M; ++j)
            p[j] = ((negative >> j) & 1u) ? Int(p[j] - s.t) : Int(p[j] + s.t);
        negative ^= s.flip;
    }
}

} // namespace

TEST_CASE("bvh matches brute force and the grid in 1D, 2D and 3D", "[bvh]") {
    check_random_shots<std::int64_t, 1>(11, 200, 40, 100);
    check_random_shots<std::int64_t, 2>(12, 200, 40, 100);
    check_random_shots<std::int64_t, 3>(13, 200, 40, 100);
    check_random_shots<std::int64_t, 3>(14, 20, 400, 200);
    check_random_shots<int128_t, 1>(15, 50, 40, 100);
    check_random_shots<int128_t, 2>(16, 50, 40, 100);
    check_random_shots<int128_t, 3>(17, 50, 200, 100);
    check_random_shots<Integer, 1>(18, 30, 40, 100);
    check_random_shots<Integer, 2>(19, 30, 40, 100);
    check_random_shots<Integer, 3>(20, 30, 200, 100);
}

TEST_CASE("bvh is exact at large magnitudes", "[bvh]") {
    // Coordinates up to 33 * 2^53 < 2^59: the int64 bound of lattice_int.hpp.
    const Integer big = Integer(1) << 53;
    check_random_shots<std::int64_t, 2>(21, 50, 40, 100, big + 1);
    check_random_shots<std::int64_t, 3>(22, 50, 100, 100, big - 1);
    const Integer huge = Integer(1) << 110;
    check_random_shots<int128_t, 3>(23, 30, 100, 100, huge + 3);
    check_random_shots<Integer, 3>(24, 20, 100, 100, Integer(1) << 200);
}

TEST_CASE("bvh follows trajectories like the grid", "[bvh]") {
    check_trajectory<std::int64_t, 2>(31, 200, 2000);
    check_trajectory<std::int64_t, 3>(32, 300, 3000);
    check_trajectory<std::int64_t, 3>(33, 3000, 2000);
    check_trajectory<int128_t, 3>(34, 300, 1000);
    check_trajectory<Integer, 3>(35, 300, 500);
}

TEST_CASE("bvh of an empty scene lets every ray escape", "[bvh]") {
    LatticeScene ls;
    ls.dim = 3;
    const BoundingVolumeHierarchy<std::int64_t, 3> bvh(ls);
    CHECK(bvh.node_count() == 0);
    const std::int64_t p[3] = {0, 0, 0};
    for (unsigned negative = 0; negative < 8; ++negative) CHECK(bvh.shoot(p, negative).escape);
    const BoundingVolumeHierarchy<Integer, 1> bvh1(ls);
    const Integer q[1] = {Integer(5)};
    CHECK(bvh1.shoot(q, 1).escape);
}

TEST_CASE("bvh collects every element met at the same point", "[bvh]") {
    // Three mirrors through the corner (2, 2, 2), an absorber there too, and
    // a farther mirror: the ray from the origin meets all four at t = 2.
    LatticeScene ls;
    ls.dim = 3;
    for (int a = 0; a < 3; ++a) {
        LatticeElement e;
        e.axis = a;
        for (int j = 0; j < 3; ++j) {
            e.lo[j] = j == a ? 2 : 1;
            e.hi[j] = j == a ? 2 : 2;
        }
        ls.elements.push_back(e);
    }
    LatticeElement absorber = ls.elements[0];
    absorber.absorber = true;
    ls.elements.push_back(absorber);
    for (int i = 0; i < 20; ++i) { // farther, to make a deeper tree
        LatticeElement e;
        e.axis = i % 3;
        for (int j = 0; j < 3; ++j) {
            e.lo[j] = j == e.axis ? 3 + i : 0;
            e.hi[j] = j == e.axis ? 3 + i : 40;
        }
        ls.elements.push_back(e);
    }
    const BoundingVolumeHierarchy<std::int64_t, 3> bvh(ls);
    const std::int64_t p[3] = {0, 0, 0};
    const Shot<std::int64_t> s = bvh.shoot(p, 0);
    REQUIRE(!s.escape);
    CHECK(s.t == 2);
    CHECK(s.flip == 7u);
    CHECK(s.met == 7u);
    CHECK(s.absorber);
    CHECK(s.mirror < 3u);
}
