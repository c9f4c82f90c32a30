// What only the cross-section grid promises: nothing to hit in an empty
// one, and the solver's choice of it over the BVH unless elements crowd.
// Its answers against brute force on random scenes, at every density and on
// every integer type, are in test_next_hit_conformance.cpp.
#include "orthoray/solve.hpp"
#include "shoot/cross_section_grid.hpp"
#include "support/brute_force_shot.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

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

TEST_CASE("cross-section grid finds every element from one step before its points", "[section]") {
    // A cell lists only the elements some line of it meets (the sheared
    // shadows of elements normal to axes 1 and 2, not their bounding
    // boxes): every point of every element, reached one step along each
    // direction, holds the grid to brute force where a shadow is tightest.
    std::mt19937_64 rng(17);
    for (int scene_index = 0; scene_index < 40; ++scene_index) {
        int range = 0;
        const LatticeScene ls = test::random_lattice_scene<3>(rng, 24, range);
        const CrossSectionGrid<std::int64_t, 3> coarse(ls, 1), fine(ls, 16);
        for (const LatticeElement& e : ls.elements)
            for (int sample = 0; sample < 24; ++sample) {
                std::int64_t x[3];
                for (int j = 0; j < 3; ++j)
                    x[j] = test::pick(rng, static_cast<int>(e.lo[j].get_si()),
                                      static_cast<int>(e.hi[j].get_si()));
                for (unsigned negative = 0; negative < 8; ++negative) {
                    std::int64_t p[3];
                    for (int j = 0; j < 3; ++j) p[j] = (negative >> j) & 1u ? x[j] + 1 : x[j] - 1;
                    const Shot<std::int64_t> want =
                        test::brute_force_shot<std::int64_t, 3>(ls, p, negative);
                    for (const auto* grid : {&coarse, &fine}) {
                        const Shot<std::int64_t> got = grid->shoot(p, negative);
                        REQUIRE(got.escape == want.escape);
                        if (want.escape) continue;
                        REQUIRE(got.t == want.t);
                        REQUIRE(got.flip == want.flip);
                        REQUIRE(got.met == want.met);
                    }
                }
            }
    }
}
