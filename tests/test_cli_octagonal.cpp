// The command line on octagonal scenes (docs/octagonal.md): solve with the
// engines that follow diagonals, their certificates through verify, the
// refusal of the others, and render.
#include "support/run_cli.hpp"
#include "support/test_files.hpp"
#include "support/xml_check.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace orthoray::test;

namespace {

// Left to '/' at (1, 4), down past the x-mirror to '/' at (1, 1), then
// between the wall x = -1 and (1, 1), where the diagonal and the
// x-mirror's end send the ray back: tail 1, period 2.
const std::string tail_scene = "dim 2\nmirror / 0 3 2 5\nmirror / 0 0 2 2\nmirror x 1 y 1 3\n"
                               "mirror x -1 y 0 5\nray 3 4 -1 0\ntarget 9 9\n";

nlohmann::json json_of(const CliResult& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    return nlohmann::json::parse(r.out);
}

} // namespace

TEST_CASE("solve follows diagonals with every engine", "[cli][octagonal]") {
    TempDir dir;
    const std::string file = dir.write("tail.scene", tail_scene);
    for (const std::string engine : {"auto", "lattice", "induction", "reference", "graph"}) {
        const CliResult r = run_cli("solve --json --engine " + engine + " " + quote(file));
        CHECK(r.status == 1);
        const nlohmann::json j = json_of(r);
        CHECK(j["reason"] == "cycle");
        CHECK(j["tail"] == 1);
        CHECK(j["period"] == 2);
        CHECK(j["reflections"] == 3);
    }
}

TEST_CASE("a diagonal scene's certificate verifies, and render draws it", "[cli][octagonal]") {
    TempDir dir;
    const std::string file = dir.write("tail.scene", tail_scene);
    const std::string cert = dir.path("tail.cert");
    const CliResult solved =
        run_cli("solve --engine reference --certificate " + quote(cert) + " " + quote(file));
    CHECK(solved.status == 1);
    const CliResult checked = run_cli("verify " + quote(file) + " " + quote(cert));
    INFO(checked.out << checked.err);
    CHECK(checked.status == 0);
    CHECK(checked.out.find("valid: cycle, 3 reflections") != std::string::npos);
    const std::string svg = dir.path("tail.svg");
    const CliResult drawn = run_cli("render " + quote(file) + " -o " + quote(svg));
    INFO(drawn.out << drawn.err);
    CHECK(drawn.status == 0);
    CHECK(drawn.out.find("wrote ") == 0);
    // The picture: the four mirrors in one path, two of them slanted, and
    // the ray's path from its start.
    const XmlDocument picture = read_xml(slurp(svg));
    INFO(picture.error);
    REQUIRE(picture.well_formed);
    const auto mirrors = with_class(picture, "path", "mirror");
    REQUIRE(mirrors.size() == 1);
    std::istringstream moves(mirrors[0]->attributes.at("d"));
    int drawn_mirrors = 0, slanted = 0;
    for (char m, l; moves >> m;) {
        double x0, y0, x1, y1;
        REQUIRE((m == 'M' && moves >> x0 >> y0 >> l >> x1 >> y1 && l == 'L'));
        ++drawn_mirrors;
        slanted += x0 != x1 && y0 != y1;
    }
    CHECK(drawn_mirrors == 4);
    CHECK(slanted == 2);
    CHECK(!with_class(picture, "path", "trajectory").empty());
}

TEST_CASE("the walk through the command line: pieces shows the collisions, induction certifies",
          "[cli][octagonal]") {
    // The tail scene's map is no bijection (the x-mirror's end meets a ray
    // sliding along the lower '/'): `pieces` lists its collisions, and the
    // induction engine's certificate is a walk that verify accepts.
    TempDir dir;
    const std::string file = dir.write("tail.scene", tail_scene);
    const CliResult pieces = run_cli("pieces " + quote(file));
    INFO(pieces.out << pieces.err);
    CHECK(pieces.status == 0);
    CHECK(pieces.out.find("\ncollision ") != std::string::npos);
    const std::string cert = dir.path("walk.cert");
    const CliResult solved =
        run_cli("solve --engine induction --certificate " + quote(cert) + " " + quote(file));
    CHECK(solved.status == 1);
    CHECK(solved.out.find("induction") != std::string::npos);
    CHECK(slurp(cert).find("\nwalk-search ") != std::string::npos);
    const CliResult checked = run_cli("verify " + quote(file) + " " + quote(cert));
    INFO(checked.out << checked.err);
    CHECK(checked.status == 0);
    CHECK(checked.out.find("valid: cycle, 3 reflections") != std::string::npos);
}

TEST_CASE("exchange and pieces say why a diagonal scene has none", "[cli][octagonal]") {
    // The tail scene has collisions, so no exchange; a ray absorbed before
    // it reflects has no tables. Each message names the diagonal case's own
    // conditions, not the axis-parallel ones (a ray moving along neither
    // axis), which both scenes meet.
    TempDir dir;
    const std::string tail = dir.write("tail.scene", tail_scene);
    const CliResult exchange = run_cli("exchange " + quote(tail));
    CHECK(exchange.status == 2);
    CHECK(exchange.out.empty());
    CHECK(exchange.err.find("where no two states step to one") != std::string::npos);
    const std::string absorbed =
        dir.write("absorbed.scene", "dim 2\nabsorber / 3 4 7 8\nmirror x 0 y 0 9\n"
                                    "ray 3 5 1 -1\ntarget 100 100\n");
    for (const std::string command : {"pieces", "exchange"}) {
        INFO(command);
        const CliResult r = run_cli(command + " " + quote(absorbed));
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.find("whose ray reflects at least once") != std::string::npos);
        CHECK(r.err.find("moves in both x and y") == std::string::npos);
    }
}
