// What only the bounding volume hierarchy promises: a tree of fewer nodes
// than twice the elements, nothing to hit in an empty one, and every element
// met at the first point collected. Its answers against brute force on
// random scenes are in test_next_hit_conformance.cpp.
#include "shoot/bvh.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

TEST_CASE("bvh has a node for every split and fewer than twice the elements", "[bvh]") {
    std::mt19937_64 rng(11);
    for (int scene_index = 0; scene_index < 200; ++scene_index) {
        int range = 0;
        const LatticeScene ls = test::random_lattice_scene<3>(rng, 400, range);
        const BoundingVolumeHierarchy<std::int64_t, 3> bvh(ls);
        REQUIRE(bvh.size() == ls.elements.size());
        REQUIRE(bvh.node_count() >= 1);
        REQUIRE(bvh.node_count() < 2 * ls.elements.size());
    }
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
