// What orthoray writes must be true: a generated scene's comments claim no
// corner the ray does not reach, and a run stopped before any arithmetic
// was chosen says so.
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <random>
#include <string>

using namespace orthoray;
using namespace orthoray::test;

TEST_CASE("generate box with a start or direction claims no corner it does not reach",
          "[honest_output]") {
    std::mt19937_64 random(20);
    int unreached = 0;
    for (int i = 0; i < 200; ++i) {
        BoxFamily f;
        f.sides = {Integer(static_cast<long>(2 + random() % 9)),
                   Integer(static_cast<long>(2 + random() % 9))};
        const auto inside = [&](const Integer& side) {
            return Rational(static_cast<long>(random() % (4 * side.get_si())), 4);
        };
        f.start = Vector{inside(f.sides[0]), inside(f.sides[1]), 0};
        f.direction = Vector{Rational(static_cast<long>(1 + random() % 3)),
                             Rational(static_cast<long>(1 + random() % 3)), 0};
        const GeneratedScene generated = generate_box(f);
        SolveOptions options;
        options.max_steps = 100000;
        const Answer answer = solve(generated.scene, options);
        const std::string text = write_generated(generated);
        CAPTURE(text);
        REQUIRE(answer.decided());
        unreached += !answer.yes();
        // Whatever the ray does, the comment must not say it reaches the target.
        CHECK(text.find("target: the corner the ray reaches") == std::string::npos);
        CHECK_FALSE(generated.expect);
    }
    CHECK(unreached > 0); // the case the old comment got wrong occurs
}

#ifndef ORTHORAY_SANITIZE // sanitizers reserve terabytes of address space
TEST_CASE("running out of memory while reading the scene names no arithmetic",
          "[honest_output][cli]") {
    const TempDir dir;
    std::string text = "dim 2\n";
    for (int i = 0; i < 400000; ++i) text += "mirror x " + std::to_string(i) + " y 0 1\n";
    text += "ray 0 0 1 1\ntarget 5 5\n";
    const std::string scene = dir.write("many.scene", text);
    const CliResult r = run_cli("solve --json --max-memory 8 " + quote(scene));
    CHECK(r.status == 3);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["limit"] == "memory");
    CHECK(j["arithmetic"] == "none");
}
#endif
