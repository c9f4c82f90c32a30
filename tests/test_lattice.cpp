// The lattice: scaling makes the direction diagonal and the data integral.
#include "lattice/lattice_scene.hpp"

#include "orthoray/parse.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;

TEST_CASE("each active axis is scaled by D * L / |u_j|", "[lattice]") {
    // u = (2, 3) (from 4/3, 2), L = 6, D = lcm(2, 3) = 6 (from 1/2 and 7/3).
    const Scene s = read_scene("dim 2\nmirror x 1/2 y 0 7/3\nray 0 0 4/3 2\ntarget 1 1\n");
    const auto ls = lattice::make_lattice(s);
    REQUIRE(ls.dim == 2);
    CHECK(ls.scale[0] == 6 * 6 / 2);
    CHECK(ls.scale[1] == 6 * 6 / 3);
    REQUIRE(ls.elements.size() == 1);
    CHECK(ls.elements[0].lo[0] == 9);  // 1/2 * 18
    CHECK(ls.elements[0].hi[1] == 28); // 7/3 * 12
    CHECK(ls.start_direction == 0);
    CHECK(ls.target_reachable);
    CHECK(ls.target[0] == 18);
    CHECK(ls.magnitude == 28);
}

TEST_CASE("a zero direction component drops the axis and unreachable elements", "[lattice]") {
    const Scene s = read_scene("dim 3\n"
                               "mirror x 5 y 0 1 z 0 1\n" // spans the ray's y = 1/2, z = 1
                               "mirror x 6 y 0 1 z 2 3\n" // not at z = 1: never met
                               "mirror z 0 x 0 9 y 0 9\n" // normal z, but the ray has v_z = 0
                               "ray 0 1/2 1 -1 0 0\ntarget 3 1/2 1\n");
    const auto ls = lattice::make_lattice(s);
    REQUIRE(ls.dim == 1);
    CHECK(ls.active[0] == 0);
    REQUIRE(ls.elements.size() == 1);
    CHECK(ls.start_direction == 1); // moving towards -x
    CHECK(ls.target_reachable);

    Scene off = s;
    off.target() = {3, Rational(1, 2), 2};
    CHECK_FALSE(lattice::make_lattice(off).target_reachable);
}

TEST_CASE("point() and to_lattice() are inverse on lattice points", "[lattice]") {
    const Scene s =
        read_scene("dim 3\nmirror z 1/5 x 0 1 y 0 1\nray 1/3 1/4 0 3 -2 7/2\ntarget 0 0 0\n");
    const auto ls = lattice::make_lattice(s);
    for (int a = -3; a <= 3; ++a)
        for (int b = -3; b <= 3; ++b) {
            lattice::Coords c{Integer(a * 7), Integer(b * 11), Integer(a * b)}, back;
            REQUIRE(ls.to_lattice(ls.point(c), back));
            CHECK(back == c);
        }
    lattice::Coords out;
    Vector off = ls.point({1, 1, 1});
    off[0] += Rational(1, 10 * ls.scale[0].get_si());
    CHECK_FALSE(ls.to_lattice(off, out));
    // Bit i of the mask is active axis i: here x and z move backwards.
    CHECK(ls.direction(0b101) == Vector{-3, 2, Rational(-7, 2)});
}
