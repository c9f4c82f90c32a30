// Degenerate geometry, traced by hand. Every scene below is tiny and comes
// with its derivation under the rules of spec/semantics.md; the expected
// answer is asserted for every engine (lattice with both arithmetic modes,
// reference, graph) and both cycle detectors, so a disagreement points at the
// engine that breaks the rule the scene isolates. The scenes of one rule
// form a table, each row run on its own.
#include "orthoray/answer.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

namespace {

using orthoray::Answer;
using orthoray::Arithmetic;
using orthoray::CycleDetector;
using orthoray::Engine;
using orthoray::Reason;

struct Config {
    const char* name;
    Engine engine;
    Arithmetic arithmetic;
    CycleDetector detector;
};

// Every engine with every option that may change how it gets there.
const Config configs[] = {
    {"lattice/automatic/first-state", Engine::lattice, Arithmetic::automatic,
     CycleDetector::first_state},
    {"lattice/automatic/brent", Engine::lattice, Arithmetic::automatic, CycleDetector::brent},
    {"lattice/wide/first-state", Engine::lattice, Arithmetic::wide, CycleDetector::first_state},
    {"lattice/wide/brent", Engine::lattice, Arithmetic::wide, CycleDetector::brent},
    {"reference/first-state", Engine::reference, Arithmetic::automatic, CycleDetector::first_state},
    {"reference/brent", Engine::reference, Arithmetic::automatic, CycleDetector::brent},
    {"graph/first-state", Engine::graph, Arithmetic::automatic, CycleDetector::first_state},
    {"graph/brent", Engine::graph, Arithmetic::automatic, CycleDetector::brent},
};

// A hand-traced scene and its answer: `reason` and `reflections` (the period
// for a cycle). With `graph_fits` false the scene has too many lattice
// states for the graph engine, which must then refuse (Reason::limit)
// rather than answer.
struct Degenerate {
    const char* text;
    Reason reason;
    unsigned long reflections;
    bool graph_fits = true;
};

// Solves the scene with every configuration and demands its answer. A step
// cap far above every answer here turns an engine that never stops into a
// failure instead of a hang. The certificates of the simulation engines must
// verify, so the independent checker agrees with the rule the scene isolates.
void expect(const Degenerate& degenerate) {
    const auto [text, reason, reflections, graph_fits] = degenerate;
    const orthoray::Scene scene = orthoray::read_scene(text, "<degenerate>");
    const std::string want_reason = orthoray::to_string(reason);
    const std::string want_reflections = std::to_string(reflections);
    INFO("scene:\n" << text);
    for (const Config& config : configs) {
        orthoray::SolveOptions options;
        options.engine = config.engine;
        options.arithmetic = config.arithmetic;
        options.cycle_detector = config.detector;
        options.max_steps = 10'000;
        const Answer answer = orthoray::solve(scene, options);
        INFO("configuration " << config.name);
        if (config.engine == Engine::graph && !graph_fits) {
            CHECK(answer.reason == Reason::limit);
            continue;
        }
        CHECK(std::string(orthoray::to_string(answer.reason)) == want_reason);
        CHECK(answer.reflections.get_str() == want_reflections);
        CHECK(std::string(orthoray::answer_word(answer)) == (reason == Reason::hit ? "yes" : "no"));
    }
    for (Engine engine : {Engine::lattice, Engine::reference}) {
        std::stringstream certificate;
        orthoray::CertificateWriter writer(certificate, scene);
        orthoray::SolveOptions options;
        options.engine = engine;
        writer.attach(options);
        writer.finish(orthoray::solve(scene, options));
        const orthoray::Verdict verdict = orthoray::verify_certificate(scene, certificate);
        INFO("certificate of the " << (engine == Engine::lattice ? "lattice" : "reference")
                                   << " engine:\n"
                                   << certificate.str() << "verify said: " << verdict.message);
        CHECK(verdict.valid);
    }
    // The step map of every scene here is injective (spec: reflection is
    // reversible), and the state graph must say so.
    const auto report = orthoray::explore_state_graph(scene, 2'000'000);
    if (!graph_fits) {
        CHECK_FALSE(report.has_value());
        return;
    }
    REQUIRE(report.has_value());
    CHECK(report->injective);
}

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
