// The exports for other programs: `pieces --json` (the piece tables) and
// `exchange` (the interval exchange, text and JSON), and the scenes each
// refuses with one message and exit 2.
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace orthoray::test;

namespace {

const std::string box_corner = "2d/box-corner-3x5.scene";

nlohmann::json json_of(const CliResult& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.status == 0);
    return nlohmann::json::parse(r.out);
}

void require_refused(const CliResult& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

} // namespace

TEST_CASE("pieces --json lists the elements and every piece", "[cli][pieces]") {
    const nlohmann::json j = json_of(run_cli("pieces --json " + quote(instance(box_corner))));
    CHECK(j["scale"] == nlohmann::json::array({1, 1}));
    CHECK(j["elements"].size() == 4);
    CHECK(j["pieces"].size() == 32);
    // From (0, 2) on the left wall, moving up and right, the ray reaches the
    // corner (3, 5) at t = 3 and flips both components (as the text says).
    const nlohmann::json expected = {{"element", 0},      {"direction", "+x+y"}, {"from", 2},
                                     {"kind", "reflect"}, {"next", 3},           {"t0", 3},
                                     {"slope", 0},        {"flip", "xy"}};
    CHECK(std::find(j["pieces"].begin(), j["pieces"].end(), expected) != j["pieces"].end());
    TempDir dir;
    const std::string diagonal =
        dir.write("d.scene", "dim 2\nmirror / 0 0 4 4\nmirror x 6 y -9 9\nray 5 1 -1 0\n"
                             "target 9 9\n");
    require_refused(run_cli("pieces --json " + quote(diagonal)));
    require_refused(
        run_cli("pieces --json " + quote(source_path("instances/3d/box-corner-1x2x3.scene"))));
}

TEST_CASE("exchange writes the two-row form in text and JSON", "[cli][exchange]") {
    const CliResult text = run_cli("exchange " + quote(instance(box_corner)));
    CHECK(text.status == 0);
    CHECK(text.out.starts_with("orthoray-exchange 1\n"));
    CHECK(text.out.find("\nsize 32\n") != std::string::npos);
    CHECK(text.out.ends_with("\nend\n"));
    const nlohmann::json j = json_of(run_cli("exchange --json " + quote(instance(box_corner))));
    CHECK(j["format"] == "orthoray-exchange");
    CHECK(j["size"] == 32);
    CHECK(j["pieces"].size() == 26);
    CHECK(j["top"].size() == 26);
    CHECK(j["bottom"].size() == 26);
    // Piece 0 is the state after the first reflection, alone.
    CHECK(j["pieces"][0]["start"] == 0);
    CHECK(j["pieces"][0]["length"] == 1);
    TempDir dir;
    const std::string one_sided =
        dir.write("o.scene", "dim 2\nmirror x+ 0 y 0 9\nmirror x 9 y 0 9\nmirror y 0 x 0 9\n"
                             "mirror y 9 x 0 9\nray 1 2 1 1\ntarget 50 50\n");
    require_refused(run_cli("exchange " + quote(one_sided)));
    require_refused(
        run_cli("exchange " + quote(source_path("instances/3d/box-corner-1x2x3.scene"))));
}
