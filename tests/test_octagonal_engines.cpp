// Octagonal scenes (docs/octagonal.md): the engines that follow diagonals
// held to each other on seeded random scenes, and their certificates to the
// independent verifier.
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"
#include "support/case_count.hpp"
#include "support/random_octagonal.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;
using Status = TargetAnswer::Status;

TEST_CASE("reference tracer and state graph agree on random octagonal trajectories",
          "[octagonal][property]") {
    // Two readings of one trajectory: stepping with Brent's detector (and
    // the second pass for the tail), and breadth-first search with strong
    // components on the graph of the states reached.
    std::mt19937_64 rng(14'001);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 25;
    const int cases = test::case_count(5000);
    int compared = 0, hits = 0, escapes = 0, absorbed = 0, cycles = 0, tails = 0;
    SolveOptions reference;
    reference.engine = Engine::reference;
    reference.max_steps = 100'000;
    for (int i = 0; i < cases; ++i) {
        shape.max_elements = 3 + i % 8;
        const Scene s = test::random_octagonal_scene(rng, shape);
        INFO("case " << i << "\n" << write_scene(s));
        const Answer a = solve(s, reference);
        const std::optional<StateGraphReport> g = explore_state_graph(s, 200'000);
        REQUIRE(a.decided());
        REQUIRE(g);
        ++compared;
        CHECK(a.reason == g->answer.reason);
        CHECK(a.reflections == g->answer.reflections);
        CHECK(a.tail == g->answer.tail);
        switch (a.reason) {
        case Reason::hit:
            ++hits;
            break;
        case Reason::escape:
            ++escapes;
            break;
        case Reason::absorbed:
            ++absorbed;
            break;
        default:
            ++cycles;
            tails += a.tail > 0;
        }
    }
    CHECK(compared == cases);
    // Every outcome is common enough to be exercised.
    CHECK(hits > cases / 10);
    CHECK(escapes > cases / 50);
    CHECK(absorbed > cases / 50);
    CHECK(cycles > cases / 10);
    CHECK(tails > cases / 100);
}

TEST_CASE("branches, reference and graph illumination agree on random octagonal scenes",
          "[octagonal][property]") {
    // Three readings of the illumination question with diagonal splitters:
    // the branch-state search, the reference Dijkstra over every state, and
    // Boost.Graph's BFS and Dijkstra over the explicit graph.
    std::mt19937_64 rng(14'002);
    test::RandomOctagonalShape shape;
    shape.splitter_percent = 30;
    shape.one_sided_percent = 25;
    shape.max_rays = 3;
    shape.max_targets = 3;
    const int cases = test::case_count(5000);
    int compared = 0, lit = 0, unlit = 0;
    SolveOptions reference;
    reference.engine = Engine::reference;
    for (int i = 0; i < cases; ++i) {
        shape.max_elements = 3 + i % 6;
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (s.single_trajectory()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const std::optional<Answer> graph = explore_illumination_graph(s, 100'000);
        REQUIRE(graph);
        const Answer branches = solve(s);
        const Answer by_reference = solve(s, reference);
        REQUIRE(branches.decided());
        REQUIRE(by_reference.decided());
        ++compared;
        CHECK(branches.reason == graph->reason);
        CHECK(by_reference.reason == graph->reason);
        CHECK(branches.reflections == graph->reflections);
        for (std::size_t t = 0; t < s.targets.size(); ++t) {
            const TargetAnswer &b = branches.targets[t], &r = by_reference.targets[t],
                               &g = graph->targets[t];
            CHECK(b.status == g.status);
            CHECK(r.status == g.status);
            if (g.status != Status::lit) {
                ++unlit;
                continue;
            }
            ++lit;
            CHECK(b.reflections == g.reflections);
            CHECK(r.reflections == g.reflections);
            CHECK(b.ray == g.ray);
            CHECK(r.ray == g.ray);
        }
    }
    CHECK(compared > cases / 2);
    CHECK(lit > cases / 2);
    CHECK(unlit > cases / 10);
}
