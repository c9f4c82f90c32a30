// Every curated instance gives its expected answer with every engine (the
// induction simulates in 3D, docs/induction.md).
#include "support/run_cli.hpp"

#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace orthoray;

TEST_CASE("instances/ give their expected answers", "[instances]") {
    std::ifstream in(test::source_path("instances/expected.json"));
    REQUIRE(in);
    const nlohmann::json expected = nlohmann::json::parse(in);
    REQUIRE(expected.size() >= 20);
    for (const auto& [file, want] : expected.items()) {
        INFO(file);
        const Scene scene = load_scene(test::source_path("instances/" + file));
        for (Engine engine : {Engine::automatic, Engine::lattice, Engine::induction,
                              Engine::reference, Engine::graph}) {
            SolveOptions o;
            o.engine = engine;
            o.max_graph_states = 5'000'000;
            const Answer a = solve(scene, o);
            if (engine == Engine::graph && !a.decided()) continue; // too many states
            CHECK(answer_word(a) == want.at("answer").get<std::string>());
            CHECK(to_string(a.reason) == want.at("reason").get<std::string>());
            CHECK(a.reflections.get_str() == std::to_string(want.at("reflections").get<long>()));
            if (a.reason == Reason::cycle)
                CHECK(a.reflections.get_str() == std::to_string(want.at("period").get<long>()));
        }
    }
}
