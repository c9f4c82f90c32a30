// Degenerate geometry, traced by hand, continued (test_degenerate.cpp has
// the single contacts): 3D edges and vertices, a zero direction component,
// box corners, elements end to end and grazed, coordinates around 10^40 and
// with mixed denominators, empty scenes, a comb of near misses, and numbers
// out of lowest terms. Each answer is asserted for every engine and option
// (support/degenerate_check.hpp).
#include "support/degenerate_check.hpp"

#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

namespace {

using orthoray::Answer;
using orthoray::Engine;
using orthoray::Reason;
using orthoray::test::Degenerate;
using orthoray::test::expect;

} // namespace

TEST_CASE("3D edge and vertex hits flip two and three components", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Edge: rectangles x=2 (y in [0,2], z in [0,4]) and y=2 (x in [0,2],
        // z in [0,4]) share the edge x=y=2. From the origin along (1,1,1) both
        // are met at (2,2,2) on that edge: v -> (-1,-1,1). (0,0,4) = (2,2,2) +
        // 2(-1,-1,1): yes after 1.
        {R"(dim 3
mirror x 2 y 0 2 z 0 4
mirror y 2 x 0 2 z 0 4
ray 0 0 0 1 1 1
target 0 0 4
)",
         Reason::hit, 1},
        // The edge y=2 of a single rectangle x=2: only x flips, v -> (-1,1,1);
        // (0,4,4) = (2,2,2) + 2(-1,1,1): yes after 1.
        {R"(dim 3
mirror x 2 y 0 2 z 0 4
ray 0 0 0 1 1 1
target 0 4 4
)",
         Reason::hit, 1},
        // Vertex: three unit-cube faces x=2, y=2, z=2 (each over [0,2]^2) meet at
        // (2,2,2). All three are met there: v -> (-1,-1,-1), back through the
        // start; (-1,-1,-1) = (2,2,2) + 3(-1,-1,-1): yes after 1.
        {R"(dim 3
mirror x 2 y 0 2 z 0 2
mirror y 2 x 0 2 z 0 2
mirror z 2 x 0 2 y 0 2
ray 0 0 0 1 1 1
target -1 -1 -1
)",
         Reason::hit, 1},
        // Same vertex, target (0,0,4), which only a two-component flip (x, y)
        // would reach: all three flip, so no, escape, 1.
        {R"(dim 3
mirror x 2 y 0 2 z 0 2
mirror y 2 x 0 2 z 0 2
mirror z 2 x 0 2 y 0 2
ray 0 0 0 1 1 1
target 0 0 4
)",
         Reason::escape, 1},
        // The corner of a single rectangle x=2 over [0,2]^2: only x flips,
        // v -> (-1,1,1); (0,4,4) = (2,2,2) + 2(-1,1,1): yes after 1.
        {R"(dim 3
mirror x 2 y 0 2 z 0 2
ray 0 0 0 1 1 1
target 0 4 4
)",
         Reason::hit, 1},
    })));
}

TEST_CASE("3D with a zero component: mirrors off the fixed coordinate are never met",
          "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // The ray keeps z = 5 (direction (1,1,0)). Mirror x=2 with z in [0,4] and
        // mirror x=2 with z in [51/10,9] do not span z=5: never met. Mirror z=5 is
        // parallel: never met although the ray moves inside it. Mirror x=3 with
        // z in [0,6] is met at (3,3,5), v -> (-1,1,0). Back across x=2 at
        // (2,4,5), again not met. (0,6,5) = (3,3,5) + 3(-1,1,0): yes after 1.
        {R"(dim 3
mirror x 2 y 0 4 z 0 4
mirror x 2 y 0 4 z 51/10 9
mirror z 5 x 0 10 y 0 10
mirror x 3 y 0 4 z 0 6
ray 0 0 5 1 1 0
target 0 6 5
)",
         Reason::hit, 1},
        // A mirror whose edge is exactly at z=5 does span it: mirror x=2 with z in
        // [5,9] is met at (2,2,5), v -> (-1,1,0); (0,4,5) = (2,2,5) + 2(-1,1,0):
        // yes after 1.
        {R"(dim 3
mirror x 2 y 0 4 z 5 9
mirror x 3 y 0 4 z 0 6
ray 0 0 5 1 1 0
target 0 4 5
)",
         Reason::hit, 1},
        // A target off the fixed coordinate (z = 4 instead of 5), on the
        // projected path: never reached, the ray escapes after 1.
        {R"(dim 3
mirror x 3 y 0 4 z 0 6
ray 0 0 5 1 1 0
target 0 6 4
)",
         Reason::escape, 1},
    })));
}

TEST_CASE("a ray from a corner of a box moving inwards", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Box [0,1] x [0,2] of four mirrors; start at the corner (0,0) (on two
        // mirrors, nothing at t=0), v = (1,1):
        //   p1 = (1,1) on x=1                 v -> (-1, 1)
        //   p2 = (0,2) corner: x=0 and y=2    v -> ( 1,-1)
        //   p3 = (1,1) on x=1                 v -> (-1,-1)
        //   p4 = (0,0) corner: x=0 and y=0    v -> ( 1, 1)
        //   p5 = (1,1) on x=1                 v -> (-1, 1) = state 1
        // Period 4. The corner (1,0) is on none of the segments: no, cycle 4.
        {R"(dim 2
mirror x 0 y 0 2
mirror x 1 y 0 2
mirror y 0 x 0 1
mirror y 2 x 0 1
ray 0 0 1 1
target 1 0
)",
         Reason::cycle, 4},
        // (1/2,3/2) is on the segment p1 p2: yes after 1.
        {R"(dim 2
mirror x 0 y 0 2
mirror x 1 y 0 2
mirror y 0 x 0 1
mirror y 2 x 0 1
ray 0 0 1 1
target 1/2 3/2
)",
         Reason::hit, 1},
        // The square [0,2]^2: from the corner (0,0) along (1,1) the ray hits the
        // opposite corner (2,2) (both flip), comes back to (0,0) (both flip), and
        // state 1 repeats: period 2. (1,0) is off the diagonal: no, cycle 2.
        {R"(dim 2
mirror x 0 y 0 2
mirror x 2 y 0 2
mirror y 0 x 0 2
mirror y 2 x 0 2
ray 0 0 1 1
target 1 0
)",
         Reason::cycle, 2},
    })));
}

TEST_CASE("mirrors touching end to end", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Collinear: x=2 with y in [0,2] and with y in [2,4] touch at (2,2). From
        // (0,0) along (1,1) both are met there; same axis, so x flips once:
        // v -> (-1,1); (0,4) = (2,2) + 2(-1,1): yes after 1.
        {R"(dim 2
mirror x 2 y 0 2
mirror x 2 y 2 4
ray 0 0 1 1
target 0 4
)",
         Reason::hit, 1},
        // A 'T': mirror y=2 (x in [2,5]) ends on mirror x=2 (y in [0,4]) at
        // (2,2). From (4,0) along (-1,1) both planes are reached at t=2, at
        // (2,2), which lies on both: v -> (1,-1). (5,-1) = (2,2) + 3(1,-1): yes
        // after 1.
        {R"(dim 2
mirror x 2 y 0 4
mirror y 2 x 2 5
ray 4 0 -1 1
target 5 -1
)",
         Reason::hit, 1},
    })));
}

TEST_CASE("an absorber grazed in parallel is not met", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // 2D: the ray runs along y=0 through absorber y=0 (x in [2,4]), entering
        // at its endpoint; v_y = 0, so it is never met. (10,0): yes after 0.
        {R"(dim 2
absorber y 0 x 2 4
ray 0 0 1 0
target 10 0
)",
         Reason::hit, 0},
        // 3D: the ray runs along the x axis, which is an edge of absorber z=0
        // (x, y in [0,2]) and of absorber y=0 (x, z in [0,2]); v_y = v_z = 0, so
        // neither is met. Mirror x=4 reflects at (4,0,0), v -> (-1,0,0); the ray
        // slides back along the edge. (-2,0,0) = (4,0,0) + 6(-1,0,0): yes after 1.
        {R"(dim 3
absorber z 0 x 0 2 y 0 2
absorber y 0 x 0 2 z 0 2
mirror x 4 y -1 1 z -1 1
ray -1 0 0 1 0 0
target -2 0 0
)",
         Reason::hit, 1},
        // 3D diagonal inside the absorber's plane: direction (1,1,0) in z=0
        // crosses absorber z=0 (x, y in [0,2]) without meeting it. (3,3,0): yes
        // after 0.
        {R"(dim 3
absorber z 0 x 0 2 y 0 2
ray -1 -1 0 1 1 0
target 3 3 0
)",
         Reason::hit, 0},
    })));
}

TEST_CASE("coordinates around 10^40 with a short answer", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // N = 10^40. Mirror x=N with y in [N-5, N+5]. From (N-3, N) along (1,1),
        // x=N at t=3 gives (N, N+3), inside: v -> (-1,1). (N-3, N+6) = (N, N+3) +
        // 3(-1,1): yes after 1. The automatic lattice engine must go to GMP.
        {R"(dim 2
mirror x 10000000000000000000000000000000000000000 y 9999999999999999999999999999999999999995 10000000000000000000000000000000000000005
ray 9999999999999999999999999999999999999997 10000000000000000000000000000000000000000 1 1
target 9999999999999999999999999999999999999997 10000000000000000000000000000000000000006
)",
         Reason::hit, 1},
        // The unit box [N, N+1]^2 from (N, N+1/2) (on its left wall) along (1,1);
        // relative to (N,N): (1/2,1) on y=1, (1,1/2) on x=1, (1/2,0) on y=0,
        // (0,1/2) on x=0, then (1/2,1) with v = (1,-1) again: period 4. The
        // corner (N+1, N+1) is never reached: no, cycle 4.
        {R"(dim 2
mirror x 10000000000000000000000000000000000000000 y 10000000000000000000000000000000000000000 10000000000000000000000000000000000000001
mirror x 10000000000000000000000000000000000000001 y 10000000000000000000000000000000000000000 10000000000000000000000000000000000000001
mirror y 10000000000000000000000000000000000000000 x 10000000000000000000000000000000000000000 10000000000000000000000000000000000000001
mirror y 10000000000000000000000000000000000000001 x 10000000000000000000000000000000000000000 10000000000000000000000000000000000000001
ray 10000000000000000000000000000000000000000 20000000000000000000000000000000000000001/2 1 1
target 10000000000000000000000000000000000000001 10000000000000000000000000000000000000001
)",
         Reason::cycle, 4},
        // A direction with a 10^40 component: from (0,0) along (N, 1), mirror x=N
        // (y in [0,2]) is met at t=1 at (N,1), v -> (-N,1). (-N, 3) = (N,1) +
        // 2(-N,1): yes after 1. The lattice scales y by N, so the mirror holds
        // 2N+1 lattice points: the graph engine must refuse (limit), not answer.
        {R"(dim 2
mirror x 10000000000000000000000000000000000000000 y 0 2
ray 0 0 10000000000000000000000000000000000000000 1
target -10000000000000000000000000000000000000000 3
)",
         Reason::hit, 1, false},
    })));
}

TEST_CASE("fractional coordinates with different denominators", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Start (0,1/7), direction (1/2,1/3); mirrors x=0.6=3/5 (y in [0,1]) and
        // y=11/14 (x in [-1,1]).
        //   x=3/5 at t=(3/5)/(1/2)=6/5: y = 1/7 + 2/5 = 19/35 in [0,1]; y stays
        //   below 11/14 on the way. p1 = (3/5, 19/35), v -> (-1/2, 1/3).
        //   y=11/14 at t = (11/14 - 19/35)*3 = 51/70: x = 3/5 - 51/140 = 33/140.
        //   p2 = (33/140, 11/14), v -> (-1/2, -1/3). Nothing else ahead.
        //   (0, 22/35) = p2 + (33/70)(-1/2,-1/3): yes after 2.
        {R"(dim 2
mirror x 0.6 y 0 1
mirror y 11/14 x -1 1
ray 0 1/7 1/2 1/3
target 0 22/35
)",
         Reason::hit, 2},
        // Same, target (0, 23/35): not on the final ray (nor earlier): no,
        // escape, 2.
        {R"(dim 2
mirror x 0.6 y 0 1
mirror y 11/14 x -1 1
ray 0 1/7 1/2 1/3
target 0 23/35
)",
         Reason::escape, 2},
        // Decimals and fractions for the same values: mirror x=1.25 (y in
        // [-0.5, 1/2]); from (0.125, 0) along (9/8, 0.75): x=5/4 at t=1 gives
        // (5/4, 3/4), outside y in [-1/2,1/2]: not met, escape after 0. A target
        // on the ray, (2.375, 1.5) = start + 2v: yes after 0.
        {R"(dim 2
mirror x 1.25 y -0.5 1/2
ray 0.125 0 9/8 0.75
target 2.375 1.5
)",
         Reason::hit, 0},
    })));
}

TEST_CASE("no elements, and elements behind the start", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Nothing to meet: (4,6) = 2(2,3) is on the ray: yes after 0.
        {R"(dim 2
ray 0 0 2 3
target 4 6
)",
         Reason::hit, 0},
        // (-2,-3) is behind the start: no, escape, 0.
        {R"(dim 2
ray 0 0 2 3
target -2 -3
)",
         Reason::escape, 0},
        // Mirror x=-1 is behind the start (t < 0): never met; escape after 0.
        {R"(dim 2
mirror x -1 y -5 5
ray 0 0 1 1
target -1 -1
)",
         Reason::escape, 0},
    })));
}

TEST_CASE("a comb of mirrors the ray misses by one unit, then two endpoint hits", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirrors x=k with y in [k+1, k+2] for k = 1..10, and x=11 with y in
        // [11,12]. From (0,0) along (1,1) the ray crosses x=k at y=k, one unit
        // below mirror k: none of the ten is met. x=11 is met at (11,11), its
        // lower endpoint: v -> (-1,1). x=10 is then reached at y=12, the upper
        // endpoint of mirror 10: met, v -> (1,1). From (10,12) the ray crosses
        // x=11 at y=13 > 12: not met; nothing else is ahead. (12,14) = (10,12) +
        // 2(1,1): yes after 2. (Eleven elements: the lattice engine's grid has
        // several cells, and both hits lie on cell walls or corners.)
        {R"(dim 2
mirror x 1 y 2 3
mirror x 2 y 3 4
mirror x 3 y 4 5
mirror x 4 y 5 6
mirror x 5 y 6 7
mirror x 6 y 7 8
mirror x 7 y 8 9
mirror x 8 y 9 10
mirror x 9 y 10 11
mirror x 10 y 11 12
mirror x 11 y 11 12
ray 0 0 1 1
target 12 14
)",
         Reason::hit, 2},
        // Same comb, target (11,12), the upper endpoint of mirror 11: it is on
        // no segment (p0 p1 has x = y; p1 p2 has x + y = 22; the final ray from
        // (10,12) has y - x = 2; here x + y = 23 and y - x = 1): no, escape, 2.
        {R"(dim 2
mirror x 1 y 2 3
mirror x 2 y 3 4
mirror x 3 y 4 5
mirror x 4 y 5 6
mirror x 5 y 6 7
mirror x 6 y 7 8
mirror x 7 y 8 9
mirror x 8 y 9 10
mirror x 9 y 10 11
mirror x 10 y 11 12
mirror x 11 y 11 12
ray 0 0 1 1
target 11 12
)",
         Reason::escape, 2},
    })));
}

TEST_CASE("numbers built in code out of lowest terms mean what they say", "[degenerate]") {
    // GMP compares rationals correctly only in lowest terms. A ray start of
    // 2/4 set directly (the builders canonicalize, a field does not) once
    // made the reference tracer see a different ray (1,109 reflections after
    // a tail of 39) from the other engines (1,070): solve() now takes every
    // scene in lowest terms. The box and its little diagonal are the
    // 45-degree billiard of test_octagonal_induction.cpp.
    orthoray::Scene s;
    s.add_diagonal(orthoray::ElementKind::mirror, 10, 0, 11, 1);
    s.add_mirror(0, 0, {{0, 327}});
    s.add_mirror(0, 145, {{0, 327}});
    s.add_mirror(1, 0, {{0, 145}});
    s.add_mirror(1, 327, {{0, 145}});
    s.ray().start = {orthoray::Rational(126), orthoray::Rational(2, 4), orthoray::Rational(0)};
    s.ray().direction = {orthoray::Rational(1), orthoray::Rational(1), orthoray::Rational(0)};
    s.target() = {orthoray::Rational(290), orthoray::Rational(0), orthoray::Rational(0)};
    CHECK_FALSE(s.in_lowest_terms());
    for (const Engine engine : {Engine::reference, Engine::lattice, Engine::graph,
                                Engine::induction, Engine::automatic}) {
        orthoray::SolveOptions o;
        o.engine = engine;
        const Answer a = orthoray::solve(s, o);
        INFO("engine " << static_cast<int>(engine));
        CHECK(a.reason == Reason::cycle);
        CHECK(a.reflections == 1070);
        CHECK(a.tail == 0);
    }
}
