// Degenerate geometry, traced by hand: where a ray touches more than the
// inside of one element (endpoints, crossings, corners, parallels, starts and
// targets on elements, overlaps, absorbers beside mirrors) and 1D motion.
// Every scene comes with its derivation under the rules of
// spec/semantics.md; support/degenerate_check.hpp asserts its answer for
// every engine (lattice with both arithmetic modes, reference, graph) and
// both cycle detectors, so a disagreement points at the engine that breaks
// the rule the scene isolates. The scenes of one rule form a table, each row
// run on its own.
#include "support/degenerate_check.hpp"

#include <catch2/catch.hpp>

namespace {

using orthoray::Reason;
using orthoray::test::Degenerate;
using orthoray::test::expect;

} // namespace

TEST_CASE("a hit on a mirror's endpoint reflects like a hit on its inside", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirror x=2, y in [0,2]. From (0,0) along (1,1), x=2 at t=2 gives (2,2):
        // y=2 is the mirror's upper endpoint, closed, so it is met and v -> (-1,1).
        // From (2,2) nothing else is met; (0,4) = (2,2) + 2(-1,1): yes after 1.
        {R"(dim 2
mirror x 2 y 0 2
ray 0 0 1 1
target 0 4
)",
         Reason::hit, 1},
        // The lower endpoint: from (0,2) along (1,-1), x=2 at t=2 gives (2,0), y=0
        // is the endpoint, v -> (-1,-1); (-1,-3) = (2,0) + 3(-1,-1): yes after 1.
        {R"(dim 2
mirror x 2 y 0 2
ray 0 2 1 -1
target -1 -3
)",
         Reason::hit, 1},
        // Just past the endpoint: from (0,1/2) along (1,1), x=2 at t=2 is at
        // y=5/2 > 2, so nothing is met and the ray escapes unreflected. The
        // target (0,4) would need a reflection: no, escape, 0.
        {R"(dim 2
mirror x 2 y 0 2
ray 0 1/2 1 1
target 0 4
)",
         Reason::escape, 0},
    })));
}

TEST_CASE("a hit on the crossing of two mirrors flips both components", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // A '+': mirror x=2 (y in [0,4]) and mirror y=2 (x in [0,4]) cross at
        // (2,2). From (0,0) along (1,1) both are met at t=2, so v -> (-1,-1).
        // Back through the start; nothing more is met (both planes are at t=0).
        // (-1,-1) = (2,2) + 3(-1,-1): yes after 1.
        {R"(dim 2
mirror x 2 y 0 4
mirror y 2 x 0 4
ray 0 0 1 1
target -1 -1
)",
         Reason::hit, 1},
        // Same scene, target (0,4): reachable only if x alone flipped, i.e.
        // along (-1,1) from (2,2). Both flip, so the ray escapes along (-1,-1)
        // after 1 reflection without passing (0,4).
        {R"(dim 2
mirror x 2 y 0 4
mirror y 2 x 0 4
ray 0 0 1 1
target 0 4
)",
         Reason::escape, 1},
        // 3D: rectangles x=2 and y=2 (each spanning [0,4] on the other axes)
        // cross along the line x=y=2. From the origin along (1,1,1) both are met
        // at (2,2,2); x and y flip, z is kept: v -> (-1,-1,1). (0,0,4) =
        // (2,2,2) + 2(-1,-1,1): yes after 1.
        {R"(dim 3
mirror x 2 y 0 4 z 0 4
mirror y 2 x 0 4 z 0 4
ray 0 0 0 1 1 1
target 0 0 4
)",
         Reason::hit, 1},
    })));
}

TEST_CASE("a concave corner reverses the ray", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // An inside corner: mirror x=4 (y in [0,4]) and mirror y=4 (x in [0,4])
        // meet at (4,4). From (1,1) along (1,1) both are met at t=3 (each on its
        // endpoint), v -> (-1,-1). The ray runs back through its start; (0,0) =
        // (4,4) + 4(-1,-1), behind the start: yes after 1.
        {R"(dim 2
mirror x 4 y 0 4
mirror y 4 x 0 4
ray 1 1 1 1
target 0 0
)",
         Reason::hit, 1},
        // The outside (convex side) of an L with its corner at (0,0): mirror x=0
        // (y in [0,2]) and mirror y=0 (x in [0,2]). From (-1,1) along (1,-1) both
        // planes are reached at t=1, at (0,0), which lies on both (endpoints):
        // v -> (-1,1). (-2,2) = (0,0) + 2(-1,1): yes after 1.
        {R"(dim 2
mirror x 0 y 0 2
mirror y 0 x 0 2
ray -1 1 1 -1
target -2 2
)",
         Reason::hit, 1},
    })));
}

TEST_CASE("a ray moving parallel to a mirror never meets it", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // The ray runs inside the plane y=0 of mirror y=0 (x in [0,4]) with v_y=0:
        // never met. Mirror x=6 (y in [-1,1]) is met at (6,0), v -> (-1,0); the
        // ray slides back through the first mirror's plane and escapes. (-1,0) =
        // (6,0) + 7(-1,0): yes after 1.
        {R"(dim 2
mirror y 0 x 0 4
mirror x 6 y -1 1
ray 0 0 1 0
target -1 0
)",
         Reason::hit, 1},
        // Without the far mirror: the ray slides through the whole mirror and
        // reaches (10,0) unreflected: yes after 0.
        {R"(dim 2
mirror y 0 x 0 4
ray -1 0 1 0
target 10 0
)",
         Reason::hit, 0},
    })));
}

TEST_CASE("a start point on a mirror does not reflect at t = 0", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirrors x=0 and x=4 (y in [-10,10]); the start (0,0) is on x=0. Nothing
        // happens at t=0. p1 = (4,4) on x=4, v -> (-1,1); p2 = (0,8) on x=0,
        // v -> (1,1); x=4 next at y=12 > 10: not met, the ray escapes. (5,13) =
        // (0,8) + 5(1,1): yes after 2. (Had the start reflected, v would be
        // (-1,1) and the ray would escape at once.)
        {R"(dim 2
mirror x 0 y -10 10
mirror x 4 y -10 10
ray 0 0 1 1
target 5 13
)",
         Reason::hit, 2},
        // Start on a mirror, moving away from it: nothing is met at all. (-2,2)
        // = (0,0) + 2(-1,1): yes after 0.
        {R"(dim 2
mirror x 0 y -1 1
ray 0 0 -1 1
target -2 2
)",
         Reason::hit, 0},
        // Start on the corner of an L, moving outwards: no reflection at t=0,
        // nothing ahead; the target (1,1) inside the L is never reached: no,
        // escape, 0.
        {R"(dim 2
mirror x 0 y 0 2
mirror y 0 x 0 2
ray 0 0 -1 -1
target 1 1
)",
         Reason::escape, 0},
    })));
}

TEST_CASE("a target on a reflection point is reached before that reflection", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirrors x=0 and x=2 (y in [-5,5]). From (1,0) along (1,1): p1 = (2,1),
        // v -> (-1,1); p2 = (0,3) on x=0. The target (0,3) is the end of the
        // closed segment p1 p2, so it is reached before the second reflection:
        // yes after 1.
        {R"(dim 2
mirror x 0 y -5 5
mirror x 2 y -5 5
ray 1 0 1 1
target 0 3
)",
         Reason::hit, 1},
        // The target is p1 = (2,1) itself: end of the segment p0 p1: yes after 0.
        {R"(dim 2
mirror x 0 y -5 5
mirror x 2 y -5 5
ray 1 0 1 1
target 2 1
)",
         Reason::hit, 0},
    })));
}

TEST_CASE("a target at the start is reached with 0 reflections", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Inside the mirror box [0,2]^2 the ray from (1/2,1/2) along (1,1) would
        // cycle, but P = s: yes after 0.
        {R"(dim 2
mirror x 0 y 0 2
mirror x 2 y 0 2
mirror y 0 x 0 2
mirror y 2 x 0 2
ray 1/2 1/2 1 1
target 1/2 1/2
)",
         Reason::hit, 0},
        // The start is a corner of the box (on two mirrors): still yes after 0.
        {R"(dim 2
mirror x 0 y 0 2
mirror x 2 y 0 2
mirror y 0 x 0 2
mirror y 2 x 0 2
ray 0 0 1 1
target 0 0
)",
         Reason::hit, 0},
    })));
}

TEST_CASE("overlapping collinear mirrors reflect once", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirrors x=2 with y in [0,3] and in [1,4] overlap on [1,3]. From (0,0)
        // along (1,1) both are met at (2,2); they share axis x, so x flips once:
        // v -> (-1,1). (0,4) = (2,2) + 2(-1,1): yes after 1. (Flipping twice
        // would keep (1,1) and never reach (0,4).)
        {R"(dim 2
mirror x 2 y 0 3
mirror x 2 y 1 4
ray 0 0 1 1
target 0 4
)",
         Reason::hit, 1},
        // The same mirror listed twice behaves like one.
        {R"(dim 2
mirror x 2 y 0 4
mirror x 2 y 0 4
ray 0 0 1 1
target 0 4
)",
         Reason::hit, 1},
        // 3D: rectangles z=2 over [0,3]^2 and [1,4]^2 overlap; from the origin
        // along (1,1,1) both are met at (2,2,2), z flips once: v -> (1,1,-1).
        // (4,4,0) = (2,2,2) + 2(1,1,-1): yes after 1.
        {R"(dim 3
mirror z 2 x 0 3 y 0 3
mirror z 2 x 1 4 y 1 4
ray 0 0 0 1 1 1
target 4 4 0
)",
         Reason::hit, 1},
    })));
}

TEST_CASE("an absorber and a mirror at the same point: the absorber wins", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirror x=2 (y in [0,4]) and absorber x=2 (y in [2,3]). From (0,0)
        // along (1,1) both are met at (2,2) (the absorber on its endpoint): the
        // ray stops with no reflection. (0,4) would be reached had it reflected:
        // no, absorbed, 0.
        {R"(dim 2
mirror x 2 y 0 4
absorber x 2 y 2 3
ray 0 0 1 1
target 0 4
)",
         Reason::absorbed, 0},
        // The absorber is perpendicular to the mirror and touches the hit point
        // with its end: absorber y=2, x in [2,3], met at (2,2) too: absorbed, 0.
        {R"(dim 2
mirror x 2 y 0 4
absorber y 2 x 2 3
ray 0 0 1 1
target 0 4
)",
         Reason::absorbed, 0},
        // The target is the absorption point (2,2): it ends the final segment,
        // which counts (closed): yes after 0.
        {R"(dim 2
mirror x 2 y 0 4
absorber x 2 y 2 3
ray 0 0 1 1
target 2 2
)",
         Reason::hit, 0},
    })));
}

TEST_CASE("a target beyond an absorber is not reached", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Absorber x=3 (y in [0,2]); from (0,1) along (1,0) it is met at (3,1).
        // (5,1) lies on the line beyond it: no, absorbed, 0.
        {R"(dim 2
absorber x 3 y 0 2
ray 0 1 1 0
target 5 1
)",
         Reason::absorbed, 0},
        // An absorber is met on its endpoint too: absorber x=3 with y in [1,2]
        // is met at (3,1).
        {R"(dim 2
absorber x 3 y 1 2
ray 0 1 1 0
target 5 1
)",
         Reason::absorbed, 0},
        // After a reflection: mirror x=3 (y in [0,2]) is met on its endpoint
        // (3,2) from (1,0) along (1,1), v -> (-1,1); absorber x=0 (y in [0,6])
        // is met at (0,5). (-1,6) lies beyond it: no, absorbed, 1.
        {R"(dim 2
mirror x 3 y 0 2
absorber x 0 y 0 6
ray 1 0 1 1
target -1 6
)",
         Reason::absorbed, 1},
    })));
}

TEST_CASE("a target far out on the final escaping ray is reached", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirror x=1 (y in [-1,1]) is met on its endpoint (1,1), v -> (-1,1), and
        // nothing else exists. With N = 10^30, (1-N, 1+N) = (1,1) + N(-1,1):
        // yes after 1.
        {R"(dim 2
mirror x 1 y -1 1
ray 0 0 1 1
target -999999999999999999999999999999 1000000000000000000000000000001
)",
         Reason::hit, 1},
        // One unit off that ray, (1-N, 2+N) is never reached: no, escape, 1.
        {R"(dim 2
mirror x 1 y -1 1
ray 0 0 1 1
target -999999999999999999999999999999 1000000000000000000000000000002
)",
         Reason::escape, 1},
    })));
}

TEST_CASE("1D motion between two mirrors is a cycle of period 2", "[degenerate]") {
    expect(GENERATE(values<Degenerate>({
        // Mirrors x=0 and x=3 (y in [-1,1]); from (1,0) along (1,0):
        // p1 = (3,0), v -> (-1,0); p2 = (0,0), v -> (1,0); p3 = (3,0) with
        // (-1,0) = state 1. Period 2. (1,1) is off the line y=0: no, cycle 2.
        {R"(dim 2
mirror x 0 y -1 1
mirror x 3 y -1 1
ray 1 0 1 0
target 1 1
)",
         Reason::cycle, 2},
        // The same with a scaled, negative direction (-5,0): p1 = (0,0),
        // p2 = (3,0), p3 = p1. (-1,0) is on the line but outside [0,3]: no,
        // cycle 2.
        {R"(dim 2
mirror x 0 y -1 1
mirror x 3 y -1 1
ray 1 0 -5 0
target -1 0
)",
         Reason::cycle, 2},
        // (2,0) is on the first segment: yes after 0.
        {R"(dim 2
mirror x 0 y -1 1
mirror x 3 y -1 1
ray 1 0 1 0
target 2 0
)",
         Reason::hit, 0},
        // 3D, direction (0,0,3): only z moves. Mirrors z=1 and z=-1 span (0,0).
        // Mirror z=0 spans x in [1,2] only, not x=0: never met. Mirror x=0 is
        // parallel (the ray slides inside its plane). p1 = (0,0,1), p2 =
        // (0,0,-1), p3 = p1 with v = (0,0,-3) = state 1: period 2; (0,0,2) is
        // never reached: no, cycle 2.
        {R"(dim 3
mirror z 1 x -1 1 y -1 1
mirror z -1 x -1 1 y -1 1
mirror z 0 x 1 2 y -1 1
mirror x 0 y -1 1 z -1 1
ray 0 0 0 0 0 3
target 0 0 2
)",
         Reason::cycle, 2},
    })));
}
