// The explicit state graph on small scenes: its size, injectivity, answers.
#include "orthoray/parse.hpp"
#include "orthoray/state_graph.hpp"

#include <catch2/catch.hpp>

using namespace orthoray;

TEST_CASE("state graph of a 3 x 5 box", "[graph]") {
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 5\nmirror x 3 y 0 5\nmirror y 0 x 0 3\n"
                               "mirror y 5 x 0 3\nray 0 0 1 1\ntarget 3 5\n");
    const auto report = explore_state_graph(s, 1000);
    REQUIRE(report);
    // 16 boundary lattice points (perimeter 16), 4 directions each.
    CHECK(report->states == 16 * 4);
    CHECK(report->injective);
    CHECK(report->answer.reason == Reason::hit);
    CHECK(report->answer.reflections == 6);
    // The ray retraces its path between the corners (0,0) and (3,5): the
    // walk from the start covers the 14 states of that period.
    CHECK(report->reachable == 14);
    CHECK_FALSE(explore_state_graph(s, 63));
}

TEST_CASE("state graph finds the period of a cycle", "[graph]") {
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 1\nmirror x 1 y 0 1\nmirror y 0 x 0 1\n"
                               "mirror y 1 x 0 1\nray 1/3 2/7 2 3\ntarget 0 0\n");
    const auto report = explore_state_graph(s, 100000);
    REQUIRE(report);
    CHECK(report->injective);
    CHECK(report->answer.reason == Reason::cycle);
    CHECK(report->answer.reflections == 10);
    CHECK(report->reachable == 10);
}
