// Property test: on thousands of seeded random scenes the default engine (on
// all three integer paths and with both cycle detectors), the reference tracer and
// the explicit state graph agree on answer, reason and reflections, and every
// certificate the default engine writes passes the independent verifier.
#include "support/case_count.hpp"
#include "support/random_scene.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace orthoray;

namespace {

constexpr std::uint64_t step_cap = 4000;

// Never stops a run, but makes the engine step in chunks (the first ones
// short), so that every chunk boundary must resume exactly where it paused.
class Watcher : public RunMonitor {
public:
    std::optional<Limit> poll(std::uint64_t) override { return std::nullopt; }
};

Answer run(const Scene& scene, Engine engine, CycleDetector detector = CycleDetector::first_state,
           Arithmetic arithmetic = Arithmetic::automatic, std::uint64_t cap = step_cap,
           Shooter shooter = Shooter::automatic) {
    SolveOptions o;
    o.shooter = shooter;
    o.engine = engine;
    o.cycle_detector = detector;
    o.arithmetic = arithmetic;
    o.max_steps = cap;
    return solve(scene, o);
}

std::string summary(const Answer& a) {
    return std::string(to_string(a.reason)) + " " + a.reflections.get_str();
}

struct Tally {
    int scenes = 0, graph_checked = 0, decided = 0;
    int by_reason[5] = {};

    std::string summary() const {
        std::ostringstream out;
        out << "decided " << decided << ", graph " << graph_checked
            << ", hit/escape/absorbed/cycle/limit " << by_reason[0] << "/" << by_reason[1] << "/"
            << by_reason[2] << "/" << by_reason[3] << "/" << by_reason[4];
        return out.str();
    }
};

void check_scene(const Scene& scene, Tally& tally) {
    INFO("scene:\n" << write_scene(scene));
    const Answer lattice = run(scene, Engine::lattice);
    const Answer reference = run(scene, Engine::reference);
    REQUIRE(summary(lattice) == summary(reference));
    for (Shooter shooter : {Shooter::grid, Shooter::bvh, Shooter::pieces, Shooter::section}) {
        if (shooter == Shooter::pieces && scene.dim != 2) continue; // refused: 2D tables
        REQUIRE(summary(run(scene, Engine::lattice, CycleDetector::first_state,
                            Arithmetic::automatic, step_cap, shooter)) == summary(lattice));
    }
    {
        Watcher watcher;
        SolveOptions o;
        o.shooter = scene.dim == 2 ? Shooter::pieces : Shooter::automatic;
        o.max_steps = step_cap;
        o.monitor = &watcher;
        REQUIRE(summary(solve(scene, o)) == summary(lattice));
    }
    for (Arithmetic wider : {Arithmetic::int128, Arithmetic::wide})
        REQUIRE(summary(run(scene, Engine::lattice, CycleDetector::first_state, wider)) ==
                summary(lattice));

    // Brent notices a cycle up to about twice as late: give it room, then it
    // must agree wherever the first-state detector decided.
    const Answer brent =
        run(scene, Engine::lattice, CycleDetector::brent, Arithmetic::automatic, 4 * step_cap);
    if (lattice.decided()) REQUIRE(summary(brent) == summary(lattice));

    if (auto graph = explore_state_graph(scene, 20'000)) {
        REQUIRE(graph->injective); // reflection is reversible
        if (lattice.decided()) REQUIRE(summary(graph->answer) == summary(lattice));
        ++tally.graph_checked;
    }

    std::stringstream cert;
    CertificateWriter writer(cert, scene);
    SolveOptions o;
    o.max_steps = step_cap;
    writer.attach(o);
    const Answer certified = solve(scene, o);
    writer.finish(certified);
    REQUIRE(summary(certified) == summary(lattice));
    const Verdict verdict = verify_certificate(scene, cert);
    INFO("certificate:\n" << cert.str());
    REQUIRE(verdict.valid == lattice.decided());

    ++tally.scenes;
    tally.decided += lattice.decided();
    ++tally.by_reason[static_cast<int>(lattice.reason)];
}

void run_family(std::uint64_t seed, int count, const test::RandomSceneShape& shape, Tally& tally) {
    std::mt19937_64 rng(seed);
    for (int i = 0; i < count; ++i) {
        Scene scene = test::random_scene(rng, shape);
        scene.target() = test::random_target(rng, scene, shape);
        check_scene(scene, tally);
    }
}

} // namespace

TEST_CASE("engines, state graph and verifier agree on random 2D scenes", "[property][slow]") {
    Tally tally;
    test::RandomSceneShape rational{2, 12, 6, 3, 3}, integral{2, 12, 6, 1, 2};
    run_family(20261122, test::case_count(1500), rational, tally);
    run_family(424242, test::case_count(1500), integral, tally);
    WARN("2D: " << tally.summary());
    // The families must exercise every outcome and the graph cross-check.
    for (Reason r : {Reason::hit, Reason::escape, Reason::absorbed, Reason::cycle})
        CHECK(tally.by_reason[static_cast<int>(r)] > test::case_count(100));
    CHECK(tally.graph_checked > test::case_count(1500));
}

TEST_CASE("engines, state graph and verifier agree on random 3D scenes", "[property][slow]") {
    Tally tally;
    test::RandomSceneShape rational{3, 12, 4, 2, 2}, integral{3, 10, 3, 1, 1};
    run_family(77, test::case_count(1000), rational, tally);
    run_family(31337, test::case_count(1000), integral, tally);
    WARN("3D: " << tally.summary());
    for (Reason r : {Reason::hit, Reason::escape, Reason::absorbed, Reason::cycle})
        CHECK(tally.by_reason[static_cast<int>(r)] > test::case_count(30));
    CHECK(tally.graph_checked > test::case_count(500));
}
