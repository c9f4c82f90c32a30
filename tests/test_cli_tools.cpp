// The commands beside solve and verify as a user meets them: `pieces`
// prints the 2D piece tables, `generate` writes instance families (the same
// bytes to stdout and to -o), `bounds` prints the state-count bounds; bad
// input to any of them is status 2 with one line.
#include "support/cli_checks.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

using namespace orthoray::test;

namespace {

const std::string box_corner = "2d/box-corner-3x5.scene"; // yes, hit, 6

} // namespace

TEST_CASE("pieces prints the 2D piece tables and refuses other scenes", "[cli][pieces]") {
    const CliResult r = run_cli("pieces " + quote(instance(box_corner)));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    // From (0, 2) on the left wall, moving up and right, the ray reaches the
    // corner (3, 5) at t = 3 and flips both components.
    CHECK(r.out.find("element 0 +x+y from 2: element 3 at t = 3, flip xy\n") != std::string::npos);
    const CliResult r3 =
        run_cli("pieces " + quote(source_path("instances/3d/box-corner-1x2x3.scene")));
    require_bad_input(r3);
}

// ---------------------------------------------------------------- generate, bounds

TEST_CASE("generate writes the same bytes to stdout and -o, and they solve as expected",
          "[cli][generate]") {
    TempDir dir;
    const std::string args = "generate random --dim 3 --mirrors 30 --denominator 3 --box "
                             "--absorbers 1/10 --target-after 12 --seed 5";
    const CliResult first = run_cli(args), second = run_cli(args);
    CHECK(first.status == 0);
    CHECK(first.err.empty());
    CHECK(first.out == second.out);
    CHECK(first.out.starts_with("# orthoray generate random --seed 5 --dim 3 --mirrors 30 "));
    const std::string file = dir.path("random.scene");
    const CliResult written = run_cli(args + " -o " + quote(file));
    CHECK(written.status == 0);
    CHECK(written.out.empty());
    CHECK(slurp(file) == first.out);
    CHECK(first.out != run_cli(args + "0").out); // seed 50

    REQUIRE(first.out.find("# expect: yes hit ") != std::string::npos);
    const nlohmann::json answer = parse_json(run_cli("solve --json " + quote(file)).out);
    const std::size_t at = first.out.find("# expect: yes hit ") + 18;
    CHECK(answer["answer"] == "yes");
    CHECK(answer["reflections"].dump() == first.out.substr(at, first.out.find('\n', at) - at));
}

TEST_CASE("generate random records the optics options in its header", "[cli][generate]") {
    const CliResult r = run_cli("generate random --mirrors 12 --splitters 1/3 --one-sided 1/4 "
                                "--rays 2 --targets 3 --box --seed 4");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out.starts_with("# orthoray generate random --seed 4 --mirrors 12 --splitters 1/3 "
                            "--one-sided 1/4 --rays 2 --targets 3 --box\n"));
    CHECK(r.out == run_cli("generate random --box --targets 3 --rays 2 --one-sided 1/4 "
                           "--splitters 1/3 --mirrors 12 --seed 4")
                       .out);
    // The header is a command that runs: the same bytes again.
    const std::string header = r.out.substr(0, r.out.find('\n'));
    const std::string prefix = "# orthoray ";
    REQUIRE(header.starts_with(prefix));
    const CliResult again = run_cli(header.substr(prefix.size()));
    CHECK(again.status == 0);
    CHECK(again.out == r.out);
}

TEST_CASE("generate: each family runs from the command line", "[cli][generate][slow]") {
    for (const char* args : {"box --sides 3 5 --target far", "box --sides 2 3 4 --target generic",
                             "box --sides 4 6 --start 1 0 --direction 1 2 --target-point 1 1",
                             "square --direction 5 3", "hallway --length 100 --slope 1/7",
                             "coprime-box --k 6", "coprime-cuboid --k 3 --target far"}) {
        INFO("orthoray generate " << args);
        const CliResult r = run_cli(std::string("generate ") + args);
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        const std::string family = std::string(args).substr(0, std::string(args).find(' '));
        CHECK(r.out.starts_with("# orthoray generate " + family + " "));
    }
    CHECK(run_cli("generate box --sides 4 5 --target far").out.find("# expect: no cycle 16\n") !=
          std::string::npos);
    CHECK(run_cli("generate coprime-box --k 6").out.find("# expect: yes hit 127\n") !=
          std::string::npos);
}

TEST_CASE("generate: usage errors are status 2 with one line", "[cli][generate][slow]") {
    for (const char* args : {
             "generate",                                  // no family
             "generate frobnicate",                       // unknown family
             "generate box --mirrors 3",                  // an option of another family
             "generate box --sides 3",                    // one side
             "generate box --sides 3 0",                  // a zero side
             "generate box --sides 3 5 --start 1 1 1",    // a 3D start in a 2D box
             "generate box --sides 3 5 --direction 0 0",  // no direction
             "generate box --sides 3 5 --target nowhere", // not a target kind
             "generate box --sides 3 5 --target far --target-point 1 1",
             "generate random --absorbers x",                       // not a number
             "generate random --absorbers 3/2",                     // not a fraction in [0, 1]
             "generate random --absorbers 1/100000000000000000000", // a huge denominator
             "generate random --bits 3 --range 9",                  // two ways to say one thing
             "generate random --dim 4",                             // no such dimension
             "generate random --splitters 2",                       // not a fraction in [0, 1]
             "generate random --rays 0",                            // no ray
             "generate random --targets 2 --target-after 3",        // which target?
             "generate square --direction 0 1",                     // a zero component
             "generate hallway --slope -1",                         // a negative slope
             "generate coprime-box --k 0",                          // k too small
         }) {
        INFO("orthoray " << args);
        const CliResult r = run_cli(args);
        require_bad_input(r);
        CHECK(r.err.starts_with("orthoray: "));
    }
    TempDir dir;
    const CliResult r =
        run_cli("generate box --sides 3 5 -o " + quote(dir.path("no-such-dir/x.scene")));
    require_bad_input(r);
}

TEST_CASE("generate --help lists every family with an example", "[cli][generate]") {
    const CliResult r = run_cli("generate --help");
    CHECK(r.status == 0);
    for (const char* family :
         {"random", "box", "square", "hallway", "coprime-box", "coprime-cuboid"})
        CHECK(r.out.find(std::string("orthoray generate ") + family + " ") != std::string::npos);
    for (const char* option : {"--seed", "--mirrors", "--absorbers", "--bits", "--denominator",
                               "--box", "--target-after", "--direction-size", "--sides", "--target",
                               "--length", "--slope", "--k", "-o"})
        CHECK(r.out.find(option) != std::string::npos);
}

TEST_CASE("bounds prints the lattice and refined bounds", "[cli][bounds]") {
    const nlohmann::json j =
        parse_json(run_cli("bounds --json " + quote(instance(box_corner))).out);
    CHECK(j["dim"] == 2);
    CHECK(j["scale"] == nlohmann::json::array({1, 1}));
    CHECK(j["points"] == 16);
    CHECK(j["lattice_states"] == 64);
    CHECK(j["line_modulus"] == nlohmann::json::array({2}));
    CHECK(j["refined_states"] == 32);
    CHECK(j["pieces"].is_number_integer());

    const nlohmann::json bare =
        parse_json(run_cli("bounds --json --no-pieces " + quote(instance(box_corner))).out);
    CHECK_FALSE(bare.contains("pieces"));
    CHECK(bare["refined_states"] == 32);

    const CliResult text = run_cli("bounds " + quote(instance(box_corner)));
    CHECK(text.status == 0);
    CHECK(text.out.find("lattice states   64 (points * 2^2)\n") != std::string::npos);
    CHECK(text.out.find("refined states   32\n") != std::string::npos);

    const nlohmann::json j3 = parse_json(
        run_cli("bounds --json " + quote(source_path("instances/3d/box-corner-1x2x3.scene"))).out);
    CHECK(j3["dim"] == 3);
    CHECK(j3["points"] == 24); // the 2 x 3 x 4 grid of the 1 x 2 x 3 box: all on its surface
    CHECK(j3["line_modulus"].size() == 3);
    CHECK_FALSE(j3.contains("pieces"));
}

TEST_CASE("bounds: bad input and usage are status 2", "[cli][bounds]") {
    TempDir dir;
    const std::string file = dir.write("bad.scene", "dim 2\nray 0 0 1\n");
    CliResult r = run_cli("bounds " + quote(file));
    require_bad_input(r);
    CHECK(r.err.starts_with(file + ":2:10: "));
    r = run_cli("bounds");
    require_bad_input(r);
    r = run_cli("bounds --json --frobnicate " + quote(instance(box_corner)));
    require_bad_input(r);
}
