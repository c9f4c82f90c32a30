// The orthoray command line as a user meets it: exit statuses, one-line
// errors on stderr and nothing on stdout for bad input, the JSON and text
// answers, certificates and their verification, and the help texts.
#include "support/cli_checks.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace orthoray::test;

namespace {

namespace fs = std::filesystem;

const std::string box_corner = "2d/box-corner-3x5.scene";         // yes, hit, 6
const std::string unit_square = "2d/unit-square-slope-2-3.scene"; // no, cycle, period 10

} // namespace

// ---------------------------------------------------------------- bad input

TEST_CASE("malformed scene files: status 2, no stdout, one FILE:LINE:COL line", "[cli][slow]") {
    TempDir dir;
    struct Case {
        const char* name;
        std::string text;
        int line, column;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"no-dim.scene", "mirror x 0 y 0 1\nray 0 0 1 1\ntarget 1 1\n", 1, 1,
         "found 'mirror', expected 'dim 2' or 'dim 3' as the first statement"},
        {"empty.scene", "", 1, 1,
         "found end of file, expected 'dim 2' or 'dim 3' as the first statement"},
        {"unknown.scene", "dim 2\nprism x 0\n", 2, 1,
         "found 'prism', expected a statement: dim, mirror, absorber, splitter, ray or target"},
        {"zero-den.scene", "dim 2\nmirror x 1/0 y 0 1\n", 2, 10,
         "found '1/0', expected the offset x = c with a nonzero denominator"},
        {"zero-dir.scene", "dim 3\nray 0 0 0 0 0 0\n", 2, 11,
         "found the direction 0, expected a nonzero direction"},
        {"sign-apart.scene", "dim 2\nmirror x + 3 y 0 5\n", 2, 10,
         "found '+' after a space, expected the side's sign right after the axis letter (x+) "
         "or the offset"},
        {"trailing.scene", "dim 2\r\nray 0 0 1 1\r\ntarget 1 1 junk\r\n", 3, 12,
         "found 'junk', expected end of line"},
        {"empty-extent.scene", "dim 2\nmirror x 0 y 3 3\n", 2, 16,
         "found '3' as the upper end of the y extent, expected a number greater than 3"},
        {"axes.scene", "dim 3\nmirror x 0 z 0 1 y 0 1\n", 2, 12,
         "found 'z', expected 'y' (the other axes, in the order x, y, z)"},
        {"nul.scene", std::string("dim 2\nray 0 0\0 1 1\n", 15), 2, 8,
         "found byte 0x00, expected printable ASCII text"},
        {"no-target.scene", "dim 2\nray 0 0 1 1\n", 3, 1,
         "found end of file, expected a 'target' statement"},
    };
    for (const Case& c : cases) {
        const std::string file = dir.write(c.name, c.text);
        for (const std::string& flags : {std::string(), std::string(" --json")}) {
            INFO(c.name << flags);
            const CliResult r = run_cli("solve " + quote(file) + flags);
            require_bad_input(r);
            CHECK(r.err == file + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) +
                               ": " + c.message + "\n");
        }
    }
}

TEST_CASE("binary garbage is bad input, never a crash", "[cli]") {
    TempDir dir;
    std::mt19937 rng(7);
    for (int i = 0; i < 4; ++i) {
        std::string bytes(static_cast<std::size_t>(200 + 1000 * i), '\0');
        for (char& c : bytes) c = static_cast<char>(rng() & 0xff);
        const std::string file = dir.write("garbage" + std::to_string(i) + ".scene", bytes);
        INFO("garbage file " << i);
        const CliResult r = run_cli("solve --json " + quote(file));
        require_bad_input(r);
        CHECK(r.err.starts_with(file + ":"));
    }
}

TEST_CASE("a bad scene writes no certificate", "[cli]") {
    TempDir dir;
    const std::string file = dir.write("bad.scene", "dim 2\nray 0 0 1\n");
    const std::string cert = dir.path("out.cert");
    const CliResult r = run_cli("solve " + quote(file) + " --certificate " + quote(cert));
    require_bad_input(r);
    CHECK(r.err.starts_with(file + ":2:10: "));
    CHECK_FALSE(fs::exists(cert));
}

TEST_CASE("a missing file or a directory is bad input", "[cli]") {
    TempDir dir;
    const std::string missing = dir.path("no-such.scene");
    CliResult r = run_cli("solve " + quote(missing));
    require_bad_input(r);
    CHECK(r.err.starts_with(missing + ":1:1: "));

    r = run_cli("solve --json " + quote(dir.path("")));
    require_bad_input(r);
    CHECK(r.err.starts_with(dir.path("") + ":1:1: found a directory"));

    r = run_cli("verify " + quote(instance(box_corner)) + " " + quote(missing));
    require_bad_input(r);
    CHECK(r.err.starts_with(missing + ":1:1: "));
}

TEST_CASE("usage errors: status 2, no stdout, one line", "[cli][slow]") {
    const std::string scene = quote(instance(box_corner));
    for (const std::string& args : {
             std::string(""),                   // no subcommand
             std::string("frobnicate"),         // unknown subcommand
             std::string("solve"),              // missing FILE
             std::string("solve --json"),       // missing FILE, with a flag
             "solve " + scene + " --bogus",     // unknown option
             "solve --frobnicate " + scene,     // unknown option first
             "solve " + scene + " extra.scene", // one FILE too many
             "solve " + scene + " --max-steps", // option without its value
             "solve " + scene + " --max-steps abc", "solve " + scene + " --engine nonsense",
             std::string("verify ") + scene, // missing CERT
         }) {
        INFO("orthoray " << args);
        const CliResult r = run_cli(args);
        require_bad_input(r);
        CHECK(r.err.starts_with("orthoray: "));
    }
}

TEST_CASE("a negative --max-steps is a usage error", "[cli]") {
    const CliResult r = run_cli("solve " + quote(instance(box_corner)) + " --max-steps -1");
    require_bad_input(r);
}

TEST_CASE("an unwritable --certificate path is a usage error", "[cli]") {
    TempDir dir;
    const CliResult r = run_cli("solve " + quote(instance(box_corner)) + " --certificate " +
                                quote(dir.path("no-such-dir/out.cert")));
    require_bad_input(r);
    CHECK(r.err == "orthoray: cannot write the certificate '" + dir.path("no-such-dir/out.cert") +
                       "': No such file or directory\n");
}

TEST_CASE("an unknown command is named in the message", "[cli]") {
    const CliResult r = run_cli("frobnicate");
    require_bad_input(r);
    CHECK(r.err ==
          "orthoray: found the command 'frobnicate', expected solve, verify, pieces, exchange, "
          "generate, bounds, render, convert, puzzle, realistic, batch or version (see 'orthoray "
          "--help')\n");
}

// ---------------------------------------------------------------- help

TEST_CASE("help texts exit 0 and show an example", "[cli]") {
    for (const char* args : {"--help", "-h", "solve --help", "verify --help"}) {
        INFO("orthoray " << args);
        const CliResult r = run_cli(args);
        CHECK(r.status == 0);
        CHECK(r.err.empty());
        CHECK(r.out.find("Example") != std::string::npos);
        CHECK(r.out.find("Exit status") != std::string::npos);
    }
    const CliResult top = run_cli("--help");
    CHECK(top.out.find("orthoray solve ") != std::string::npos);
    CHECK(top.out.find("orthoray verify ") != std::string::npos);

    const CliResult solve = run_cli("solve --help");
    for (const char* word : {"orthoray solve ", "--json", "--certificate", "--max-steps", "FILE"})
        CHECK(solve.out.find(word) != std::string::npos);

    const CliResult verify = run_cli("verify --help");
    for (const char* word : {"orthoray verify ", "FILE", "CERT"})
        CHECK(verify.out.find(word) != std::string::npos);
}

// ---------------------------------------------------------------- answers

TEST_CASE("solve --json on a hit", "[cli]") {
    const CliResult r = run_cli("solve --json " + quote(instance(box_corner)));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    const nlohmann::json j = parse_json(r.out);
    CHECK(j["answer"] == "yes");
    CHECK(j["reason"] == "hit");
    REQUIRE(j["reflections"].is_number_integer());
    CHECK(j["reflections"] == 6);
    CHECK_FALSE(j.contains("period"));
    // The option may come after the file too.
    const CliResult after = run_cli("solve " + quote(instance(box_corner)) + " --json");
    CHECK(after.status == 0);
    CHECK(parse_json(after.out)["reflections"] == 6);
}

TEST_CASE("solve --json on a cycle", "[cli]") {
    const CliResult r = run_cli("solve --json " + quote(instance(unit_square)));
    CHECK(r.status == 1);
    CHECK(r.err.empty());
    const nlohmann::json j = parse_json(r.out);
    CHECK(j["answer"] == "no");
    CHECK(j["reason"] == "cycle");
    REQUIRE(j["reflections"].is_number_integer());
    CHECK(j["reflections"] == 10);
    REQUIRE(j.contains("period"));
    REQUIRE(j["period"].is_number_integer());
    CHECK(j["period"] == 10);
}

TEST_CASE("solve --max-steps stops with status 3 and answer unknown", "[cli]") {
    const CliResult r = run_cli("solve --json --max-steps 3 " + quote(instance(unit_square)));
    CHECK(r.status == 3);
    CHECK(r.err.empty());
    const nlohmann::json j = parse_json(r.out);
    CHECK(j["answer"] == "unknown");
    CHECK(j["reason"] == "limit");
    REQUIRE(j["reflections"].is_number_integer());
    CHECK(j["reflections"] == 3);
    CHECK_FALSE(j.contains("period"));

    // A limit above what the instance needs changes nothing.
    const CliResult enough = run_cli("solve --json --max-steps 100 " + quote(instance(box_corner)));
    CHECK(enough.status == 0);
    CHECK(parse_json(enough.out)["reflections"] == 6);

    // The text output says the same.
    const CliResult text = run_cli("solve --max-steps 3 " + quote(instance(unit_square)));
    CHECK(text.status == 3);
    CHECK(text.out.find("unknown") != std::string::npos);
    CHECK(text.out.find("limit") != std::string::npos);
}

TEST_CASE("reflections is written as a JSON integer in full", "[cli]") {
    // A count above 2^64 is out of reach of a test run, so check the form:
    // the value after "reflections": is a bare run of decimal digits.
    for (const std::string& name : {box_corner, unit_square}) {
        const CliResult r = run_cli("solve --json " + quote(instance(name)));
        const std::string key = "\"reflections\":";
        const std::size_t at = r.out.find(key);
        REQUIRE(at != std::string::npos);
        std::size_t end = at + key.size();
        while (end < r.out.size() && r.out[end] >= '0' && r.out[end] <= '9') ++end;
        CHECK(end > at + key.size());
        REQUIRE(end < r.out.size());
        CHECK((r.out[end] == ',' || r.out[end] == '}'));
        CHECK(parse_json(r.out)["reflections"].is_number_unsigned());
    }
}

TEST_CASE("the default output is a short human summary", "[cli]") {
    const CliResult yes = run_cli("solve " + quote(instance(box_corner)));
    CHECK(yes.status == 0);
    CHECK(yes.err.empty());
    // Whole lines: a name, spaces to the value's column, the value.
    CHECK(yes.out.find("answer       yes\n") == 0);
    CHECK(yes.out.find("\nreason       hit\n") != std::string::npos);
    CHECK(yes.out.find("\nreflections  6\n") != std::string::npos);
    CHECK(yes.out.find('{') == std::string::npos); // not JSON
    CHECK(std::count(yes.out.begin(), yes.out.end(), '\n') <= 10);

    const CliResult no = run_cli("solve " + quote(instance(unit_square)));
    CHECK(no.status == 1);
    CHECK(no.out.find("answer       no\n") == 0);
    CHECK(no.out.find("\nreason       cycle\n") != std::string::npos);
    CHECK(no.out.find("\nperiod       10\n") != std::string::npos);
}

TEST_CASE("a scene written by hand in a temporary file solves", "[cli]") {
    TempDir dir;
    // One mirror straight ahead: the ray comes back through its start and
    // escapes; the target behind the start is on the way back.
    const std::string file = dir.write("back.scene", "dim 2\r\n"
                                                     "mirror x 4 y -1 1\t# wall\r\n"
                                                     "ray 0 0 1 0\r\n"
                                                     "target -3 0\r\n");
    const CliResult r = run_cli("solve --json " + quote(file));
    CHECK(r.status == 0);
    const nlohmann::json j = parse_json(r.out);
    CHECK(j["answer"] == "yes");
    CHECK(j["reflections"] == 1);

    const std::string away = dir.write("away.scene", "dim 3\nray 0 0 0 1 1 1\ntarget -1 0 0\n");
    const CliResult e = run_cli("solve --json " + quote(away));
    CHECK(e.status == 1);
    const nlohmann::json k = parse_json(e.out);
    CHECK(k["answer"] == "no");
    CHECK(k["reason"] == "escape");
    CHECK(k["reflections"] == 0);
}

// ---------------------------------------------------------------- certificates

TEST_CASE("solve --certificate then verify says valid", "[cli]") {
    TempDir dir;
    for (const std::string& name : {box_corner, unit_square}) {
        INFO(name);
        const std::string cert = dir.path("out.cert");
        const CliResult s =
            run_cli("solve --json " + quote(instance(name)) + " --certificate " + quote(cert));
        CHECK((s.status == 0 || s.status == 1));
        parse_json(s.out); // the certificate does not disturb the JSON on stdout
        REQUIRE(fs::exists(cert));
        const CliResult v = run_cli("verify " + quote(instance(name)) + " " + quote(cert));
        INFO(v.out << v.err);
        CHECK(v.status == 0);
        CHECK(v.out.starts_with("valid"));
        CHECK(is_one_line(v.out));
        CHECK(v.err.empty());
    }
}

TEST_CASE("a tampered certificate is invalid", "[cli]") {
    TempDir dir;
    const std::string cert = dir.path("out.cert");
    REQUIRE(
        run_cli("solve " + quote(instance(box_corner)) + " --certificate " + quote(cert)).status ==
        0);
    const std::string good = slurp(cert);

    // Move the second reflection point, (1, 5), off the path.
    const std::string from = "\npoint 1 5\n";
    const std::size_t at = good.find(from);
    REQUIRE(at != std::string::npos);
    std::string bad = good;
    bad.replace(at, from.size(), "\npoint 1 4\n");
    const std::string bad_cert = dir.write("bad.cert", bad);
    const CliResult v = run_cli("verify " + quote(instance(box_corner)) + " " + quote(bad_cert));
    INFO(v.out << v.err);
    CHECK(v.status == 1);
    CHECK(v.out.starts_with("invalid"));
    CHECK(is_one_line(v.out));

    // A certificate checked against another scene is invalid too.
    const CliResult other = run_cli("verify " + quote(instance(unit_square)) + " " + quote(cert));
    CHECK(other.status == 1);
    CHECK(other.out.starts_with("invalid"));

    // A cut-off certificate (no final `end`) never verifies.
    const std::string cut = dir.write("cut.cert", good.substr(0, good.find("answer")));
    const CliResult c = run_cli("verify " + quote(instance(box_corner)) + " " + quote(cut));
    CHECK(c.status == 1);
    CHECK(c.out.starts_with("invalid"));
}

TEST_CASE("a --max-steps certificate is partial and exits 1", "[cli]") {
    TempDir dir;
    const std::string cert = dir.path("partial.cert");
    const CliResult s = run_cli("solve --max-steps 3 " + quote(instance(unit_square)) +
                                " --certificate " + quote(cert));
    CHECK(s.status == 3);
    const CliResult v = run_cli("verify " + quote(instance(unit_square)) + " " + quote(cert));
    CHECK(v.status == 1);
    CHECK(v.out.find("partial") != std::string::npos);
}

TEST_CASE("a malformed certificate is bad input", "[cli]") {
    TempDir dir;
    const std::string cert = dir.write("junk.cert", "not a certificate\n");
    const CliResult v = run_cli("verify " + quote(instance(box_corner)) + " " + quote(cert));
    require_bad_input(v);
    CHECK(v.err.starts_with(cert + ":1:1: "));
}

TEST_CASE("solve on generated long orbits gives the closed-form answer", "[cli][slow]") {
    // The command line steps in chunks (it polls for limits and signals) and
    // switches 2D runs to piece tables: both must resume exactly. Each scene
    // states its answer in an '# expect:' line.
    TempDir dir;
    const std::vector<std::string> families = {
        "coprime-box --k 15",          // 65,535 reflections: past the grid phase, on piece tables
        "square --direction 1000 999", // cycle of period 3,998
        "hallway --length 100000 --slope 1/1000", // hit after 100
        "coprime-cuboid --k 4 --target far",      // 3D
        "box --sides 4999 5001 --target far"};    // 2D, long
    for (const std::string& family : families) {
        INFO(family);
        const std::string scene = dir.path("s.scene");
        REQUIRE(run_cli("generate " + family + " -o " + quote(scene)).status == 0);
        const std::string text = slurp(scene);
        const std::size_t at = text.find("# expect: ");
        REQUIRE(at != std::string::npos);
        std::istringstream expect(text.substr(at + 10, text.find('\n', at) - at - 10));
        std::string answer, reason, count;
        expect >> answer >> reason >> count;
        // Simulation on its own (chunks, then tables), the default (which
        // induces once the grid phase is over) and induction from the start.
        for (const std::string engine : {"lattice", "auto", "induction"}) {
            INFO("engine " << engine);
            const nlohmann::json j =
                parse_json(run_cli("solve --json --engine " + engine + " " + quote(scene)).out);
            CHECK(j["answer"] == answer);
            CHECK(j["reason"] == reason);
            CHECK(j[reason == "cycle" ? "period" : "reflections"].dump() == count);
        }
    }
}

TEST_CASE("solve --engine induction reports the exchange it decided on", "[cli][induction]") {
    const nlohmann::json j =
        parse_json(run_cli("solve --json --engine induction " + quote(instance(box_corner))).out);
    CHECK(j["answer"] == "yes");
    CHECK(j["reflections"] == 6);
    CHECK(j["engine"] == "induction");
    CHECK(j["exchange_pieces"] == 26);
    CHECK(j["exchange_states"] == 32);
    CHECK(j["induction_steps"] == 25);
    CHECK(j["induction_seconds"].is_number());
    // The text summary names the engine and its steps.
    const CliResult text = run_cli("solve --engine induction " + quote(instance(box_corner)));
    CHECK(text.out.find("induction    25 steps on 26 pieces, 32 states") != std::string::npos);
}

TEST_CASE("the default engine answers a 2^61 box by induction, in full", "[cli][induction]") {
    // (2^61 + 1) x 2^61 from a corner: 2^62 - 1 reflections, beyond any simulation.
    TempDir dir;
    const std::string scene = dir.path("big.scene");
    REQUIRE(
        run_cli("generate box --sides 2305843009213693953 2305843009213693952 -o " + quote(scene))
            .status == 0);
    const CliResult r = run_cli("solve --json " + quote(scene));
    CHECK(r.status == 0);
    const nlohmann::json j = parse_json(r.out);
    CHECK(j["engine"] == "induction");
    CHECK(j["reflections"].dump() == "4611686018427387903");
}

TEST_CASE("a step limit holds for the induction engine too", "[cli][induction]") {
    // 65,535 reflections are needed; the induction knows at once, and the
    // limit then stops a simulation at exactly 1,000, as without induction.
    TempDir dir;
    const std::string scene = dir.path("long.scene");
    REQUIRE(run_cli("generate coprime-box --k 15 -o " + quote(scene)).status == 0);
    for (const std::string engine : {"auto", "induction"}) {
        INFO(engine);
        const CliResult r =
            run_cli("solve --json --engine " + engine + " --max-steps 1000 " + quote(scene));
        CHECK(r.status == 3);
        const nlohmann::json j = parse_json(r.out);
        CHECK(j["limit"] == "steps");
        CHECK(j["reflections"] == 1000);
        const CliResult enough =
            run_cli("solve --json --engine " + engine + " --max-steps 65535 " + quote(scene));
        CHECK(enough.status == 0);
        CHECK(parse_json(enough.out)["reflections"] == 65535);
    }
}

TEST_CASE("'-' reads the scene from standard input", "[cli]") {
    const std::string box = source_path("instances/2d/box-corner-3x5.scene");
    const CliResult piped = run_cli("solve --json -", box);
    const CliResult named = run_cli("solve --json " + quote(box));
    REQUIRE(piped.status == 0);
    CHECK(nlohmann::json::parse(piped.out)["reflections"] ==
          nlohmann::json::parse(named.out)["reflections"]);
    // Errors name the file '-'; JSON needs --format json, as nothing names it.
    const CliResult bad = run_cli("solve -");
    CHECK(bad.status == 2);
    CHECK(bad.err.starts_with("-:1:1: found end of file"));
}

TEST_CASE("verify --json gives the verdict as one JSON object", "[cli]") {
    TempDir dir;
    const std::string box = source_path("instances/2d/box-corner-3x5.scene");
    const std::string cert = dir.path("box.cert");
    REQUIRE(run_cli("solve --certificate " + quote(cert) + " " + quote(box)).status == 0);
    const CliResult good = run_cli("verify --json " + quote(box) + " " + quote(cert));
    CHECK(good.status == 0);
    const nlohmann::json verdict = nlohmann::json::parse(good.out);
    CHECK(verdict["valid"] == true);
    // The message is the text verdict, without its newline.
    CHECK(verdict["message"].get<std::string>() + "\n" ==
          run_cli("verify " + quote(box) + " " + quote(cert)).out);
    // Another scene's certificate: invalid, exit 1, still one object.
    const CliResult bad =
        run_cli("verify --json " + quote(source_path("instances/2d/box-corner-4x6.scene")) + " " +
                quote(cert));
    CHECK(bad.status == 1);
    CHECK(nlohmann::json::parse(bad.out)["valid"] == false);
}
