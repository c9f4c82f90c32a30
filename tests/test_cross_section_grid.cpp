// The cross-section grid's next-hit answer equals a brute-force scan over
// all elements, for random lattice scenes (coincident and overlapping
// elements, absorbers), rays from corners, planes, walls and outside the
// scene, along whole trajectories, on all integer types and at magnitudes
// near each type's bound.
#include "orthoray/solve.hpp"
#include "shoot/cross_section_grid.hpp"
#include "support/brute_force_shot.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

template <class Int, int M>
void require_brute_force(const LatticeScene& ls, const CrossSectionGrid<Int, M>& grid,
                         const Int (&p)[M], unsigned negative) {
    const Shot<Int> got = grid.shoot(p, negative),
                    want = test::brute_force_shot<Int, M>(ls, p, negative);
    REQUIRE(got.escape == want.escape);
    if (want.escape) return;
    REQUIRE(got.t == want.t);
    REQUIRE(got.flip == want.flip);
    REQUIRE(got.met == want.met);
    REQUIRE(got.absorber == want.absorber);
    if (got.flip != 0) REQUIRE(test::mirror_holds_hit<Int, M>(ls, got, p, negative));
}

template <class Int, int M>
void check_random_shots(std::uint64_t seed, int scenes, int max_elements, int shots,
                        std::int64_t density, const Integer& scale = 1) {
    std::mt19937_64 rng(seed);
    for (int scene_index = 0; scene_index < scenes; ++scene_index) {
        int range = 0;
        const LatticeScene ls = test::random_lattice_scene<M>(rng, max_elements, range, scale);
        const CrossSectionGrid<Int, M> grid(ls, density);
        for (int shot = 0; shot < shots; ++shot) {
            Int p[M];
            test::random_query_point<Int, M>(rng, ls, range, scale, p);
            const unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
            require_brute_force<Int, M>(ls, grid, p, negative);
        }
    }
}

template <class Int, int M>
void check_trajectory(std::uint64_t seed, int obstacles, int steps, std::int64_t density) {
    std::mt19937_64 rng(seed);
    const LatticeScene ls = test::random_box_scene<M>(rng, obstacles);
    const CrossSectionGrid<Int, M> grid(ls, density);
    Int p[M];
    for (int j = 0; j < M; ++j) p[j] = test::pick(rng, 1, 999);
    unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
    for (int step = 0; step < steps; ++step) {
        require_brute_force<Int, M>(ls, grid, p, negative);
        const Shot<Int> s = grid.shoot(p, negative);
        if (s.escape) break;
        for (int j = 0; j < M; ++j)
            p[j] = ((negative >> j) & 1u) ? Int(p[j] - s.t) : Int(p[j] + s.t);
        negative ^= s.flip;
    }
}

} // namespace

TEST_CASE("cross-section grid matches brute force in 1D, 2D and 3D", "[section]") {
    for (std::int64_t density : {1, 4, 16}) {
        check_random_shots<std::int64_t, 1>(41, 100, 40, 100, density);
        check_random_shots<std::int64_t, 2>(42, 200, 40, 100, density);
        check_random_shots<std::int64_t, 3>(43, 200, 40, 100, density);
    }
    check_random_shots<std::int64_t, 3>(44, 20, 400, 200, 1);
    check_random_shots<int128_t, 2>(45, 50, 40, 100, 1);
    check_random_shots<int128_t, 3>(46, 50, 200, 100, 2);
    check_random_shots<Integer, 2>(47, 30, 40, 100, 1);
    check_random_shots<Integer, 3>(48, 30, 200, 100, 2);
}

TEST_CASE("cross-section grid is exact at large magnitudes", "[section]") {
    // Coordinates up to 33 * 2^53 < 2^59: the int64 bound of lattice_int.hpp.
    const Integer big = Integer(1) << 53;
    check_random_shots<std::int64_t, 2>(51, 50, 40, 100, 1, big + 1);
    check_random_shots<std::int64_t, 3>(52, 50, 100, 100, 4, big - 1);
    check_random_shots<int128_t, 3>(53, 30, 100, 100, 1, (Integer(1) << 110) + 3);
    check_random_shots<Integer, 3>(54, 20, 100, 100, 1, Integer(1) << 200);
}

TEST_CASE("cross-section grid follows trajectories like brute force", "[section]") {
    check_trajectory<std::int64_t, 2>(61, 200, 2000, 1);
    check_trajectory<std::int64_t, 3>(62, 300, 3000, 1);
    check_trajectory<std::int64_t, 3>(63, 3000, 2000, 4);
    check_trajectory<int128_t, 3>(64, 300, 1000, 1);
    check_trajectory<Integer, 3>(65, 300, 500, 1);
}

TEST_CASE("cross-section grid of an empty scene lets every ray escape", "[section]") {
    LatticeScene ls;
    ls.dim = 3;
    const CrossSectionGrid<std::int64_t, 3> grid(ls);
    const std::int64_t p[3] = {0, 0, 0};
    for (unsigned negative = 0; negative < 8; ++negative) CHECK(grid.shoot(p, negative).escape);
}

namespace {

// A closed 3D box of side 10^4 with `n` small mirrors, either spread over
// the box or crowded into one corner of side 100.
Scene mirror_box(int n, bool crowded) {
    auto q = [](long v) { return Rational(Integer(v)); };
    Scene scene;
    scene.dim = 3;
    for (int axis = 0; axis < 3; ++axis)
        for (long offset : {0L, 10000L})
            scene.add_mirror(axis, q(offset), {{q(0), q(10000)}, {q(0), q(10000)}});
    std::mt19937_64 rng(7);
    const int side = crowded ? 100 : 10000;
    for (int i = 0; i < n; ++i) {
        const int axis = test::pick(rng, 0, 2);
        std::vector<std::pair<Rational, Rational>> extent;
        for (int j = 0; j < 2; ++j) {
            const int lo = test::pick(rng, 1, side - 20);
            extent.emplace_back(q(lo), q(lo + test::pick(rng, 1, 19)));
        }
        scene.add_mirror(axis, q(test::pick(rng, 1, side - 1)), extent);
    }
    scene.ray().start = {q(5001), q(5003), q(5007)};
    scene.ray().direction = {q(3), q(5), q(7)};
    scene.target() = {q(1), q(2), q(3)};
    return scene;
}

} // namespace

TEST_CASE("3D solves use the cross-section grid unless elements crowd", "[section]") {
    SolveOptions options;
    options.max_steps = 1000;
    CHECK(solve(mirror_box(2000, false), options).shooter == ShooterUsed::section);
    CHECK(solve(mirror_box(2000, true), options).shooter == ShooterUsed::bvh);
}
