// Options reject what they cannot mean with one message and exit 2,
// instead of clamping, wrapping or reading nan as "no limit".
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace orthoray::test;

namespace {

const std::string box = instance("2d/box-corner-3x5.scene");

void require_rejected(const std::string& args, const std::string& expected) {
    CAPTURE(args);
    const CliResult r = run_cli(args);
    INFO("stderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.err.find(expected) != std::string::npos);
}

} // namespace

TEST_CASE("the option --timeout takes only a finite number of seconds above 0",
          "[option_ranges][cli]") {
    for (const std::string& command :
         std::vector<std::string>{"solve " + quote(box), "render " + quote(box) + " -o x.svg",
                                  "bounds " + quote(box), "convert " + quote(box) + " x.json"})
        for (const std::string value : {"nan", "NaN", "inf", "-inf", "-1", "0", "0.0", "1e300",
                                        "1e-400", "x", "''", "0x1p-3", "' 1'"})
            require_rejected(command + " --timeout " + value,
                             "expected a number of seconds above 0 and at most 10^9");
    CHECK(run_cli("solve " + quote(box) + " --timeout 1e9").status == 0);
    CHECK(run_cli("solve " + quote(box) + " --timeout 0.5").status == 0);
}

TEST_CASE("the options --max-steps and --seed take whole numbers up to 2^64 - 1",
          "[option_ranges][cli]") {
    for (const char* value : {"18446744073709551616", "99999999999999999999", "-1", "1e3",
                              "100000000000000000000000", "0x10", "+5", "''"}) {
        require_rejected("solve " + quote(box) + " --max-steps " + value,
                         "expected a whole number from 0 to 18446744073709551615");
        require_rejected(std::string("generate random --seed ") + value,
                         "expected a whole number from 0 to 18446744073709551615");
    }
    const CliResult top = run_cli("generate random --seed 18446744073709551615");
    CHECK(top.status == 0);
    CHECK(top.out.find("--seed 18446744073709551615") != std::string::npos);
    CHECK(run_cli("solve " + quote(box) + " --max-steps 18446744073709551615").status == 0);
}

TEST_CASE("an empty value is refused, not read as the option left out", "[option_ranges][cli]") {
    // Else `-o ''` wrote to standard output (or render's default file), and
    // `--min-intensity ''` answered the plain question.
    const std::string level = quote(instance("puzzles/opaque-5x5.bff"));
    const std::string model = quote(instance("realistic/greedy-fails.realistic"));
    const std::string scene = quote(box);
    for (const auto& [args, option] : std::vector<std::pair<std::string, std::string>>{
             {"solve " + scene + " --min-intensity ''", "--min-intensity"},
             {"solve " + scene + " --certificate ''", "--certificate"},
             {"render " + scene + " -o ''", "--output"},
             {"render " + scene + " --html ''", "--html"},
             {"render " + scene + " --certificate ''", "--certificate"},
             {"batch " + scene + " -o ''", "--output"},
             {"batch " + scene + " --certificates ''", "--certificates"},
             {"generate box --sides 3,5 -o ''", "--output"},
             {"puzzle solve " + level + " -o ''", "--output"},
             {"puzzle solve " + level + " --render ''", "--render"},
             {"puzzle scene " + level + " -o ''", "--output"},
             {"puzzle generate -o ''", "--output"},
             {"realistic " + model + " --certificate ''", "--certificate"},
             {"realistic " + scene + " --from-scene --min-intensity ''", "--min-intensity"},
             {"realistic " + scene + " --from-scene --min-intensity 1 --write-model ''",
              "--write-model"}})
        require_rejected(args, option + ": found an empty value, expected ");
    // Options that only mean something with --from-scene are not ignored
    // without it: a model states its own eps and receiver.
    require_rejected("realistic " + model + " --min-intensity 5",
                     "--min-intensity requires --from-scene");
    require_rejected("realistic " + model + " --target 2", "--target requires --from-scene");
}

TEST_CASE("bounded whole numbers and named choices say what they found and expected",
          "[option_ranges][cli]") {
    const std::string file = quote(box);
    for (const std::string value : {"0", "4097", "-1", "2.5", "x", "99999999999999999999999"})
        require_rejected("batch " + file + " --jobs " + value,
                         "--jobs: found '" + value + "', expected a whole number from 1 to 4096");
    CHECK(run_cli("batch " + file + " --jobs 4096").status == 0);
    CHECK(run_cli("batch " + file + " --jobs 1").status == 0);
    require_rejected("solve " + file + " --max-memory 1099511627777",
                     "found '1099511627777', expected a whole number from 1 to 1099511627776");
    require_rejected("solve " + file + " --engine fast",
                     "--engine: found 'fast', expected one of auto, graph, induction, lattice, "
                     "reference");
    require_rejected("solve " + file + " --format xml",
                     "--format: found 'xml', expected one of auto, scene, json, grid");
    require_rejected("convert " + file + " x.txt --to grid",
                     "--to: found 'grid', expected one of auto, scene, json");
    require_rejected("generate random --dim 4", "--dim: found '4', expected one of 2, 3");
    // --k was unsigned behind an integer check: CLI11 said "Could not convert".
    require_rejected("generate coprime-box --k -3",
                     "--k: found '-3', expected a whole number from 1 to 4096");
    require_rejected("generate maze", "found 'maze', expected one of random, box,");
    // The generator's ranges, at the option that sets them (CLI11 said
    // "Could not convert", and the library "the number of mirrors must be in
    // [0, 10^6]", naming no option and not what it found).
    for (const std::string value : {"x", "1.5", "-", "-1", "1000001", "99999999999999999999"})
        require_rejected("generate random --mirrors " + value,
                         "--mirrors: found '" + value +
                             "', expected a whole number from 0 to 1000000");
    for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
             {"random --rays 0", "--rays: found '0', expected a whole number from 1 to 1000"},
             {"random --targets 1001",
              "--targets: found '1001', expected a whole number from 1 to 1000"},
             {"random --range 1",
              "--range: found '1', expected a whole number from 2 to 4611686018427387904"},
             {"random --denominator 0",
              "--denominator: found '0', expected a whole number from 1 to 1048576"},
             {"random --target-after -1",
              "--target-after: found '-1', expected a whole number from 0 to 1000000"},
             {"random --direction-size 0",
              "--direction-size: found '0', expected a whole number from 1 to 1099511627776"},
             {"random --absorbers 3/2", "found '3/2' for --absorbers, expected a fraction from 0 "
                                        "to 1 with a denominator up to 2^20"},
             {"random --splitters -1/2",
              "found '-1/2' for --splitters, expected a fraction from 0 to 1"},
             {"random --one-sided 1/2097152", "found '1/2097152' for --one-sided, expected a "
                                              "fraction from 0 to 1 with a denominator up to 2^20"},
             {"random --diagonals 2", "found '2' for --diagonals, expected a fraction"},
             {"box --sides 3 0", "found '0' for --sides, expected a positive integer"},
             {"square --direction 0 3", "found '0' for --direction, expected a nonzero integer"},
             {"hallway --length -5", "found '-5' for --length, expected a number above 0"},
             {"hallway --slope 0", "found '0' for --slope, expected a number above 0"},
             {"coprime-cuboid --k 1",
              "found '1' for --k, expected a whole number from 2 to 4096 for coprime-cuboid"},
             // What no single option decides, the library says in the same form.
             {"random --range 4611686018427387904 --denominator 2",
              "random: found 4611686018427387904 for the coordinate range, expected a "
              "whole number from 2 to 2^62 / the denominator bound = 2305843009213693952"},
             {"random --rays 2 --target-after 3",
              "random: found a target on the trajectory with 2 rays, 1 targets and the "
              "splitter fraction 0, expected one ray, one target and no splitters"},
             {"random --dim 3 --diagonals 1/2",
              "random: found diagonal elements in dimension 3, expected dimension 2"},
             {"random --mirrors 1000000 --target-after 1000",
              "random: found 1001006006 for (the target's segment + 1) * (mirrors + 6), "
              "expected at most 10^9"},
             {"box --mirrors 3", "found --mirrors for the family box, expected one of its "
                                 "options: --direction, --sides, --start, --target, "
                                 "--target-point, --seed"},
             {"box --target far --target-point 1 1",
              "found both --target and --target-point, expected one of them"},
             {"box --sides 3 5 --direction 0 0",
              "box: found the direction 0, expected a nonzero vector"}})
        require_rejected("generate " + args, expected);
    // -1 wrapped to 2^64 - 1, and 0x9 read as hex, before.
    for (const std::string value : {"-1", "0x1", "''"})
        require_rejected("realistic --from-scene --target " + value + " " + file,
                         "--target: found '");
    require_rejected("realistic --from-scene --max-states 0x9 " + file,
                     "--max-states: found '0x9', expected a whole number from 1 to 4294967294");
    CHECK(run_cli("generate random --mirrors 3 --range 4611686018427387904").status == 0);
    require_rejected("pieces " + quote(instance("3d/box-corner-1x2x3.scene")),
                     "', expected a 2D scene whose ray moves in both x and y");
}

TEST_CASE("integer options are decimal, leading zeros and all", "[option_ranges][cli]") {
    // CLI11 reads numbers in base 0: "010" was octal 8 and "08" did not
    // convert, silently another scene or a usage error.
    const auto body = [](const CliResult& r) { return r.out.substr(r.out.find("\ndim")); };
    for (const std::string option : {"--seed", "--mirrors"}) {
        const CliResult padded = run_cli("generate random " + option + " 010");
        const CliResult plain = run_cli("generate random " + option + " 10");
        REQUIRE(padded.status == 0);
        CHECK(padded.out.find(option + " 10") != std::string::npos); // the header: as read
        CHECK(body(padded) == body(plain));
    }
    const CliResult level = run_cli("puzzle generate --seed 0000000000000000000000010");
    CHECK(level.status == 0);
    CHECK(level.out == run_cli("puzzle generate --seed 10").out);

    // Every integer option takes "08": a validator added with check() instead
    // of transform() leaves CLI11 its own octal reading, and this fails.
    TempDir dir;
    std::string targets;
    for (int y = 1; y <= 8; ++y) targets += "target 1/2 " + std::to_string(y) + "\n";
    const std::string beam =
        quote(dir.write("beam.scene", "dim 2\nmirror x 1 y 0 10 reflectance 1/2\n"
                                      "ray 0 1 1 0 intensity 10\n" +
                                          targets));
    const std::string file = quote(box), puzzle = quote(instance("puzzles/opaque-5x5.bff"));
    for (const std::string& args : std::vector<std::string>{
             "batch " + file + " --jobs 08 -o " + quote(dir.path("r.jsonl")),
             "generate random --seed 08",
             "generate random --mirrors 08",
             "generate random --rays 08",
             "generate random --targets 08",
             "generate random --range 08",
             "generate random --bits 08",
             "generate random --denominator 08",
             "generate random --mirrors 30 --target-after 08",
             "generate random --direction-size 08",
             "generate coprime-box --k 08",
             "puzzle generate --lasers 08 --size 3x3",
             "puzzle generate --points 08",
             "puzzle generate --seed 08",
             "puzzle generate --attempts 08",
             "puzzle generate --max-nodes 08",
             "puzzle solve " + puzzle + " --jobs 08",
             "puzzle solve " + puzzle + " --max-nodes 08",
             "realistic --from-scene --min-intensity 1 --target 08 " + beam,
             "realistic --from-scene --min-intensity 1 --max-states 08 " + beam,
             "render " + file + " --steps 08 -o " + quote(dir.path("r.svg")),
             "solve " + file + " --max-steps 08",
             "solve " + file + " --max-memory 08"}) {
        CAPTURE(args);
        const CliResult r = run_cli(args);
        INFO("stderr: " << r.err);
        CHECK(r.status != 2);
    }
    require_rejected("generate random --mirrors -08",
                     "--mirrors: found '-08', expected a whole number from 0 to 1000000");
    require_rejected("batch " + file + " --jobs 0000",
                     "--jobs: found '0000', expected a whole number from 1 to 4096");
}
