// The lattice engine on 2D scenes with diagonal elements (docs/octagonal.md,
// docs/lattice.md "Diagonal elements"): the lattice's scale, hand-traced
// scenes (a diamond of four diagonals in closed form, a diagonal's end, a
// corner of a diagonal and a wall, a rho cycle through a one-way mirror),
// the shooters that refuse diagonals, and agreement with the reference
// tracer on random octagonal scenes.
#include "lattice/octagonal_lattice.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

using namespace orthoray;

namespace {

Vector at(const Rational& x, const Rational& y) {
    return {x, y, Rational(0)};
}

// A diamond of four diagonal mirrors with corners (n, 0), (2n, n), (n, 2n),
// (0, n), and a ray along +x at height h inside it.
std::string diamond(int n, const std::string& h, const std::string& direction = "1 0") {
    std::ostringstream s;
    s << "dim 2\nmirror \\ 0 " << n << ' ' << n << " 0\nmirror / " << n << " 0 " << 2 * n << ' '
      << n << "\nmirror \\ " << n << ' ' << 2 * n << ' ' << 2 * n << ' ' << n << "\nmirror / 0 "
      << n << ' ' << n << ' ' << 2 * n << "\nray " << n << ' ' << h << ' ' << direction
      << "\ntarget -7 -7\n";
    return s.str();
}

Answer lattice_solve(const Scene& scene, PathSink* path = nullptr) {
    SolveOptions options;
    options.path = path;
    return solve(scene, options);
}

} // namespace

TEST_CASE("octagonal lattice: one scale for both axes, N from a, b, a - b and a + b",
          "[octagonal][lattice]") {
    // u = (1, 2): N = lcm(1, 2, 1, 3) = 6; denominators 2 (start) and 3.
    Scene s = read_scene("dim 2\nmirror / 0 0 1/3 1/3\nray 1/2 0 1 2\ntarget 0 0\n");
    const lattice::OctagonalLattice l = lattice::make_octagonal_lattice(s);
    CHECK(l.scale == 36);
    CHECK(l.distinct_directions == 8);
    CHECK(l.start[0] == 18);
    CHECK(l.w[5] == std::array<Integer, 2>{-2, 1}); // swapped, then x negated
    CHECK(l.direction(5) == at(-2, 1));
    // u = (1, 1): N = lcm(1, 1, 2) = 2, four distinct directions.
    s = read_scene("dim 2\nmirror \\ 0 1 1 0\nray 0 0 -3 -3\ntarget 0 0\n");
    const lattice::OctagonalLattice d = lattice::make_octagonal_lattice(s);
    CHECK(d.scale == 2);
    CHECK(d.distinct_directions == 4);
    CHECK(d.canonical[4] == 0);
    // Along an axis: N = 1.
    s = read_scene("dim 2\nmirror \\ 0 1 1 0\nray 0 0 0 5\ntarget 0 0\n");
    CHECK(lattice::make_octagonal_lattice(s).scale == 1);
}

TEST_CASE("octagonal lattice: a diamond of diagonals, period 4 off its axis and 2 on it",
          "[octagonal][lattice]") {
    // At height h the ray turns up at (n + h, h), left at (n + h, 2n - h),
    // down at (n - h, 2n - h) and right at (n - h, h): period 4. At h = n it
    // meets the corner (2n, n) of two slopes and goes back: period 2.
    for (int n = 1; n <= 6; ++n)
        for (int twice_h = 1; twice_h < 4 * n; ++twice_h) {
            Rational h(twice_h, 2);
            h.canonicalize();
            const Scene s = read_scene(diamond(n, h.get_str()));
            INFO(write_scene(s));
            PathRecorder path;
            const Answer a = lattice_solve(s, &path);
            CHECK(a.reason == Reason::cycle);
            CHECK(a.tail == 0);
            CHECK(a.reflections == (h == n ? 2 : 4));
            if (n <= h) continue; // above the axis: the mirror image of below
            REQUIRE(path.points.size() >= 5);
            CHECK(path.points[1] == at(n + h, h));
            CHECK(path.points[2] == at(n + h, 2 * n - h));
            CHECK(path.points[3] == at(n - h, 2 * n - h));
            CHECK(path.points[4] == at(n - h, h));
            CHECK(path.directions[1] == at(0, 1));
            CHECK(path.directions[4] == at(1, 0));
        }
    // Along a diagonal the ray slides along two sides and meets the other
    // two head on: straight back, period 2.
    const Answer a = lattice_solve(read_scene(diamond(4, "1", "1 1")));
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 2);
}

TEST_CASE("octagonal lattice: a ray along x in a box with a '/' and a '\\'",
          "[octagonal][lattice]") {
    // From (1/2, 1) along +x: the '\' (x + y = 2) turns it down at (1, 1);
    // at (1, 0) the wall y = 0 and the end of the '/' (y = x - 1) meet, a
    // corner of two orientations: back up; the '\' turns it left at (1, 1);
    // the wall x = 0 sends it right at (0, 1); period 4.
    const std::string box = "dim 2\nmirror x 0 y 0 4\nmirror x 4 y 0 4\nmirror y 0 x 0 4\n"
                            "mirror y 4 x 0 4\nmirror / 1 0 3 2\nmirror \\ 0 2 2 0\n"
                            "ray 1/2 1 1 0\n";
    PathRecorder path;
    Answer a = lattice_solve(read_scene(box + "target 9 9\n"), &path);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 4);
    CHECK(a.tail == 0);
    REQUIRE(path.points.size() >= 5);
    CHECK(path.points[1] == at(1, 1));
    CHECK(path.points[2] == at(1, 0));
    CHECK(path.directions[2] == at(0, 1));
    CHECK(path.points[3] == at(1, 1));
    CHECK(path.directions[3] == at(-1, 0));
    CHECK(path.points[4] == at(0, 1));
    // Targets on the way: after one reflection, and after three.
    a = lattice_solve(read_scene(box + "target 1 1/2\n"));
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 1);
    a = lattice_solve(read_scene(box + "target 1/4 1\n"));
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 3);
}

TEST_CASE("octagonal lattice: a diagonal's endpoint reflects like its inside",
          "[octagonal][lattice]") {
    // '/' from (2, 0) to (3, 1): the ray along +x at y = 0 meets its end
    // (2, 0), turns to +y and escapes.
    PathRecorder path;
    const Answer a =
        lattice_solve(read_scene("dim 2\nmirror / 2 0 3 1\nray 0 0 5/2 0\ntarget 2 7\n"), &path);
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 1);
    const Answer escape =
        lattice_solve(read_scene("dim 2\nmirror / 2 0 3 1\nray 0 0 5/2 0\ntarget 3 7\n"), &path);
    CHECK(escape.reason == Reason::escape);
    CHECK(escape.reflections == 1);
    CHECK(path.points.back() == at(2, 0));
    CHECK(path.directions.back() == at(0, Rational(5, 2)));
    // The lower end (3, 1) of a '\' from (2, 2), met by a ray along
    // (-1, 2) from (4, -1) (a direction of neither kind).
    const Answer far =
        lattice_solve(read_scene("dim 2\nmirror \\ 2 2 3 1\nray 4 -1 -1 2\ntarget -9 -9\n"), &path);
    CHECK(far.reason == Reason::escape);
    CHECK(far.reflections == 1);
    CHECK(path.points.back() == at(3, 1));
    CHECK(path.directions.back() == at(-2, 1)); // '\': (v_x, v_y) -> (-v_y, -v_x)
}

TEST_CASE("octagonal lattice: one-way mirrors and a diagonal make a rho cycle with a tail",
          "[octagonal][lattice]") {
    // Down from (1/2, 2) past the end of the wall y = 1 (x in [2, 4]): the
    // '\' x + y = 1 sends it right at (1/2, 1/2); it passes the back of the
    // one-way mirror x+ 1; the '/' y = x - 5/2 turns it up at (3, 1/2); the
    // wall y = 1 sends it down at (3, 1); the '/' left at (3, 1/2); the
    // one-way mirror right at (1, 1/2), and again up at (3, 1/2). The first
    // state is not on the cycle: tail 1, period 4.
    const Scene s = read_scene("dim 2\nmirror \\ 0 1 1 0\nmirror x+ 1 y 0 1\nmirror / 5/2 0 7/2 1\n"
                               "mirror y 1 x 2 4\nray 1/2 2 0 -1\ntarget 9 9\n");
    PathRecorder path;
    const Answer a = lattice_solve(s, &path);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.tail == 1);
    CHECK(a.period() == 4);
    CHECK(a.reflections == 5);
}

TEST_CASE("octagonal lattice: grid, piece tables and cross-section grid refuse diagonals",
          "[octagonal][lattice]") {
    const Scene s = read_scene(diamond(3, "1"));
    for (const Shooter shooter : {Shooter::grid, Shooter::pieces, Shooter::section}) {
        SolveOptions options;
        options.shooter = shooter;
        CHECK_THROWS_AS(solve(s, options), UnsupportedScene);
    }
    SolveOptions bvh;
    bvh.shooter = Shooter::bvh;
    CHECK(solve(s, bvh).shooter == ShooterUsed::bvh);
    SolveOptions induction;
    induction.engine = Engine::induction;
    CHECK_THROWS_AS(solve(s, induction), UnsupportedScene);
}
