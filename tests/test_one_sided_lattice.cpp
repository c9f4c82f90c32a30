// The lattice engine on single trajectories with one-sided elements
// (docs/optics.md): every shooter, integer type and engine option against
// the reference tracer on random 2D and 3D scenes, a family of rho cycles
// with tail and period in closed form, the detector every engine must pick,
// and the rho-cycle certificate checked step by step.
#include "engine/cycle_detector.hpp"
#include "engine/reference_step.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace orthoray;

namespace {

void check_same(const Answer& got, const Answer& want) {
    CHECK(got.reason == want.reason);
    CHECK(got.reflections == want.reflections);
    CHECK(got.tail == want.tail);
    if (!want.decided()) CHECK(got.limit == want.limit);
}

// A channel between the mirrors y = 0 and y = 1 from x = 0 to x = n, closed
// by a mirror x = n, with a one-way mirror x+ m (acting on rays moving
// toward -x). The ray starts at the origin along (1, 1) and reflects at
// x = 1, 2, ...: it passes the one-way mirror's back at reflection m, turns
// at the corner x = n, and comes back to x = m, whose corner sends it along
// (1, 1) again, leaving the state s_m = ((m, m mod 2), (1, 1)) once more.
// So s_m starts the cycle, s_(m-1) (on x = m - 1, going right) is not on it:
// tail m - 1, period 2 (n - m). In 3D the mirrors z = 0 and z = 1 join in
// and the ray runs along (1, 1, 1): y and z flip together, the same path.
std::string channel(int n, int m, int dim) {
    std::ostringstream s;
    const bool space = dim == 3;
    const std::string z = space ? " z 0 1" : "";
    s << "dim " << dim << "\nmirror y 0 x 0 " << n << z << "\nmirror y 1 x 0 " << n << z
      << "\nmirror x " << n << " y 0 1" << z << "\nmirror x+ " << m << " y 0 1" << z << "\n";
    if (space)
        s << "mirror z 0 x 0 " << n << " y 0 1\nmirror z 1 x 0 " << n
          << " y 0 1\nray 0 0 0 1 1 1\ntarget -5 -5 0\n";
    else
        s << "ray 0 0 1 1\ntarget -5 -5\n";
    return s.str();
}

// The states s_1, s_2, ... of a trajectory that cycles, by the reference
// step, up to and including the first repeated one.
std::vector<std::pair<Vector, Vector>> states_until_repeat(const Scene& scene) {
    std::vector<std::pair<Vector, Vector>> states;
    std::map<std::pair<Vector, Vector>, std::size_t> seen;
    Vector p = scene.ray().start, v = scene.ray().direction;
    while (true) {
        const engine::ReferenceEvent e = engine::reference_step(scene, p, v);
        REQUIRE_FALSE(e.escape);
        REQUIRE_FALSE(e.absorbed);
        p = e.point;
        v = e.direction;
        states.emplace_back(p, v);
        if (!seen.emplace(states.back(), states.size()).second) return states;
    }
}

} // namespace

TEST_CASE("one-sided trajectories: every lattice shooter agrees with the reference tracer",
          "[optics][lattice][property]") {
    std::mt19937_64 rng(1301);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 0;
    shape.one_sided_percent = 60;
    shape.max_rays = 1;
    shape.max_targets = 1;
    const Shooter shooters[] = {Shooter::automatic, Shooter::grid, Shooter::bvh, Shooter::section,
                                Shooter::pieces};
    const Arithmetic arithmetics[] = {Arithmetic::automatic, Arithmetic::int128, Arithmetic::wide};
    const Engine engines[] = {Engine::automatic, Engine::lattice, Engine::induction};
    const int cases = test::case_count(2000);
    int compared = 0, tails = 0, limits = 0, by_graph = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        shape.scene.box_percent = 95;
        shape.scene.max_denominator = i % 4 == 0 ? 1 : 3;
        const Scene s = test::random_optics_scene(rng, shape);
        if (!s.has_one_sided()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        SolveOptions reference;
        reference.engine = Engine::reference;
        // Now and then a cap on the reflections: both engines run Brent's
        // detector on the same states, so they stop at the same count.
        if (test::chance(rng, 20))
            reference.max_steps = static_cast<std::uint64_t>(test::pick(rng, 0, 40));
        const Answer want = solve(s, reference);
        if (!want.decided() && !reference.max_steps) continue;
        ++compared;
        tails += want.tail > 0;
        limits += !want.decided();
        for (const Shooter shooter : shooters) {
            if (shooter == Shooter::pieces && s.dim != 2) continue; // refused: 2D tables
            SolveOptions options;
            options.shooter = shooter;
            options.max_steps = reference.max_steps;
            options.arithmetic = arithmetics[test::pick(rng, 0, 2)];
            options.engine = engines[test::pick(rng, 0, 2)];
            options.cycle_detector =
                test::chance(rng, 50) ? CycleDetector::first_state : CycleDetector::brent;
            const Answer got = solve(s, options);
            INFO("shooter " << static_cast<int>(shooter) << ", arithmetic "
                            << static_cast<int>(options.arithmetic) << ", engine "
                            << static_cast<int>(options.engine));
            CHECK(got.engine == EngineUsed::lattice);
            check_same(got, want);
        }
        // The state graph: every lattice state, reachable ones from the
        // start; under a cap it stops where Brent's detector would.
        if (shape.scene.max_denominator == 1) {
            SolveOptions graph;
            graph.engine = Engine::graph;
            graph.max_graph_states = 20000;
            graph.max_steps = reference.max_steps;
            const Answer got = solve(s, graph);
            if (got.decided() || got.limit == Limit::steps) { // not refused as too large
                ++by_graph;
                CHECK(got.reason == want.reason);
                if (want.decided()) check_same(got, want);
            }
        }
    }
    CHECK(compared > cases * 8 / 10);
    CHECK(tails > cases / 100); // real rho shapes (about 2%), not only pure cycles
    CHECK(limits > 0);
    CHECK(by_graph > cases / 10);
}

TEST_CASE("a one-way mirror in a channel: tail m - 1, period 2 (n - m)", "[optics][lattice]") {
    for (const int dim : {2, 3})
        for (const auto& [n, m] : std::vector<std::pair<int, int>>{
                 {2, 1}, {10, 1}, {10, 5}, {10, 9}, {37, 20}, {1000, 999}}) {
            INFO("dim " << dim << ", n " << n << ", m " << m);
            const Scene s = read_scene(channel(n, m, dim));
            for (const Shooter shooter : {Shooter::automatic, Shooter::grid, Shooter::bvh,
                                          Shooter::section, Shooter::pieces}) {
                if (shooter == Shooter::pieces && dim != 2) continue; // refused: 2D tables
                SolveOptions options;
                options.shooter = shooter;
                const Answer a = solve(s, options);
                CHECK(a.engine == EngineUsed::lattice);
                CHECK(a.reason == Reason::cycle);
                CHECK(a.tail == m - 1);
                CHECK(a.period() == 2 * (n - m));
                CHECK(a.reflections == m - 1 + 2 * (n - m));
            }
        }
    // Long enough that the 2D run moves on to the piece tables (after
    // 2^14 reflections on the grid), whose cursors the tail pass copies.
    const Scene long_channel = read_scene(channel(300000, 100000, 2));
    const Answer a = solve(long_channel);
    CHECK(a.shooter == ShooterUsed::pieces);
    CHECK(a.tail == 99999);
    CHECK(a.period() == 400000);
}

TEST_CASE("no engine can run the first-state detector with one-sided elements",
          "[optics][lattice]") {
    using engine::detector_for;
    static_assert(detector_for(true, CycleDetector::first_state) == CycleDetector::brent);
    static_assert(detector_for(true, CycleDetector::brent) == CycleDetector::brent);
    static_assert(detector_for(false, CycleDetector::first_state) == CycleDetector::first_state);
    // Asked for first-state on a rho, every engine still finds the cycle
    // (the first state never comes back: first-state would hit the cap).
    const Scene s = read_scene(channel(40, 30, 2));
    for (const Engine e : {Engine::automatic, Engine::lattice, Engine::reference}) {
        SolveOptions options;
        options.engine = e;
        options.cycle_detector = CycleDetector::first_state;
        options.max_steps = 1000;
        const Answer a = solve(s, options);
        CHECK(a.reason == Reason::cycle);
        CHECK(a.tail == 29);
    }
}

TEST_CASE("rho-cycle certificates: each point the next acting event, the cycle's start state",
          "[optics][lattice][certificate]") {
    std::mt19937_64 rng(1302);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 0;
    shape.one_sided_percent = 50;
    shape.max_rays = 1;
    shape.max_targets = 1;
    shape.scene.box_percent = 90;
    std::vector<Scene> scenes{read_scene(channel(10, 5, 2)), read_scene(channel(7, 3, 3))};
    for (int i = 0; i < test::case_count(300); ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        scenes.push_back(test::random_optics_scene(rng, shape));
    }
    int checked = 0, with_tail = 0;
    for (const Scene& s : scenes) {
        if (!s.has_one_sided()) continue;
        SolveOptions probe;
        probe.max_steps = 5000;
        const Answer answer = solve(s, probe);
        if (answer.reason != Reason::cycle) continue;
        INFO(write_scene(s));
        for (const CertificateFormat format : {CertificateFormat::text, CertificateFormat::jsonl}) {
            std::ostringstream out;
            CertificateWriter writer(out, s, format);
            SolveOptions options;
            const bool pieces = test::chance(rng, 50); // the tables are 2D
            options.shooter = pieces && s.dim == 2 ? Shooter::pieces : Shooter::automatic;
            // The reference tracer writes the same certificate.
            if (test::chance(rng, 25)) options.engine = Engine::reference;
            writer.attach(options);
            const Answer a = solve(s, options);
            writer.finish(a);
            REQUIRE(a.reason == Reason::cycle);
            // The text form, line by line (the JSON Lines form is checked
            // for its verdict keys).
            const std::string text = out.str();
            const std::string tail = a.tail.get_str(), period = a.period().get_str();
            if (format == CertificateFormat::jsonl) {
                CHECK(text.find("\"period\": \"" + period + "\", \"tail\": \"" + tail + "\"") !=
                      std::string::npos);
                continue;
            }
            std::istringstream lines(text);
            std::string word;
            std::vector<Vector> points;
            Vector state_point, state_direction;
            std::string line;
            std::map<std::string, std::string> verdict;
            while (std::getline(lines, line)) {
                std::istringstream in(line);
                in >> word;
                auto read_vector = [&] {
                    Vector x;
                    for (int j = 0; j < s.dim; ++j) {
                        std::string c;
                        in >> c;
                        x[j] = Rational(c);
                        x[j].canonicalize();
                    }
                    return x;
                };
                if (word == "point") {
                    points.push_back(read_vector());
                } else if (word == "state") {
                    state_point = read_vector();
                    state_direction = read_vector();
                } else {
                    std::string rest;
                    std::getline(in, rest);
                    verdict[word] = rest.empty() ? "" : rest.substr(1);
                }
            }
            CHECK(verdict["period"] == period);
            CHECK(verdict["tail"] == tail);
            CHECK(verdict["reason"] == "cycle");
            // Every point is the first acting event from the previous state.
            const std::vector<std::pair<Vector, Vector>> states = states_until_repeat(s);
            const std::size_t T = static_cast<std::size_t>(a.tail.get_ui()),
                              L = static_cast<std::size_t>(a.period().get_ui());
            REQUIRE(points.size() >= T + L + 2); // p0 .. pm, m >= T + L + 1
            CHECK(points[0] == s.ray().start);
            Vector v = s.ray().direction;
            for (std::size_t k = 1; k < points.size(); ++k) {
                const engine::ReferenceEvent e = engine::reference_step(s, points[k - 1], v);
                REQUIRE(e.point == points[k]);
                v = e.direction;
            }
            // s_(T+1) as the reference step computes it; the cycle closes
            // there after L and the tail is least.
            REQUIRE(states.size() == T + L + 1);
            CHECK(state_point == states[T].first);
            CHECK(state_direction == states[T].second);
            CHECK(states[T + L] == states[T]);
            if (T >= 1) CHECK_FALSE(states[T - 1] == states[T + L - 1]);
            ++checked;
            with_tail += T > 0;
        }
    }
    // Scaled like the cases (support/case_count.hpp).
    CHECK(checked > test::case_count(300) / 15);
    CHECK(with_tail > test::case_count(300) / 60);
}

TEST_CASE("a stop while the tail is searched ends the run as a limit",
          "[optics][lattice][limits]") {
    // The tail pass (engine/tail_search.hpp) runs after Brent's detector
    // has found the period and polls the monitor from its first step, so it
    // makes a run's last poll; stopped there, the run must report the limit,
    // not the cycle. The lattice engine (on the grid), and the octagonal
    // one (on its hierarchy: a diagonal far off the channel brings it in,
    // and the answer is the same).
    // Polls are paced by the clock (PollPacer), so how many come before the
    // tail pass varies with the machine's load; the reflections a poll names
    // do not. Stepping polls name counts below the one Brent's detector
    // stopped at (the last chunk ends with the answer, not a poll), and the
    // tail pass names that count from its first step on: the first poll at
    // the largest count a whole run names is the tail pass's first.
    struct StopAtReflections : RunMonitor {
        std::uint64_t stop_at = ~std::uint64_t{0}, most = 0;
        std::optional<Limit> poll(std::uint64_t reflections) override {
            most = std::max(most, reflections);
            return reflections >= stop_at ? std::optional<Limit>(Limit::interrupt) : std::nullopt;
        }
    };
    Scene lattice_scene = read_scene(channel(3000, 1000, 2));
    Scene octagonal_scene = lattice_scene;
    octagonal_scene.add_diagonal(ElementKind::mirror, 5000, 5000, 5001, 5001);
    for (const Scene* s : {&lattice_scene, &octagonal_scene}) {
        StopAtReflections counting;
        SolveOptions options;
        options.monitor = &counting;
        const Answer whole = solve(*s, options);
        CHECK(whole.shooter == (s == &lattice_scene ? ShooterUsed::grid : ShooterUsed::bvh));
        CHECK(whole.reason == Reason::cycle);
        CHECK(whole.tail == 999);
        // The detector stops past the tail and a period, after the answer's
        // count (the tail and one period).
        CHECK(counting.most > whole.reflections);
        StopAtReflections last;
        last.stop_at = counting.most;
        options.monitor = &last;
        const Answer stopped = solve(*s, options);
        CHECK(stopped.reason == Reason::limit);
        CHECK(stopped.limit == Limit::interrupt);
        CHECK(stopped.tail == 0);
    }
}
