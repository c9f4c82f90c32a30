// The realistic model derived from a mirror scene (docs/realistic-scenes.md,
// "From mirror scenes"): where the dynamic program agrees with the exact
// branch search, and the corridor where it over-approximates, since a chain
// of locally feasible triples need not be one ray.
#include "engine/event_rule.hpp"
#include "engine/event_stepper.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <tuple>

using namespace orthoray;

namespace {

Integer exact_best(const Scene& scene, long eps) {
    SolveOptions options;
    options.min_intensity = Integer(eps);
    const Answer a = solve(scene, options);
    const TargetAnswer& t = a.targets.front();
    return t.status == TargetAnswer::Status::lit ? *t.intensity : Integer(-1);
}

std::string path_of(const RealisticModel& model, const RealisticAnswer& answer) {
    std::string path;
    for (const std::size_t object : answer.path)
        path += (path.empty() ? "" : " ") + model.objects[object];
    return path;
}

// The legs of a model as sets: its first legs, and each triple with the
// numerator and denominator of its scale.
using Legs =
    std::pair<std::set<std::size_t>,
              std::set<std::tuple<std::size_t, std::size_t, std::size_t, Integer, Integer>>>;

Legs legs_of(const RealisticModel& model) {
    Legs legs;
    legs.first.insert(model.first_legs.begin(), model.first_legs.end());
    for (const Triple& t : model.triples)
        legs.second.emplace(t.from, t.via, t.to, t.transfer.p, t.transfer.q);
    return legs;
}

// The legs as docs/realistic-scenes.md defines them, found the plain way:
// every reachable state is kept, with the object it leaves, the one before
// and the factor it left with, and each is stepped once with the rational
// scan. The library keeps only the states leaving junctions and follows
// the rest with Brent's method on the ray's lattice. `came_back` says
// whether some state was reached twice (a cycle, or branches merging).
Legs legs_keeping_every_state(const Scene& scene, bool* came_back = nullptr) {
    struct State {
        Vector p, v;
        std::size_t previous, current;
        Rational factor;
        bool operator<(const State& o) const {
            return std::tie(p, v, previous, current, factor) <
                   std::tie(o.p, o.v, o.previous, o.current, o.factor);
        }
    };
    const engine::ReferenceStepper stepper(scene);
    const std::size_t source = 0, receiver = 1;
    std::map<std::tuple<std::size_t, std::size_t, std::size_t>, Rational> best;
    Legs legs;
    auto leg = [&](const State& s, std::size_t to) {
        if (s.current == source) {
            legs.first.insert(to);
        } else {
            Rational& f = best.try_emplace({s.previous, s.current, to}, s.factor).first->second;
            f = std::max(f, s.factor);
        }
    };
    std::set<State> seen;
    std::vector<State> work{{scene.ray().start, scene.ray().direction, source, source, 1}};
    while (!work.empty()) {
        const State s = work.back();
        work.pop_back();
        if (!seen.insert(s).second) {
            if (came_back) *came_back = true;
            continue;
        }
        const engine::ReferenceEvent e = stepper.next(s.p, s.v);
        if (stepper.passes(scene.targets.front(), s.p, s.v, e)) leg(s, receiver);
        if (e.escape) continue;
        std::size_t object = scene.elements.size();
        for (const Element* a : e.acting)
            object = std::min<std::size_t>(object, a - scene.elements.data());
        leg(s, object + 2);
        for (const engine::Outgoing& out : e.outgoing)
            work.push_back({e.point, out.direction, s.current, object + 2,
                            engine::outgoing_factor(e.acting, s.v, out.direction)});
    }
    for (const auto& [key, f] : best) {
        const auto& [from, via, to] = key;
        legs.second.emplace(from, via, to, f.get_num(), f.get_den());
    }
    return legs;
}

} // namespace

TEST_CASE("the model keeps the legs of every state while it keeps only junction states",
          "[realistic][intensity]") {
    // Splitters and one-sided elements make junctions and merges; boxes
    // close stretches into cycles that only Brent's method ends.
    std::mt19937_64 rng(2911);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 40;
    shape.max_rays = 1;
    shape.max_targets = 1;
    shape.scene.max_elements = 10;
    int junctions = 0, cycles = 0; // scenes with junctions; without, but cycling
    const int cases = test::case_count(800);
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        Scene s = test::random_optics_scene(rng, shape);
        test::add_random_attenuation(rng, s, 300);
        if (!s.ray().intensity) s.ray().intensity = Integer(1);
        INFO("case " << i << "\n" << write_scene(s));
        bool came_back = false;
        const Legs expected = legs_keeping_every_state(s, &came_back);
        CHECK(legs_of(realistic_model_of_scene(s, 0, Integer(0))) == expected);
        // With no room for a junction state the walk either needs none or
        // stops as a limit.
        std::optional<Legs> tight;
        try {
            tight = legs_of(realistic_model_of_scene(s, 0, Integer(0), 1));
        } catch (const StatesExceeded&) {
            ++junctions;
        }
        if (!tight) continue;
        CHECK(*tight == expected);
        if (came_back) ++cycles;
    }
    // Of the 800 cases, 225 have junctions and 33 cycle without one.
    CHECK(junctions > cases / 8);
    CHECK(cycles > cases / 50);
}

TEST_CASE("a ray that never splits is walked without keeping its states",
          "[realistic][intensity]") {
    // A 5001 x 4999 box: the ray's orbit is a cycle of 2 (5001 + 4999) =
    // 20,000 reflections (unfolding: it closes after lcm(2a, 2b) = 2ab of
    // travel). One kept state is enough.
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 4999\nmirror x 5001 y 0 4999\n"
                               "mirror y 0 x 0 5001\nmirror y 4999 x 0 5001\n"
                               "ray 1/2 0 1 1 intensity 100\ntarget 1/3 1/5\n");
    REQUIRE(solve(s).reflections == 20'000);
    const RealisticModel model = realistic_model_of_scene(s, 0, Integer(0), 1);
    CHECK(legs_of(model) == legs_keeping_every_state(s));
    // The ray leaves e3 (y = 0) and first meets e4 (y = 4999).
    CHECK(model.first_legs == std::vector<std::size_t>{5});
    CHECK(model.triples.size() == 17);
}

TEST_CASE("the model of a scene whose legs are each one ray agrees with the branch search",
          "[realistic][intensity]") {
    // Through the dim splitter e1 (10), or turned by it and the mirrors e2
    // and e3 (100): each leg is met by one state only.
    const Scene s = read_scene("dim 2\nsplitter x 2 y 1 3 transmittance 1/10\n"
                               "mirror x 0 y 3 5\nmirror y 6 x 1 3\n"
                               "ray 0 0 1 1 intensity 100\ntarget 4 4\n");
    const RealisticModel model = realistic_model_of_scene(s, 0, Integer(0));
    CHECK(model.objects.size() == 5);
    const RealisticAnswer dp = solve_realistic(model);
    CHECK(dp.yes);
    CHECK(dp.best == 100);
    CHECK(dp.best == exact_best(s, 0));
    CHECK(path_of(model, dp) == "S e1 e2 e3 R");
    // Above eps 100 neither lights it.
    const RealisticAnswer above = solve_realistic(realistic_model_of_scene(s, 0, Integer(100)));
    CHECK(!above.yes);
    CHECK(exact_best(s, 100) == -1);
}

TEST_CASE("the model of a mirror corridor over-approximates: triples forget the bounces",
          "[realistic][intensity]") {
    // The ray zigzags between walls e1 (x = 0) and e2 (x = 1) of reflectance
    // 2/3 and passes the target after 4 reflections: 1000 -> 666 -> 444 ->
    // 296 -> 197. The model has the triple (e2, e1, R), and the pair
    // (e2, e1) is reached with 666 after one reflection, so the program
    // passes 444 to R: a chain of feasible triples that no ray follows.
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 100 reflectance 2/3\n"
                               "mirror x 1 y 0 100 reflectance 2/3\n"
                               "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    CHECK(exact_best(s, 0) == 197);
    const RealisticModel model = realistic_model_of_scene(s, 0, Integer(300));
    const RealisticAnswer dp = solve_realistic(model);
    CHECK(dp.best == 444);
    CHECK(path_of(model, dp) == "S e2 e1 R");
    // With eps 300 the program says yes where no branch is bright enough.
    CHECK(dp.yes);
    CHECK(exact_best(s, 300) == -1);
    // Written out and read back, the model gives the same answer.
    const RealisticModel again = read_realistic(write_realistic(model));
    CHECK(write_realistic(again) == write_realistic(model));
    CHECK(solve_realistic(again).best == 444);
}

TEST_CASE("the derived model never delivers less than the scene", "[realistic][intensity]") {
    // Every branch is a path of the model with the same floor chain, so the
    // program's best is at least the branch search's on random scenes.
    std::mt19937_64 rng(1617);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 50;
    shape.max_rays = 1;
    shape.max_targets = 1;
    shape.scene.max_elements = 8;
    const Rational factors[] = {Rational(1), Rational(1, 2), Rational(2, 3), Rational(0)};
    // Under sanitizers a quarter of the cases run, unless no scene has shown
    // the over-approximation yet: then the full 600 may run to find one.
    const int cases = test::case_count(600);
    int lit = 0, over = 0, ran = 0;
    for (int i = 0; i < 600 && (i < cases || over == 0); ++i, ++ran) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        Scene s = test::random_optics_scene(rng, shape);
        for (Element& e : s.elements) {
            if (e.kind == ElementKind::absorber) continue;
            e.reflectance = factors[test::pick_index(rng, 0, 3)];
            if (e.kind == ElementKind::splitter)
                e.transmittance = factors[test::pick_index(rng, 0, 3)];
        }
        s.ray().intensity = Integer(test::pick(rng, 1, 300));
        INFO("case " << i << "\n" << write_scene(s));
        const Integer exact = exact_best(s, 0);
        const RealisticAnswer dp = solve_realistic(realistic_model_of_scene(s, 0, Integer(0)));
        CHECK(dp.best >= exact);
        if (exact > 0) ++lit;
        if (dp.best > exact && exact > 0) ++over;
    }
    CHECK(lit > ran / 10);
    CHECK(over > 0);
}

TEST_CASE("realistic --from-scene runs the program on a scene", "[realistic][cli]") {
    test::TempDir dir;
    const std::string file =
        dir.write("corridor.scene", "dim 2\nmirror x 0 y 0 100 reflectance 2/3\n"
                                    "mirror x 1 y 0 100 reflectance 2/3\n"
                                    "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    const test::CliResult r =
        test::run_cli("realistic --from-scene --min-intensity 300 " + test::quote(file));
    CHECK(r.status == 0);
    CHECK(r.out.find("best         444 (eps 300)\n") != std::string::npos);
    CHECK(r.out.find("path         S e2 e1 R\n") != std::string::npos);
    const test::CliResult exact = test::run_cli("solve --min-intensity 300 " + test::quote(file));
    CHECK(exact.status == 1);
    // The derived model written out, and a certificate verify accepts.
    const std::string model = dir.path("corridor.realistic"), cert = dir.path("c.txt");
    const test::CliResult written = test::run_cli(
        "realistic --from-scene --min-intensity 300 --write-model " + test::quote(model) +
        " --certificate " + test::quote(cert) + " " + test::quote(file));
    CHECK(written.status == 0);
    CHECK(test::slurp(model).starts_with("realistic 1\nobject S R e1 e2\nsource S 1000\n"));
    const test::CliResult verified =
        test::run_cli("verify " + test::quote(model) + " " + test::quote(cert));
    INFO(verified.out << verified.err);
    CHECK(verified.status == 0);
    // One ray with an intensity, and a certificate only beside a model.
    const std::string two = dir.write("two.scene", "dim 2\nray 0 0 1 0 intensity 5\n"
                                                   "ray 0 1 1 0 intensity 5\ntarget 1 0\n");
    const test::CliResult second = test::run_cli("realistic --from-scene " + test::quote(two));
    CHECK(second.status == 2);
    CHECK(second.err.find("two.scene:3:1: found a second ray, expected one ray") !=
          std::string::npos);
    // The column is the ray's keyword, or its JSON object, wherever it stands.
    const std::string dark = dir.write("dark.scene", "dim 2\n   ray 0 0 1 0\ntarget 1 0\n");
    const test::CliResult unlit = test::run_cli("realistic --from-scene " + test::quote(dark));
    CHECK(unlit.status == 2);
    CHECK(unlit.err.find("dark.scene:2:4: found a ray without an intensity") != std::string::npos);
    const std::string dark_json =
        dir.write("dark.json", "{\"dim\": 2, \"elements\": [],\n \"rays\": [  {\"start\": [0, 0], "
                               "\"direction\": [1, 0]}],\n \"targets\": [[1, 0]]}\n");
    const test::CliResult unlit_json =
        test::run_cli("solve --min-intensity 1 " + test::quote(dark_json));
    CHECK(unlit_json.status == 2);
    CHECK(unlit_json.err.find("dark.json:2:13: found a ray without an intensity") !=
          std::string::npos);
    CHECK(test::run_cli("realistic --from-scene --certificate x " + test::quote(file)).status == 2);
}

TEST_CASE("realistic --from-scene stops at --max-states as a limit, writing nothing",
          "[realistic][cli]") {
    test::TempDir dir;
    // A corridor of two half-silvered walls: the ray meets them at heights
    // 1/2, 3/2, ..., 199/2, and each of those 100 events is a junction with
    // two ways out (on up the corridor, or out through the wall), so 200
    // states leave junctions; 200 fit, 199 do not.
    const std::string file = dir.write(
        "corridor.scene", "dim 2\nsplitter x 0 y 0 100 reflectance 1/2 transmittance 1/2\n"
                          "splitter x 1 y 0 100 reflectance 1/2 transmittance 1/2\n"
                          "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    constexpr int states = 200;
    const std::string model = dir.path("m.realistic");
    auto run = [&](int cap) {
        // Appended, not +: GCC 12 warns falsely on that (-Warray-bounds).
        std::string command = "realistic --from-scene --max-states ";
        command.append(std::to_string(cap)).append(" --write-model ").append(test::quote(model));
        return test::run_cli(command.append(" ").append(test::quote(file)));
    };
    const test::CliResult capped = run(states - 1);
    CHECK(capped.status == 3);
    CHECK(capped.out.empty());
    CHECK(capped.err.find("orthoray: stopped: the scene's ray reaches more than " +
                          std::to_string(states - 1) + " states leaving junctions") !=
          std::string::npos);
    CHECK(!std::filesystem::exists(model));
    CHECK(run(states).status == 0);
    CHECK(std::filesystem::exists(model));
    // The kept states are numbered in 32 bits: the largest cap is 2^32 - 2,
    // and one more is refused as usage, not left to fail past 2^32 states.
    CHECK(test::run_cli("realistic --from-scene --max-states 4294967294 " + test::quote(file))
              .status == 0);
    const test::CliResult beyond =
        test::run_cli("realistic --from-scene --max-states 4294967295 " + test::quote(file));
    CHECK(beyond.status == 2);
    CHECK(beyond.err.find("--max-states") != std::string::npos);
}
