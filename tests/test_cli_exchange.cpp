// The command line for exchange and pictures: convert both ways on every
// instance, solve/verify/pieces on JSON scenes, malformed JSON as exit 2
// with one FILE:LINE:COL line, JSON Lines certificates verified and
// tampered ones rejected, and render writing SVG and PNG.
#include "support/cli_checks.hpp"
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"
#include "support/xml_check.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace orthoray::test;

namespace {

namespace fs = std::filesystem;

// The first line of `solve` (answer ...) and its exit status.
std::string answer_of(const CliResult& r) {
    return std::to_string(r.status) + " " + r.out.substr(0, r.out.find('\n'));
}

std::vector<std::string> instance_names() {
    const fs::path root = source_path("instances");
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file() && entry.path().extension() == ".scene")
            names.push_back(fs::relative(entry.path(), root).generic_string());
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

TEST_CASE("convert round-trips every instance and solve agrees on both formats",
          "[cli][json][slow]") {
    TempDir dir;
    for (const std::string& name : instance_names()) {
        INFO(name);
        const std::string json = dir.path("s.json"), back = dir.path("back.scene"),
                          again = dir.path("again.scene");
        const CliResult to_json = run_cli("convert " + quote(instance(name)) + " " + quote(json));
        REQUIRE(to_json.status == 0);
        CHECK(to_json.out.empty());
        REQUIRE(run_cli("convert " + quote(json) + " " + quote(back)).status == 0);
        // .scene -> .scene is the canonical text; through JSON it is the same.
        REQUIRE(run_cli("convert " + quote(instance(name)) + " " + quote(again)).status == 0);
        CHECK(slurp(back) == slurp(again));
        CHECK(answer_of(run_cli("solve " + quote(json))) ==
              answer_of(run_cli("solve " + quote(instance(name)))));
        const CliResult bounds_json = run_cli("bounds --json " + quote(json));
        CHECK(bounds_json.status == 0);
        CHECK(bounds_json.out == run_cli("bounds --json " + quote(instance(name))).out);
    }
}

TEST_CASE("the format option overrides the extension", "[cli][json][slow]") {
    TempDir dir;
    const std::string json = dir.path("box.json");
    REQUIRE(run_cli("convert " + quote(instance("2d/box-corner-3x5.scene")) + " " + quote(json))
                .status == 0);
    const std::string txt = dir.write("box.txt", slurp(json));
    CHECK(run_cli("solve --format json " + quote(txt)).status == 0);
    CHECK(run_cli("pieces --format json " + quote(txt)).status == 0);
    CHECK(run_cli("bounds --format json " + quote(txt)).status == 0);
    const CliResult as_text = run_cli("solve " + quote(txt));
    require_bad_input(as_text);
    CHECK(as_text.err.rfind(txt + ":1:1: found '{'", 0) == 0);
    require_bad_input(run_cli("solve --format yaml " + quote(txt)));
    // convert --to picks the output format whatever the name
    const std::string out = dir.path("out.txt");
    REQUIRE(run_cli("convert --to json " + quote(instance("2d/box-corner-3x5.scene")) + " " +
                    quote(out))
                .status == 0);
    CHECK(slurp(out) == slurp(json));
}

TEST_CASE("malformed JSON scenes exit 2 with one FILE:LINE:COL line", "[cli][json][errors]") {
    TempDir dir;
    const std::string bad = dir.write("bad.json", "{\n  \"dim\": 2,\n  \"elements\": [}\n");
    for (const char* command : {"solve", "verify", "pieces", "render", "convert"}) {
        INFO(command);
        std::string args = std::string(command) + " " + quote(bad);
        if (std::string(command) == "verify") args += " " + quote(bad);
        if (std::string(command) == "convert") args += " " + quote(dir.path("x.scene"));
        if (std::string(command) == "render") args += " -o " + quote(dir.path("x.svg"));
        const CliResult r = run_cli(args);
        require_bad_input(r);
        CHECK(r.err == bad + ":3:16: found '}', expected '[', '{', or a literal\n");
    }
    CHECK_FALSE(fs::exists(dir.path("x.scene")));
    CHECK_FALSE(fs::exists(dir.path("x.svg")));
    const std::string not_scene = dir.write("n.json", "{\"dim\": 2, \"elements\": 3}");
    const CliResult r = run_cli("solve " + quote(not_scene));
    require_bad_input(r);
    CHECK(r.err == not_scene + ":1:24: found the number 3, expected an array of mirrors, "
                               "absorbers and splitters\n");
}

TEST_CASE("JSON Lines certificates verify, and tampered ones do not", "[cli][jsonl]") {
    TempDir dir;
    const std::string scene = instance("2d/unit-square-slope-2-3.scene");
    const std::string cert = dir.path("c.jsonl");
    const CliResult solved = run_cli("solve " + quote(scene) + " --certificate " + quote(cert) +
                                     " --certificate-format jsonl");
    CHECK(solved.status == 1);
    const CliResult ok = run_cli("verify " + quote(scene) + " " + quote(cert));
    CHECK(ok.status == 0);
    CHECK(ok.out == "valid: cycle, 10 reflections\n");

    std::string text = slurp(cert);
    const std::size_t period = text.find("\"period\": \"10\"");
    REQUIRE(period != std::string::npos);
    const std::string tampered =
        dir.write("t.jsonl", std::string(text).replace(period, 14, "\"period\": \"5\""));
    const CliResult rejected = run_cli("verify " + quote(scene) + " " + quote(tampered));
    CHECK(rejected.status == 1);
    CHECK(rejected.out.rfind("invalid: verdict: period 5", 0) == 0);

    const std::string broken = dir.write("b.jsonl", text.substr(0, 40) + "\n");
    const CliResult malformed = run_cli("verify " + quote(scene) + " " + quote(broken));
    require_bad_input(malformed);
    CHECK(malformed.err.rfind(broken + ":2:", 0) == 0);

    require_bad_input(run_cli("solve " + quote(scene) + " --certificate " + quote(cert) +
                              " --certificate-format xml"));
    // A format without a file to write is a usage error, not silently ignored.
    const CliResult no_file = run_cli("solve " + quote(scene) + " --certificate-format jsonl");
    require_bad_input(no_file);
    CHECK(no_file.err.find("--certificate") != std::string::npos);
}

TEST_CASE("render writes an SVG of the solver's path or a certificate's", "[cli][render][slow]") {
    TempDir dir;
    const std::string scene = instance("2d/box-corner-3x5.scene");
    const std::string svg = dir.path("box.svg");
    const CliResult r = run_cli("render " + quote(scene) + " -o " + quote(svg));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == "wrote " + svg + " (7 segments)\n"); // 6 reflections, then the target
    const auto doc = orthoray::test::read_xml(slurp(svg));
    INFO(doc.error);
    CHECK(doc.well_formed);
    CHECK(slurp(svg).find("answer yes, reason hit, 6 reflections") != std::string::npos);
    // The count is the segments drawn, however the path ends: three
    // reflections then out to the frame, or then into the absorber.
    for (const char* name :
         {"escape-after-three-reflections", "absorbed-after-three-reflections"}) {
        INFO(name);
        const CliResult ended =
            run_cli("render " + quote(instance(std::string("2d/") + name + ".scene")) + " -o " +
                    quote(dir.path("ended.svg")));
        CHECK(ended.out == "wrote " + dir.path("ended.svg") + " (4 segments)\n");
    }

    for (const char* format : {"text", "jsonl"}) {
        INFO(format);
        const std::string cert = dir.path(std::string("c.") + format);
        REQUIRE(run_cli("solve " + quote(scene) + " --certificate " + quote(cert) +
                        " --certificate-format " + format)
                    .status == 0);
        const std::string from_cert = dir.path("cert.svg");
        const CliResult c = run_cli("render " + quote(scene) + " --certificate " + quote(cert) +
                                    " -o " + quote(from_cert));
        CHECK(c.status == 0);
        const std::string picture = slurp(from_cert);
        CHECK(orthoray::test::read_xml(picture).well_formed);
        CHECK(picture.find("(claimed by c.") != std::string::npos);
        const CliResult two = run_cli("render " + quote(scene) + " --certificate " + quote(cert) +
                                      " --steps 2 -o " + quote(from_cert));
        CHECK(two.out == "wrote " + from_cert + " (2 segments)\n");
    }

    const std::string bad_cert = dir.write("bad.cert", "orthoray-certificate 1\ndim 3\n");
    const std::string not_written = dir.path("never.svg");
    const CliResult bad = run_cli("render " + quote(scene) + " --certificate " + quote(bad_cert) +
                                  " -o " + quote(not_written));
    require_bad_input(bad);
    CHECK(bad.err == bad_cert + ":2:5: found '3', expected '2' (the scene's dim)\n");
    CHECK_FALSE(fs::exists(not_written));
    require_bad_input(run_cli("render " + quote(scene) + " --steps 0 -o " + quote(not_written)));
}

TEST_CASE("render draws an induction certificate's path by simulating it", "[cli][render]") {
    // The induction engine's certificate lists the path up to the first
    // reflection only: the caption is its claim, the picture the simulated
    // path.
    TempDir dir;
    const std::string scene = instance("2d/box-corner-3x5.scene");
    const std::string cert = dir.path("induced.cert");
    REQUIRE(run_cli("solve " + quote(scene) + " --engine induction --certificate " + quote(cert))
                .status == 0);
    REQUIRE(slurp(cert).find("method induction") != std::string::npos);
    const std::string svg = dir.path("induced.svg");
    const CliResult r =
        run_cli("render " + quote(scene) + " --certificate " + quote(cert) + " -o " + quote(svg));
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(r.out == "wrote " + svg + " (7 segments)\n"); // 6 reflections, then the target
    const std::string picture = slurp(svg);
    CHECK(picture.find("answer yes, reason hit, 6 reflections (claimed by induced.cert") !=
          std::string::npos);
    CHECK(picture.find("path: simulated; the induction certificate lists 2 points only") !=
          std::string::npos);
    // Cut before its verdict: drawn all the same, and said to be incomplete.
    const std::string text = slurp(cert);
    const std::string cut = dir.write("cut.cert", text.substr(0, text.find("answer")));
    const CliResult c =
        run_cli("render " + quote(scene) + " --certificate " + quote(cut) + " -o " + quote(svg));
    CHECK(c.status == 0);
    CHECK(slurp(svg).find("incomplete certificate cut.cert") != std::string::npos);
}

TEST_CASE("render draws the prefix the default engine's induction certificate lists",
          "[cli][render]") {
    // The default engine simulates 16,384 reflections of the 2^20 + 1 by
    // 2^20 box before it induces, and its certificate lists them: they are
    // the path's, drawn as a path certificate's are, and nothing is
    // simulated on top of them.
    TempDir dir;
    const std::string scene = dir.path("box.scene"), cert = dir.path("box.cert");
    REQUIRE(run_cli("generate coprime-box --k 20 -o " + quote(scene)).status == 0);
    REQUIRE(run_cli("solve " + quote(scene) + " --certificate " + quote(cert)).status == 0);
    REQUIRE(slurp(cert).find("method induction") != std::string::npos);
    const std::string svg = dir.path("box.svg");
    CliResult r =
        run_cli("render " + quote(scene) + " --certificate " + quote(cert) + " -o " + quote(svg));
    INFO(r.err);
    CHECK(r.status == 0);
    std::string picture = slurp(svg);
    CHECK(picture.find("path: the 16385 points the induction certificate lists before its "
                       "proof") != std::string::npos);
    CHECK(picture.find("simulated") == std::string::npos);
    r = run_cli("render " + quote(scene) + " --certificate " + quote(cert) + " --steps 100 -o " +
                quote(svg));
    CHECK(r.status == 0);
    CHECK(r.out.find("(100 segments") != std::string::npos);
    picture = slurp(svg);
    CHECK(picture.find("path: the first 100 segments of the certificate (--steps)") !=
          std::string::npos);
    CHECK(picture.find("simulated") == std::string::npos);
}

TEST_CASE("render writes a PNG through rsvg-convert", "[cli][render][slow]") {
    TempDir dir;
    const std::string png = dir.path("cube.png");
    const CliResult r = run_cli("render " + quote(instance("3d/corner-cube-retroreflector.scene")) +
                                " -o " + quote(png));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const std::string bytes = slurp(png);
    REQUIRE(bytes.size() > 1000);
    CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);

    // A picture far larger than a pipe holds (about 0.9 MB from a 28 kB SVG)
    // comes through whole, and nothing but the target is left in its folder.
    const std::string scene = dir.write("long.scene", "dim 2\n"
                                                      "mirror x 0 y 0 997\n"
                                                      "mirror x 1000 y 0 997\n"
                                                      "mirror y 0 x 0 1000\n"
                                                      "mirror y 997 x 0 1000\n"
                                                      "ray 0 1 1 1\n"
                                                      "target 3 7/2\n");
    const std::string long_png = dir.path("long.png");
    const CliResult big =
        run_cli("render " + quote(scene) + " --steps 20000 -o " + quote(long_png));
    INFO(big.err);
    REQUIRE(big.status == 0);
    const std::string long_bytes = slurp(long_png);
    CHECK(long_bytes.size() > (1u << 18));
    CHECK(long_bytes.compare(long_bytes.size() - 8, 8, "IEND\xae\x42\x60\x82") == 0);
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path("")))
        left.push_back(entry.path().filename().string());
    std::sort(left.begin(), left.end());
    CHECK(left == std::vector<std::string>{"cube.png", "long.png", "long.scene"});
}

TEST_CASE("render without rsvg-convert says so and leaves the PNG target alone", "[cli][render]") {
    TempDir dir;
    const std::string png = dir.write("old.png", "the previous picture");
    const orthoray::test::ShellResult r =
        orthoray::test::run_shell("PATH=/nonexistent \"$ORTHORAY\" render " +
                                  quote(instance("2d/box-corner-3x5.scene")) + " -o " + quote(png));
    CHECK(r.status == 2);
    CHECK(r.err == "orthoray: PNG output needs the program rsvg-convert (Debian package "
                   "librsvg2-bin); install it, or write an .svg file instead\n");
    CHECK(slurp(png) == "the previous picture");
    CHECK(std::distance(std::filesystem::directory_iterator(dir.path("")),
                        std::filesystem::directory_iterator{}) == 1);
}

TEST_CASE("render and convert explain themselves with an example", "[cli]") {
    for (const char* args : {"render --help", "convert --help"}) {
        INFO("orthoray " << args);
        const CliResult r = run_cli(args);
        CHECK(r.status == 0);
        CHECK(r.out.find("Example:") != std::string::npos);
        const bool names_format = r.out.find("--format") != std::string::npos ||
                                  r.out.find("--from") != std::string::npos;
        CHECK(names_format);
    }
    const CliResult top = run_cli("--help");
    CHECK(top.out.find("render") != std::string::npos);
    CHECK(top.out.find("convert") != std::string::npos);
}
