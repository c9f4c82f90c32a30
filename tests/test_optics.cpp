// docs/optics.md end to end: hand-derived scenes with one-way mirrors,
// splitters and several rays; rho-shaped trajectories against a direct
// computation that stores every state; the illumination engine against the
// lattice engine run once per ray and target.
#include "engine/reference_step.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"
#include "support/case_count.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <optional>
#include <tuple>

using namespace orthoray;

namespace {

using Status = TargetAnswer::Status;

void check_lit(const TargetAnswer& t, int reflections, std::size_t ray) {
    CHECK(t.status == Status::lit);
    CHECK(t.reflections == reflections);
    CHECK(t.ray == ray);
}

} // namespace

TEST_CASE("a one-way mirror makes a rho-shaped cycle", "[optics]") {
    // The ray bounces off x = 0 (state 1), passes the back of the one-way
    // mirror x+ 5, and then cycles between x = 10 and the mirror's front:
    // states (10, -), (5, +), (10, -), ... so mu = 2, lambda = 2.
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 10\nmirror x 10 y 0 10\n"
                               "mirror x+ 5 y 0 10\nray 2 3 -1 0\ntarget 100 100\n");
    for (CycleDetector detector : {CycleDetector::first_state, CycleDetector::brent}) {
        SolveOptions options;
        options.cycle_detector = detector; // first-state is overridden: it would loop
        const Answer a = solve(s, options);
        CHECK(a.reason == Reason::cycle);
        CHECK(a.tail == 1);
        CHECK(a.period() == 2);
        CHECK(a.reflections == 3);
        CHECK(a.engine == EngineUsed::lattice);
    }
    // A target on the tail is hit; one on the cycle too.
    Scene on_tail = s;
    on_tail.target() = Vector{7, 3, 0};
    CHECK(solve(on_tail).reason == Reason::hit);
    CHECK(solve(on_tail).reflections == 1);
}

TEST_CASE("a splitter lights targets on both of its branches", "[optics]") {
    const Scene s = read_scene("dim 2\nsplitter x 2 y -1 1\ntarget 5 0\ntarget -3 0\n"
                               "target 2 -3\nray 0 0 1 0\n");
    const Answer a = solve(s);
    CHECK(a.reason == Reason::unlit);
    REQUIRE(a.targets.size() == 3);
    check_lit(a.targets[0], 0, 1); // straight through: no reflection
    check_lit(a.targets[1], 1, 1); // reflected back
    CHECK(a.targets[2].status == Status::unlit);
    CHECK(a.states == 3); // the start and the two states leaving the splitter
    CHECK(a.engine == EngineUsed::branches);

    Scene lit = s;
    lit.targets.pop_back();
    CHECK(solve(lit).reason == Reason::lit);
}

TEST_CASE("the least reflections win, ties go to the least-numbered ray", "[optics]") {
    // Ray 1 reaches (0, 2) after one reflection off x = 3; rays 2 and 3
    // reach it straight away; ray 2 is the least-numbered of those.
    const Scene s = read_scene("dim 2\nmirror x 3 y -5 5\ntarget 0 2\n"
                               "ray 2 2 1 0\nray 0 -1 0 1\nray 0 5 0 -1\n");
    const Answer a = solve(s);
    CHECK(a.reason == Reason::lit);
    REQUIRE(a.targets.size() == 1);
    check_lit(a.targets[0], 0, 2);
    // Without the straight rays, ray 1's reflection lights it.
    Scene one = s;
    one.rays.resize(1);
    one.targets.push_back(Vector{9, 9, 0}); // a second target keeps it illumination
    const Answer b = solve(one);
    check_lit(b.targets[0], 1, 1);
    CHECK(b.targets[1].status == Status::unlit);
    // A target at a ray's start is lit with 0 reflections by that ray; at
    // ray 3's start it is also on ray 2's way, and ray 2 wins the tie.
    Scene at_start = s;
    at_start.targets = {Vector{2, 2, 0}, Vector{0, 5, 0}};
    const Answer c = solve(at_start);
    check_lit(c.targets[0], 0, 1);
    check_lit(c.targets[1], 0, 2);
}

TEST_CASE("illumination stops at max_steps with the lit targets kept", "[optics]") {
    const Scene s = read_scene("dim 2\nsplitter x 2 y -1 1\ntarget 0 0\ntarget -3 0\n"
                               "ray 0 0 1 0\n");
    SolveOptions options;
    options.max_steps = 1;
    const Answer a = solve(s, options);
    CHECK(a.reason == Reason::limit);
    CHECK(a.limit == Limit::steps);
    check_lit(a.targets[0], 0, 1);
    CHECK(a.targets[1].status == Status::unknown);
}

namespace {

// The single trajectory computed directly: every state s_1, s_2, ... goes
// into a map with its index, so mu and lambda are read off the first
// repeat. nullopt when it takes more than `cap` events.
std::optional<Answer> direct_answer(const Scene& scene, std::uint64_t cap) {
    std::map<std::pair<Vector, Vector>, std::uint64_t> seen;
    Vector p = scene.ray().start, v = scene.ray().direction;
    Answer a;
    for (std::uint64_t i = 0; i < cap; ++i) {
        const engine::ReferenceEvent e = engine::reference_step(scene, p, v);
        a.reflections = Integer(static_cast<unsigned long>(i));
        if (engine::reference_passes(scene, scene.target(), p, v, e)) {
            a.reason = Reason::hit;
            return a;
        }
        if (e.escape || e.absorbed) {
            a.reason = e.escape ? Reason::escape : Reason::absorbed;
            return a;
        }
        p = e.point;
        v = e.direction;
        const auto [it, added] = seen.emplace(std::make_pair(p, v), i + 1);
        if (!added) { // s_{i+1} = s_mu: mu - 1 + lambda = i
            a.reason = Reason::cycle;
            a.tail = Integer(static_cast<unsigned long>(it->second - 1));
            return a;
        }
    }
    return std::nullopt;
}

} // namespace

TEST_CASE("rho cycles agree with a direct computation", "[optics][property]") {
    std::mt19937_64 rng(1212);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 0;
    shape.one_sided_percent = 50;
    shape.max_rays = 1;
    shape.max_targets = 1;
    int rho = 0, decided = 0;
    const int cases = test::case_count(600);
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        shape.scene.box_percent = 70;
        const Scene s = test::random_optics_scene(rng, shape);
        const std::optional<Answer> direct = direct_answer(s, 20000);
        if (!direct) continue;
        ++decided;
        const Answer a = solve(s);
        INFO("case " << i << "\n" << write_scene(s));
        CHECK(a.reason == direct->reason);
        CHECK(a.reflections == direct->reflections);
        CHECK(a.tail == direct->tail);
        rho += a.tail > 0;
    }
    CHECK(decided > cases * 9 / 10);
    CHECK(rho > 0); // the test sees tails, not only pure cycles
}

TEST_CASE("illumination agrees with the lattice engine run per ray and target",
          "[optics][property]") {
    // Without splitters every ray has one branch, so target t is lit by the
    // least (reflections, ray) over the single trajectories that hit it.
    std::mt19937_64 rng(1213);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 0;
    shape.one_sided_percent = 0;
    const int cases = test::case_count(400);
    int lit = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        const Scene s = test::random_optics_scene(rng, shape);
        if (s.single_trajectory()) continue; // not the illumination question
        const Answer a = solve(s);
        INFO("case " << i << "\n" << write_scene(s));
        REQUIRE(a.targets.size() == s.targets.size());
        for (std::size_t t = 0; t < s.targets.size(); ++t) {
            std::optional<std::pair<Integer, std::size_t>> best;
            for (std::size_t r = 0; r < s.rays.size(); ++r) {
                Scene single = s;
                single.rays = {s.rays[r]};
                single.targets = {s.targets[t]};
                const Answer one = solve(single);
                REQUIRE(one.decided());
                if (one.reason == Reason::hit && (!best || one.reflections < best->first))
                    best = std::make_pair(one.reflections, r + 1);
            }
            if (!best) {
                CHECK(a.targets[t].status == Status::unlit);
                continue;
            }
            ++lit;
            CHECK(a.targets[t].status == Status::lit);
            CHECK(a.targets[t].reflections == best->first);
            CHECK(a.targets[t].ray == best->second);
        }
    }
    CHECK(lit > cases / 2);
}

TEST_CASE("illumination: the branch search (lattice stepper) and the state graph agree",
          "[optics][property]") {
    std::mt19937_64 rng(1214);
    test::RandomOpticsShape shape;
    shape.scene.max_elements = 8;
    const int cases = test::case_count(3000);
    int compared = 0, lit = 0, unlit = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        const Scene s = test::random_optics_scene(rng, shape);
        if (s.single_trajectory()) continue;
        const Answer graph = explore_illumination_graph(s, 200000);
        if (!graph.decided()) continue;
        ++compared;
        const Answer a = solve(s);
        INFO("case " << i << "\n" << write_scene(s));
        CHECK(a.reason == graph.reason);
        REQUIRE(a.targets.size() == graph.targets.size());
        for (std::size_t t = 0; t < a.targets.size(); ++t) {
            CHECK(a.targets[t].status == graph.targets[t].status);
            CHECK(a.targets[t].reflections == graph.targets[t].reflections);
            CHECK(a.targets[t].ray == graph.targets[t].ray);
            (a.targets[t].status == Status::lit ? lit : unlit) += 1;
        }
    }
    CHECK(compared > cases / 2);
    CHECK(lit > 0);
    CHECK(unlit > 0);
}
