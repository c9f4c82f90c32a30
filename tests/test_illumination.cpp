// The space-bounded illumination search (docs/optics.md): against the
// explicit state graph on thousands of seeded random scenes, at limits
// (steps and a byte budget: lit targets exact, the rest unknown, never a
// wrong unlit), with and without a certificate's full exploration, and the
// memory of a long one-sided stretch, which must not grow with its length.
#include "engine/branch_state_set.hpp"
#include "engine/illumination.hpp"
#include "orthoray/answer_json.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

#include <tuple>

using namespace orthoray;

namespace {

using Status = TargetAnswer::Status;

// An observer that only counts, so the search explores everything as it
// does for a certificate.
struct CountingObserver : IlluminationObserver {
    std::size_t branches = 0, steps = 0;
    void branch(const Vector&, const Vector&, std::size_t, std::uint64_t) override { ++branches; }
    void lit(std::size_t, std::uint64_t, std::size_t) override {}
    void step(const Vector&, const Vector&) override { ++steps; }
    void unlit(std::size_t) override {}
    void unknown(std::size_t) override {}
};

// At a limit: never unlit; a lit target is lit, with the least count when
// the search says it is proven and with one no smaller otherwise.
void check_partial(const Answer& partial, const Answer& full) {
    REQUIRE(partial.targets.size() == full.targets.size());
    for (std::size_t t = 0; t < full.targets.size(); ++t) {
        const TargetAnswer& p = partial.targets[t];
        const TargetAnswer& f = full.targets[t];
        CHECK(p.status != Status::unlit);
        if (p.status != Status::lit) continue;
        CHECK(f.status == Status::lit);
        if (p.best_proven) {
            CHECK(p.reflections == f.reflections);
            CHECK(p.ray == f.ray);
        } else {
            CHECK_FALSE(std::tie(p.reflections, p.ray) < std::tie(f.reflections, f.ray));
        }
    }
}

} // namespace

TEST_CASE("branch-state search agrees with the state graph on splitter-rich scenes",
          "[illumination][property]") {
    std::mt19937_64 rng(1215);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 50;
    shape.one_sided_percent = 30;
    shape.max_rays = 4;
    shape.max_targets = 4;
    shape.scene.max_elements = 8;
    const int cases = test::case_count(1500);
    int compared = 0, lit = 0, unlit = 0, inside = 0, graph_cut = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        const Scene s = test::random_optics_scene(rng, shape);
        if (s.single_trajectory()) continue;
        const Answer graph = explore_illumination_graph(s, 20000);
        if (!graph.decided()) continue;
        ++compared;
        INFO("case " << i << "\n" << write_scene(s));
        // Stopping early, and exploring everything as for a certificate.
        SolveOptions full;
        CountingObserver observer;
        full.illumination_observer = &observer;
        const Answer a = solve(s, full);
        // Every reachable state explored: optics.md's `states` is the
        // graph's; the certificate lists the branch states among them.
        CHECK(a.states == graph.states);
        CHECK(observer.branches <= a.states.get_ui());
        inside += observer.branches < a.states.get_ui();
        const Answer early = solve(s);
        if (early.reason == Reason::unlit)
            CHECK(early.states == graph.states);
        else
            CHECK(early.states <= graph.states); // stopped once every target was lit
        for (const Answer& b : {early, a}) {
            CHECK(b.reason == graph.reason);
            CHECK(b.reflections == graph.reflections);
            REQUIRE(b.targets.size() == graph.targets.size());
            for (std::size_t t = 0; t < b.targets.size(); ++t) {
                CHECK(b.targets[t].status == graph.targets[t].status);
                CHECK(b.targets[t].reflections == graph.targets[t].reflections);
                CHECK(b.targets[t].ray == graph.targets[t].ray);
            }
        }
        for (const TargetAnswer& t : a.targets) (t.status == Status::lit ? lit : unlit) += 1;
        // A random cap on the events stepped: a limit or the answer.
        SolveOptions capped;
        capped.max_steps = static_cast<std::uint64_t>(uniform(rng, 0, 6));
        const Answer c = solve(s, capped);
        if (c.reason == Reason::limit)
            check_partial(c, graph);
        else
            CHECK(c.reason == graph.reason);
        // The graph itself cut short after a random number of its states.
        const std::uint64_t expanded = test::pick_index(rng, 0, graph.states.get_ui());
        const Answer g = explore_illumination_graph(s, 20000, nullptr, expanded);
        if (g.reason == Reason::limit) {
            ++graph_cut;
            CHECK(g.limit == Limit::steps);
            check_partial(g, graph);
        } else {
            CHECK(g.reason == graph.reason);
            for (std::size_t t = 0; t < g.targets.size(); ++t) {
                CHECK(g.targets[t].status == graph.targets[t].status);
                CHECK(g.targets[t].reflections == graph.targets[t].reflections);
                CHECK(g.targets[t].ray == graph.targets[t].ray);
            }
        }
        // And by its ceiling on the states it may hold: a memory limit.
        const std::uint64_t ceiling = test::pick_index(rng, 1, graph.states.get_ui());
        const Answer m = explore_illumination_graph(s, ceiling);
        if (m.reason == Reason::limit) {
            CHECK(m.limit == Limit::memory);
            check_partial(m, graph);
        } else {
            CHECK(m.reason == graph.reason);
        }
    }
    CHECK(graph_cut > compared / 2);
    CHECK(compared > cases / 2);
    CHECK(lit > 0);
    CHECK(unlit > 0);
    CHECK(inside > compared / 4); // states inside stretches are really counted
}

TEST_CASE("a byte budget ends the search with Limit::memory and no wrong answer",
          "[illumination]") {
    std::mt19937_64 rng(1216);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 70;
    shape.one_sided_percent = 10;
    shape.scene.max_elements = 10;
    shape.scene.box_percent = 80;
    int limited = 0, lit_at_limit = 0;
    for (int i = 0; i < test::case_count(200); ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        const Scene s = test::random_optics_scene(rng, shape);
        if (s.single_trajectory()) continue;
        const Answer full = solve(s);
        REQUIRE(full.decided());
        SolveOptions options;
        options.max_state_bytes = 1500;
        const Answer a = solve(s, options);
        INFO("case " << i << "\n" << write_scene(s));
        CHECK(a.stats.illumination.state_bytes <= 1500);
        if (a.reason != Reason::limit) {
            CHECK(a.reason == full.reason);
            continue;
        }
        ++limited;
        CHECK(a.limit == Limit::memory);
        check_partial(a, full);
        for (const TargetAnswer& t : a.targets) lit_at_limit += t.status == Status::lit;
    }
    CHECK(limited > 10);
    CHECK(lit_at_limit > 0);
}

TEST_CASE("a long one-sided stretch stores no states", "[illumination]") {
    // Ray 1 runs in a 997 x 1000 box along (1, 1): its orbit visits every
    // boundary point of its class before it closes, thousands of events.
    // The one-way mirror x+ 500 lets it cross one way only, so the stretch
    // is a rho (a tail, then a cycle on one side). A splitter far away,
    // met only by ray 2, makes this the illumination question.
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 1000\nmirror x 997 y 0 1000\n"
                               "mirror y 0 x 0 997\nmirror y 1000 x 0 997\n"
                               "mirror x+ 500 y 0 1000\nsplitter x 5000 y -10 10\n"
                               "ray 1 0 1 1\nray 4000 0 1 0\n"
                               "target 5000 5000\ntarget 3000 0\n");
    const Answer a = solve(s);
    REQUIRE(a.targets.size() == 2);
    CHECK(a.targets[0].status == Status::unlit);
    CHECK(a.targets[1].status == Status::lit); // ray 2's reflected branch, back along y = 0
    CHECK(a.targets[1].reflections == 1);
    CHECK(a.targets[1].ray == 2);
    // Every state of the rho is counted (by walking it again), none stored.
    CHECK(a.states == explore_illumination_graph(s, 100000).states);
    CHECK(a.states > 2000);
    CHECK(a.stats.illumination.events > 2000);
    CHECK(a.stats.illumination.state_bytes < 4096);
}

TEST_CASE("max_steps caps the events of one endless stretch", "[illumination]") {
    // Found by fuzz_solve: a direction of slope ~7.8e74 in a 6 x 5 box
    // bounces ~10^74 times between y = 0 and y = 5 before it first meets
    // the one-way mirror, so the single stretch from the ray's start never
    // ends in practice. A cap on the branch states expanded (one here)
    // never stopped it; the cap on events does, after exactly that many.
    const Scene s = read_scene(
        "dim 2\nmirror x- 0 y 0 4\nmirror x 6 y 0 4\nmirror y 0 x 0 6\nmirror y 5 x 0 6\n"
        "mirror x+ 3 y 1 3\nray 1 1 1 "
        "777777777777777777777777777777777777777777777777777777777777777777777777771\n"
        "target 2 1\ntarget 2 1\n");
    SolveOptions options;
    options.max_steps = 2000;
    const Answer a = solve(s, options);
    CHECK(a.reason == Reason::limit);
    CHECK(a.limit == Limit::steps);
    CHECK(a.stats.illumination.events == 2000);
    for (const TargetAnswer& t : a.targets) CHECK(t.status == Status::unknown);
}

TEST_CASE("a cap reports a target at a ray's start, and one passed once its count is final",
          "[illumination]") {
    // Found by a conformance audit against optics.md ("a resource limit ...
    // reports the targets lit so far"). Both engines that honour the cap
    // must say the same.
    auto capped = [](const char* text, std::uint64_t cap, Engine engine) {
        SolveOptions options;
        options.max_steps = cap;
        options.engine = engine;
        return solve(read_scene(text), options);
    };
    for (const Engine engine : {Engine::automatic, Engine::reference}) {
        INFO("engine " << static_cast<int>(engine));
        // The target is ray 1's start: lit with 0 reflections before any step.
        const char* at_start = "dim 2\nray 0 1 1 0\nray 5 5 0 1\ntarget 0 1\n";
        const Answer a = capped(at_start, 0, engine);
        CHECK(a.reason == Reason::lit);
        REQUIRE(a.targets.size() == 1);
        CHECK(a.targets[0].status == Status::lit);
        CHECK(a.targets[0].reflections == 0);
        CHECK(a.targets[0].ray == 1);
        // Between two mirrors, the ray passes the target on its second
        // segment (1 reflection) and nothing waits: the answer is complete
        // after two events, although the stretch bounces on for ever.
        const char* between = "dim 2\nmirror x 0 y 0 1\nmirror x 1 y 0 1\n"
                              "splitter y 50 x 50 51\nray 1/2 1/2 1 0\ntarget 0 1/2\n";
        for (const std::uint64_t cap : {2u, 3u, 1000u}) {
            const Answer b = capped(between, cap, engine);
            CHECK(b.reason == Reason::lit);
            CHECK(b.targets[0].reflections == 1);
            CHECK(b.targets[0].ray == 1);
        }
        const Answer c = capped(between, 1, engine);
        CHECK(c.reason == Reason::limit);
        CHECK(c.targets[0].status == Status::unknown);
    }
    // The graph engine caps the states it expands. Cut short, it proves a
    // count least only when nothing can beat it (0 reflections from ray 1),
    // but reports every target lit so far.
    {
        const Answer a = capped("dim 2\nray 0 1 1 0\nray 5 5 0 1\ntarget 0 1\n", 0, Engine::graph);
        CHECK(a.reason == Reason::lit);
        CHECK(a.targets[0].reflections == 0);
        CHECK(a.targets[0].ray == 1);
        const char* between = "dim 2\nmirror x 0 y 0 1\nmirror x 1 y 0 1\n"
                              "splitter y 50 x 50 51\nray 1/2 1/2 1 0\ntarget 0 1/2\n";
        const Answer b = capped(between, 1, Engine::graph);
        CHECK(b.reason == Reason::limit);
        CHECK(b.limit == Limit::steps);
        CHECK(b.targets[0].status == Status::unknown);
        const Answer c = capped(between, 2, Engine::graph);
        CHECK(c.reason == Reason::limit);
        CHECK(c.targets[0].status == Status::lit);
        CHECK(c.targets[0].reflections == 1);
        CHECK_FALSE(c.targets[0].best_proven);
        const Answer d = capped(between, 1000, Engine::graph);
        CHECK(d.reason == Reason::lit);
        CHECK(d.targets[0].reflections == 1);
        CHECK(d.targets[0].best_proven);
    }
    // The branch search in the middle of one long stretch: the segment
    // after 5 reflections passes the target, and once it is stepped (event
    // 6) the count is final, since later segments come after more
    // reflections and nothing else waits; with 5 events it is unknown.
    const char* channel = "dim 2\nmirror x 0 y -100 100\nmirror x 1 y -100 100\n"
                          "splitter y 500 x 50 51\nray 1/2 0 1 1\ntarget 1/2 5\n";
    const Answer early = capped(channel, 5, Engine::automatic);
    CHECK(early.reason == Reason::limit);
    CHECK(early.targets[0].status == Status::unknown);
    const Answer late = capped(channel, 7, Engine::automatic);
    CHECK(late.reason == Reason::lit);
    CHECK(late.targets[0].reflections == 5);
    CHECK(late.stats.illumination.events <= 7);
    // With a second target no branch reaches, the cap ends the run; the
    // first target's count is final all the same (the stretch cut short
    // can only offer 6 reflections or more), so it is reported.
    const std::string two = std::string(channel) + "target 100 100\n";
    const Answer cut = capped(two.c_str(), 20, Engine::automatic);
    CHECK(cut.reason == Reason::limit);
    REQUIRE(cut.targets.size() == 2);
    CHECK(cut.targets[0].status == Status::lit);
    CHECK(cut.targets[0].reflections == 5);
    CHECK(cut.targets[1].status == Status::unknown);
    // Two rays in two channels: ray 1's stretch passes the target after 5
    // reflections, but ray 2 waits with (0, ray 2) and could still pass it
    // with fewer. A cap that ends ray 1's stretch first reports the target
    // lit (optics.md: the targets lit so far), its count the best so far.
    const char* channels = "dim 2\nmirror x 0 y -10 10\nmirror x 1 y -10 10\n"
                           "mirror x 100 y -1000 1000\nmirror x 101 y -1000 1000\n"
                           "ray 1/2 0 1 1\nray 201/2 0 1 1\ntarget 1/2 5\n";
    const Answer unproven = capped(channels, 8, Engine::automatic);
    CHECK(unproven.reason == Reason::limit);
    REQUIRE(unproven.targets.size() == 1);
    CHECK(unproven.targets[0].status == Status::lit);
    CHECK(unproven.targets[0].reflections == 5);
    CHECK(unproven.targets[0].ray == 1);
    CHECK_FALSE(unproven.targets[0].best_proven);
    CHECK(answer_json_members(unproven, "branches", 0).find("\"best_proven\":false") !=
          std::string::npos);
    const Answer whole = capped(channels, 1000, Engine::automatic);
    CHECK(whole.reason == Reason::lit);
    CHECK(whole.targets[0].best_proven);
}

TEST_CASE("the branch state set keeps states exactly and compactly", "[illumination]") {
    Scene s = read_scene("dim 3\nray 0 0 0 1 2 3\nray 0 0 0 -2 -4 -6\ntarget 1 1 1\n");
    engine::ByteBudget budget(std::nullopt);
    engine::BranchStateSet set(s, budget);
    std::mt19937_64 rng(1217);
    std::vector<std::pair<Vector, Vector>> kept;
    for (int i = 0; i < 2000; ++i) {
        Vector p, v{1, 2, 3};
        for (int j = 0; j < 3; ++j) {
            // Small and huge numerators, a few denominators, both signs.
            Rational q(Integer(static_cast<long>(uniform(rng, -300, 300))),
                       Integer(static_cast<long>(uniform(rng, 1, 4))));
            if (i % 50 == 0) q *= Rational(Integer("123456789012345678901234567890"));
            q.canonicalize();
            p[j] = q;
            if (test::chance(rng, 50)) v[j] = -v[j];
        }
        if (i % 3 == 0) v = Vector{2 * v[0], 2 * v[1], 2 * v[2]}; // ray 2's class
        // Every seventh state is one kept before, met again among the others.
        if (i % 7 == 6) std::tie(p, v) = kept[uniform(rng, 0, static_cast<int>(kept.size()) - 1)];
        const auto at = set.insert(p, v);
        REQUIRE(at);
        if (at->added) {
            CHECK(at->index == kept.size());
            kept.emplace_back(p, v);
        } else {
            CHECK(kept[at->index] == std::make_pair(p, v));
        }
    }
    CHECK(set.size() == kept.size());
    CHECK(kept.size() < 2000 - 250); // the repeats were found
    for (std::uint32_t i = 0; i < kept.size(); ++i) {
        Vector p, v;
        set.state(i, p, v);
        CHECK(std::make_pair(p, v) == kept[i]);
        const auto again = set.insert(p, v);
        CHECK((again && !again->added && again->index == i));
    }
    // Mostly 2-byte coordinates: well under 16 bytes of key per state.
    CHECK(set.key_bytes() < 16 * kept.size());
    // A budget that cannot hold the next state refuses it, changing nothing.
    engine::ByteBudget tight(400);
    engine::BranchStateSet small(s, tight);
    std::size_t added = 0;
    for (int i = 0; i < 100; ++i)
        if (small.insert(Vector{i, 0, 0}, Vector{1, 2, 3})) ++added;
    CHECK(added > 0);
    CHECK(added < 100);
    CHECK(small.size() == added);
    CHECK(tight.used() <= 400);
}

TEST_CASE("branch search and reference search agree with the state graph on 5000 scenes",
          "[illumination][property][slow]") {
    // Three readings of the illumination question: the default search over
    // branch states, the reference search that stores every exact state in
    // a map, and Boost.Graph's BFS and Dijkstra over the explicit graph.
    // Every target's status, least reflections and ray must agree, and with
    // a target unlit the states explored (all that are reachable).
    std::mt19937_64 rng(50'000);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 35;
    shape.one_sided_percent = 30;
    shape.scene.max_elements = 7;
    const int cases = test::case_count(5000);
    int compared = 0, lit = 0, unlit = 0;
    SolveOptions reference;
    reference.engine = Engine::reference;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        shape.max_rays = 1 + i % 3;
        shape.max_targets = 1 + (i / 3) % 3;
        const Scene s = test::random_optics_scene(rng, shape);
        if (s.single_trajectory()) continue;
        const Answer graph = explore_illumination_graph(s, 20000);
        if (!graph.decided()) continue;
        ++compared;
        INFO("case " << i << "\n" << write_scene(s));
        const Answer branches = solve(s), plain = solve(s, reference);
        CHECK(branches.engine == EngineUsed::branches);
        CHECK(plain.engine == EngineUsed::reference);
        for (const Answer* a : {&branches, &plain}) {
            CHECK(a->reason == graph.reason);
            CHECK(a->reflections == graph.reflections);
            // A target unlit: every reachable state was explored.
            if (graph.reason == Reason::unlit) CHECK(a->states == graph.states);
            REQUIRE(a->targets.size() == graph.targets.size());
            for (std::size_t t = 0; t < a->targets.size(); ++t) {
                CHECK(a->targets[t].status == graph.targets[t].status);
                CHECK(a->targets[t].reflections == graph.targets[t].reflections);
                CHECK(a->targets[t].ray == graph.targets[t].ray);
            }
        }
        for (const TargetAnswer& t : graph.targets) (t.status == Status::lit ? lit : unlit) += 1;
    }
    CHECK(compared > cases * 3 / 5);
    CHECK(lit > compared / 2);
    CHECK(unlit > compared / 4);
}
