// The public exchange API (orthoray/exchange.hpp), used as a researcher
// would: the exchange of random 2D scenes is a bijection of its states,
// inducing it answers as simulation does, and an observer sees exactly the
// steps the induction engine reports.
#include "support/case_count.hpp"
#include "support/counting_observer.hpp"
#include "support/random_scene.hpp"

#include "orthoray/exchange.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <random>
#include <sstream>
#include <vector>

using namespace orthoray;

namespace {

using test::CountingObserver;

// A random 2D scene, mostly boxed so that the ray goes on past its first
// segments; the target half the time on the trajectory.
Scene random_2d_scene(std::mt19937_64& rng) {
    test::RandomSceneShape shape;
    shape.box_percent = 90;
    Scene scene = test::random_scene(rng, shape);
    scene.target() = test::random_target(rng, scene, shape);
    return scene;
}

// Intervals [from, from + length) that must tile [0, size) exactly once.
bool tiles(std::vector<std::pair<Integer, Integer>> intervals, const Integer& size) {
    std::sort(intervals.begin(), intervals.end());
    Integer next = 0;
    for (const auto& [from, length] : intervals) {
        if (from != next || length <= 0) return false;
        next += length;
    }
    return next == size;
}

// The answer a simulation would give, read off the induced orbit: the event
// at T^offset(x) is at the state after reflection offset + 1.
std::string induced_answer(const InducedOrbit& orbit) {
    switch (orbit.event) {
    case ExchangeEvent::none:
        return "cycle " + orbit.period.get_str();
    case ExchangeEvent::hit:
        return "hit " + Integer(orbit.offset + 1).get_str();
    case ExchangeEvent::escape:
        return "escape " + Integer(orbit.offset + 1).get_str();
    case ExchangeEvent::absorbed:
        return "absorbed " + Integer(orbit.offset + 1).get_str();
    }
    return "?";
}

std::string summary(const Answer& a) {
    return std::string(to_string(a.reason)) + " " + a.reflections.get_str();
}

} // namespace

TEST_CASE("the exchange of random 2D scenes is a bijection and induces to the simulated answer",
          "[exchange-api]") {
    std::mt19937_64 rng(1919);
    const int goal = test::case_count(300);
    int compared = 0, cycles = 0, events = 0, without = 0;
    for (int attempt = 0; compared < goal && attempt < 20 * goal; ++attempt) {
        const Scene scene = random_2d_scene(rng);
        INFO("scene:\n" << write_scene(scene));
        const std::optional<IntervalExchange> exchange = exchange_of(scene);
        SolveOptions o;
        o.engine = Engine::lattice;
        o.max_steps = 1'000'000;
        const Answer simulated = solve(scene, o);
        REQUIRE(simulated.decided());
        if (!exchange) {
            // Only a ray that never reflects (or moves along an axis) has none.
            ++without;
            continue;
        }
        // pieces[0] is x alone; the domains and the images each tile [0, N).
        REQUIRE(!exchange->pieces.empty());
        REQUIRE(exchange->pieces[0].start == 0);
        REQUIRE(exchange->pieces[0].length == 1);
        std::vector<std::pair<Integer, Integer>> domains, images;
        for (const ExchangePiece& p : exchange->pieces) {
            domains.emplace_back(p.start, p.length);
            images.emplace_back(p.image, p.length);
        }
        REQUIRE(tiles(domains, exchange->size));
        REQUIRE(tiles(images, exchange->size));
        // x is a state of the transversal the exchange names.
        REQUIRE(exchange->first_transversal < exchange->transversals.size());
        REQUIRE(exchange->first_index < exchange->transversals[exchange->first_transversal].count);

        // Before reflection 1 the exchange has nothing to say.
        if (simulated.reason != Reason::cycle && simulated.reflections == 0) continue;
        CountingObserver observer;
        const InducedOrbit orbit = induce(*exchange, &observer);
        REQUIRE(induced_answer(orbit) == summary(simulated));
        REQUIRE(observer.begun == 1);
        REQUIRE(observer.steps == orbit.steps);
        REQUIRE(observer.rounds == orbit.rounds);
        ++compared;
        (orbit.event == ExchangeEvent::none ? cycles : events) += 1;
    }
    CHECK(compared == goal);
    CHECK(cycles > goal / 10);
    CHECK(events > goal / 10);
    CHECK(without > 0);
}

TEST_CASE("an observer in the options sees the exchange and the steps the answer reports",
          "[exchange-api]") {
    std::mt19937_64 rng(2019);
    const int goal = test::case_count(100);
    int induced = 0, accelerated = 0;
    for (int attempt = 0; induced < goal && attempt < 20 * goal; ++attempt) {
        const Scene scene = random_2d_scene(rng);
        INFO("scene:\n" << write_scene(scene));
        CountingObserver observer;
        SolveOptions o;
        o.engine = Engine::induction;
        o.induction_observer = &observer;
        const Answer answer = solve(scene, o);
        if (answer.engine != EngineUsed::induction) {
            REQUIRE(observer.begun == 0); // answered on the first segment
            continue;
        }
        REQUIRE(observer.begun == 1);
        REQUIRE(observer.steps == answer.stats.induction.steps);
        REQUIRE(observer.rounds == answer.stats.induction.rounds);
        REQUIRE(observer.pieces == answer.stats.induction.pieces);
        REQUIRE(observer.states == answer.stats.induction.states);
        // The public exchange is the one the engine induced.
        const std::optional<IntervalExchange> exchange = exchange_of(scene);
        REQUIRE(exchange);
        REQUIRE(exchange->pieces.size() == answer.stats.induction.pieces);
        REQUIRE(induce(*exchange).steps == answer.stats.induction.steps);
        ++induced;
        accelerated += answer.stats.induction.rounds > 0;
    }
    CHECK(induced == goal);
    CHECK(accelerated > 0);
}

TEST_CASE("only a 2D ray that reflects has an exchange", "[exchange-api]") {
    // The 2 x 1 box shot from a corner: x is the state after the reflection
    // at (1, 1) on the top mirror, and its segment ends in the corner (2, 0).
    const Scene box = read_scene("dim 2\nmirror x 0 y 0 1\nmirror x 2 y 0 1\n"
                                 "mirror y 0 x 0 2\nmirror y 1 x 0 2\nray 0 0 1 1\ntarget 2 0\n");
    const std::optional<IntervalExchange> exchange = exchange_of(box);
    REQUIRE(exchange);
    CHECK(exchange->pieces[0].hit); // the segment after x passes the target (2, 0)
    const InducedOrbit orbit = induce(*exchange);
    CHECK(orbit.event == ExchangeEvent::hit);
    CHECK(orbit.offset == 0);
    CHECK(orbit.arithmetic == ArithmeticUsed::int64);

    // No mirror ahead: the ray escapes before reflection 1.
    CHECK_FALSE(exchange_of(read_scene("dim 2\nmirror x 0 y 0 1\nray 1 0 1 1\ntarget 5 5\n")));
    // Along an axis the state space is one line: no exchange.
    CHECK_FALSE(exchange_of(read_scene("dim 2\nmirror x 2 y 0 1\nray 0 0 1 0\ntarget 5 5\n")));
    // 3D scenes are simulated.
    CHECK_FALSE(exchange_of(read_scene("dim 3\nmirror x 2 y 0 1 z 0 1\nray 0 0 0 1 1 1\n"
                                       "target 5 5 5\n")));
}

namespace {

// The exported exchange read back as a reader would: each state x goes to
// image + (x - start) of the piece holding it, until a piece where the
// segment passes the target or the ray does not reflect. The orbit of 0,
// iterated directly (no induction), must give the simulated answer.
std::string answer_of_export(const nlohmann::json& doc, std::uint64_t cap) {
    std::vector<std::int64_t> start, length, image;
    for (const nlohmann::json& p : doc["pieces"]) {
        start.push_back(p["start"].get<std::int64_t>());
        length.push_back(p["length"].get<std::int64_t>());
        image.push_back(p["image"].get<std::int64_t>());
    }
    std::int64_t x = 0;
    for (std::uint64_t i = 0; i < cap; ++i) {
        const std::size_t k = static_cast<std::size_t>(
            std::upper_bound(start.begin(), start.end(), x) - start.begin() - 1);
        const nlohmann::json& piece = doc["pieces"][k];
        const std::string kind = piece["kind"].get<std::string>();
        if (piece["hit"].get<bool>()) return "hit " + std::to_string(i + 1);
        if (kind != "reflect") return kind + " " + std::to_string(i + 1);
        x = image[k] + (x - start[k]);
        if (x == 0) return "cycle " + std::to_string(i + 1);
    }
    return "unknown";
}

} // namespace

TEST_CASE("the exported exchange is the two-row form, and iterating it gives the answer",
          "[exchange-api]") {
    std::mt19937_64 rng(2611);
    const int goal = test::case_count(300);
    int compared = 0;
    for (int attempt = 0; compared < goal && attempt < 20 * goal; ++attempt) {
        const Scene scene = random_2d_scene(rng);
        INFO("scene:\n" << write_scene(scene));
        const std::optional<IntervalExchange> exchange = exchange_of(scene);
        if (!exchange || exchange->size > 1'000'000) continue;
        SolveOptions o;
        o.engine = Engine::lattice;
        const Answer simulated = solve(scene, o);
        if (simulated.reason != Reason::cycle && simulated.reflections == 0) continue;
        std::ostringstream json, text;
        write_exchange(*exchange, json, ExchangeFormat::json);
        write_exchange(*exchange, text, ExchangeFormat::text);
        const nlohmann::json doc = nlohmann::json::parse(json.str());
        REQUIRE(doc["format"] == "orthoray-exchange");
        REQUIRE(doc["size"].get<std::int64_t>() == exchange->size.get_si());
        // top: labels by start; bottom: labels by image; lengths by label.
        const auto& pieces = doc["pieces"];
        const std::size_t k = pieces.size();
        REQUIRE(doc["top"].size() == k);
        REQUIRE(doc["bottom"].size() == k);
        std::int64_t at = 0;
        for (std::size_t i = 0; i < k; ++i) {
            const auto& p = pieces[doc["top"][i].get<std::size_t>()];
            REQUIRE(p["start"].get<std::int64_t>() == at);
            REQUIRE(doc["lengths"][i] == p["length"]);
            at += p["length"].get<std::int64_t>();
        }
        at = 0;
        for (std::size_t i = 0; i < k; ++i) {
            const auto& p = pieces[doc["bottom"][i].get<std::size_t>()];
            REQUIRE(p["image"].get<std::int64_t>() == at);
            at += p["length"].get<std::int64_t>();
        }
        REQUIRE(at == doc["size"].get<std::int64_t>());
        // The text form lists the same pieces and rows.
        const std::string lines = text.str();
        REQUIRE(lines.starts_with("orthoray-exchange 1\n"));
        REQUIRE(static_cast<std::size_t>(std::count(lines.begin(), lines.end(), '\n')) ==
                k + 9 + (exchange->transversals.empty() ? 0 : 1));
        REQUIRE(answer_of_export(doc, 2'000'000) == summary(simulated));
        ++compared;
    }
    CHECK(compared == goal);
}
