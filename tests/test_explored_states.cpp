// The states the illumination search explored (engine/explored_states.hpp),
// counted by hand on scenes where stretches share states: a ray starting
// on another's way, two tails entering one cycle, and a ray's start left
// unexpanded inside a stretch walked. The property tests of
// test_illumination.cpp hold the count to the state graph on thousands of
// random scenes.
#include "orthoray/answer_json.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;

namespace {

const std::string box_with_splitter =
    "dim 2\nmirror x 0 y 0 5\nmirror x 7 y 0 5\nmirror y 0 x 0 7\nmirror y 5 x 0 7\n"
    "splitter x 3 y 1 4\nray 1 1 1 2\ntarget 100 100\ntarget 2 3\n";

// Every target unlit, so every reachable state is explored: the branch
// search's count must be `states`, and so must the state graph's.
void check_explored(const std::string& text, int states) {
    const Answer a = solve(read_scene(text));
    CHECK(a.engine == EngineUsed::branches);
    CHECK(a.reason == Reason::unlit);
    CHECK(a.states == states);
    CHECK(explore_illumination_graph(read_scene(text), 1000).states == states);
}

} // namespace

TEST_CASE("a ray starting on another's way shares its states", "[explored_states]") {
    // Ray 1: (0, 0) +x, then (4, 0) -x, which escapes. Ray 2 starts between
    // them and its first event's state is ray 1's second: 3 states, not 4.
    check_explored("dim 2\nmirror x 4 y -1 1\nray 0 0 1 0\nray 2 0 1 0\ntarget 9 9\n", 3);
}

TEST_CASE("a cycle entered at two states is counted once", "[explored_states]") {
    // Between x = 0 and x = 4: the cycle (4, 0) -x, (0, 0) +x. Ray 1 from
    // (1, 0) +x enters it at (4, 0) -x, ray 2 from (2, 0) -x at (0, 0) +x:
    // the two starts and the cycle's two states.
    check_explored("dim 2\nmirror x 0 y -1 1\nmirror x 4 y -1 1\n"
                   "ray 1 0 1 0\nray 2 0 -1 0\ntarget 9 9\n",
                   4);
}

TEST_CASE("two tails entering a cycle at one state share it", "[explored_states]") {
    // The one-way mirror x+ 2 turns back only rays moving -x: the cycle is
    // (4, 0) -x, (2, 0) +x. Rays from (1, 0) and (3, 0), both +x, pass x = 2
    // (ray 1) or start past it (ray 2) and enter at (4, 0) -x.
    check_explored("dim 2\nmirror x+ 2 y -1 1\nmirror x 4 y -1 1\n"
                   "ray 1 0 1 0\nray 3 0 1 0\ntarget 9 9\n",
                   4);
}

TEST_CASE("a ray's start left unexpanded inside a stretch counts once", "[explored_states]") {
    // Target 1 is lit by ray 1 before its first event, target 2 by ray 2
    // before its own: once ray 2 lights target 2 the search stops, and
    // ray 3 is never expanded. Its start (4, 0) -x is the state ray 1's
    // stretch reached: explored are ray 1's two states and ray 2's start.
    const Answer a = solve(read_scene("dim 2\nmirror x 4 y -1 1\n"
                                      "ray 0 0 1 0\nray 0 10 1 0\nray 4 0 -1 0\n"
                                      "target 1 0\ntarget 1 10\n"));
    CHECK(a.engine == EngineUsed::branches);
    CHECK(a.reason == Reason::lit);
    CHECK(a.states == 3);
}

TEST_CASE("a closed box with a splitter: every reachable state", "[explored_states]") {
    // The stretches from ray 1's start and from a state leaving the
    // splitter merge (the ray starts between events), so the sum of their
    // lengths would be 50.
    check_explored(box_with_splitter, 45);
}

TEST_CASE("a limit met while counting keeps the answer and flags the count", "[explored_states]") {
    // Byte budgets from what the search ends up holding upwards: below some
    // budget the search stops (a memory limit), above it the count too
    // finds room; in between the search answers and the count, whose
    // arrays find none, is given up.
    const Scene s = read_scene(box_with_splitter);
    const Answer full = solve(s);
    REQUIRE(full.reason == Reason::unlit);
    CHECK_FALSE(full.states_lower_bound);
    CHECK(answer_json_members(full, "auto", 0).find("states_lower_bound") == std::string::npos);
    int stopped = 0, given_up = 0, counted = 0;
    for (std::size_t extra = 0; extra < 4096; extra += 8) {
        SolveOptions tight;
        tight.max_state_bytes = full.stats.illumination.state_bytes + extra;
        const Answer a = solve(s, tight);
        CHECK(a.states_lower_bound == (a.reason == Reason::limit || a.states != full.states));
        if (a.reason == Reason::limit) {
            CHECK(counted + given_up == 0); // more room never stops the search
            ++stopped;
            continue;
        }
        CHECK(a.reason == Reason::unlit);
        REQUIRE(a.targets.size() == full.targets.size());
        for (std::size_t t = 0; t < a.targets.size(); ++t) {
            CHECK(a.targets[t].status == full.targets[t].status);
            CHECK(a.targets[t].reflections == full.targets[t].reflections);
        }
        if (a.states_lower_bound) {
            CHECK(counted == 0);
            CHECK(a.states == 9); // the branch states stored
            CHECK(answer_json_members(a, "auto", 0).find(",\"states_lower_bound\":true") !=
                  std::string::npos);
            ++given_up;
        } else {
            CHECK(a.states == full.states);
            ++counted;
        }
    }
    CHECK(stopped > 0);
    CHECK(given_up > 0);
    CHECK(counted > 0);
}

TEST_CASE("explored states equal the state graph's where many rays share cycles",
          "[explored_states][property]") {
    // Closed boxes with one-sided mirrors and up to five rays, some started
    // on others' branches: tails merge and several rays run into one
    // cycle. With every target unlit the search explores every reachable
    // state, and the graph counts them.
    std::mt19937_64 rng(2026'11'30);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 10;
    shape.one_sided_percent = 50;
    shape.max_rays = 2;
    shape.max_targets = 1;
    shape.scene.box_percent = 80;
    const int cases = test::case_count(1500);
    int compared = 0, shared = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 2;
        Scene s = test::random_optics_scene(rng, shape);
        // More rays from points on the branches, along the first ray's
        // direction with random signs: often on another ray's way.
        const int more = test::pick(rng, 1, 3);
        for (int r = 0; r < more; ++r) {
            Ray ray = s.rays.front();
            ray.start = test::point_on_a_branch(rng, s);
            for (int j = 0; j < s.dim; ++j)
                if (test::chance(rng, 50)) ray.direction[j] = -ray.direction[j];
            s.rays.push_back(ray);
        }
        const Answer graph = explore_illumination_graph(s, 20000);
        if (graph.reason != Reason::unlit) continue;
        ++compared;
        INFO("case " << i << "\n" << write_scene(s));
        CHECK(solve(s).states == graph.states);
        // Do the rays share states? Then their separate counts add to more.
        Integer apart = 0;
        for (const Ray& r : s.rays) {
            Scene one = s;
            one.rays = {r};
            one.targets.push_back(one.targets.front()); // still the illumination question
            apart += explore_illumination_graph(one, 20000).states;
        }
        shared += apart > graph.states;
    }
    CHECK(compared > cases / 3);
    CHECK(shared > compared / 4);
}
