// `orthoray solve` on the scenes of docs/optics.md: the per-target summary
// and JSON, `tail` on every cycle, exit statuses, the refused certificate
// of a one-sided single trajectory, and `convert` round trips of splitters, sides and several rays.
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace orthoray::test;

namespace {

const std::string splitter_scene = "dim 2\nsplitter x 2 y -1 1\ntarget 5 0\ntarget -3 0\n"
                                   "target 2 -3\nray 0 0 1 0\n";
const std::string rho_scene = "dim 2\nmirror x 0 y 0 10\nmirror x 10 y 0 10\n"
                              "mirror x+ 5 y 0 10\nray 2 3 -1 0\ntarget 100 100\n";

nlohmann::json json_of(const CliResult& r) {
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    return nlohmann::json::parse(r.out);
}

} // namespace

TEST_CASE("solve answers the illumination question target by target", "[cli][optics]") {
    TempDir dir;
    const std::string file = dir.write("split.scene", splitter_scene);
    const CliResult text = run_cli("solve " + quote(file));
    CHECK(text.status == 1);
    CHECK(text.out.find("target 1  lit after 0 reflections by ray 1\n") != std::string::npos);
    CHECK(text.out.find("target 2  lit after 1 reflections by ray 1\n") != std::string::npos);
    CHECK(text.out.find("target 3  unlit\n") != std::string::npos);
    CHECK(text.out.find("reason       unlit\n") != std::string::npos);

    const CliResult r = run_cli("solve --json " + quote(file));
    CHECK(r.status == 1);
    const nlohmann::json j = json_of(r);
    CHECK(j["answer"] == "no");
    CHECK(j["reason"] == "unlit");
    CHECK(j["states"] == 3);
    REQUIRE(j["targets"].size() == 3);
    CHECK(j["targets"][0] ==
          nlohmann::json::parse(R"({"target":1,"answer":"yes","reflections":0,"ray":1})"));
    CHECK(j["targets"][1] ==
          nlohmann::json::parse(R"({"target":2,"answer":"yes","reflections":1,"ray":1})"));
    CHECK(j["targets"][2] == nlohmann::json::parse(R"({"target":3,"answer":"no"})"));
    CHECK(r.out.find("\"reflections\":1,\"ray\":1}") != std::string::npos); // an integer

    // Every target lit: exit 0.
    const std::string lit = dir.write("lit.scene", "dim 2\nsplitter x 2 y -1 1\ntarget 5 0\n"
                                                   "target -3 0\nray 0 0 1 0\n");
    const CliResult all = run_cli("solve --json " + quote(lit));
    CHECK(all.status == 0);
    CHECK(json_of(all)["reason"] == "lit");

    // A limit: exit 3, what is lit so far stays lit, the rest is unknown.
    const CliResult limited = run_cli("solve --json --max-steps 2 " + quote(file));
    CHECK(limited.status == 3);
    const nlohmann::json l = json_of(limited);
    CHECK(l["reason"] == "limit");
    CHECK(l["targets"][0]["answer"] == "yes");
    CHECK(l["targets"][2]["answer"] == "unknown");

    // The graph engine takes the cap too (states expanded), and reports
    // the same way: with 2 states, target 1 (0 reflections from ray 1,
    // proven) is lit and target 3 unknown, never unlit.
    const CliResult graph = run_cli("solve --json --engine graph --max-steps 2 " + quote(file));
    CHECK(graph.status == 3);
    const nlohmann::json g = json_of(graph);
    CHECK(g["reason"] == "limit");
    CHECK(g["limit"] == "steps");
    CHECK(g["targets"][0] ==
          nlohmann::json::parse(R"({"target":1,"answer":"yes","reflections":0,"ray":1})"));
    CHECK(g["targets"][2]["answer"] == "unknown");
}

TEST_CASE("a shooter asked for by name is used or refused, never replaced", "[cli][optics]") {
    const TempDir dir;
    // The branch search steps on each ray's lattice itself: two targets.
    const std::string two = dir.write("two.scene", "dim 2\nmirror x 2 y 0 4\nray 0 1 1 0\n"
                                                   "target 1 1\ntarget 9 9\n");
    // The piece tables are 2D: a 3D box.
    const std::string cube = dir.write("cube.scene", "dim 3\nmirror x 0 y 0 2 z 0 2\n"
                                                     "mirror x 2 y 0 2 z 0 2\nray 1 1 1 1 0 0\n"
                                                     "target 9 9 9\n");
    for (const char* shooter : {"grid", "bvh", "pieces", "section"}) {
        INFO(shooter);
        const CliResult refused =
            run_cli("solve --shooter " + std::string(shooter) + ' ' + quote(two));
        CHECK(refused.status == 2);
        CHECK(refused.out.empty());
        CHECK(refused.err.find("takes --shooter auto") != std::string::npos);
        const CliResult used =
            run_cli("solve --json --shooter " + std::string(shooter) + ' ' + quote(cube));
        if (std::string(shooter) == "pieces") {
            CHECK(used.status == 2);
            CHECK(used.err.find("--shooter pieces takes 2D scenes") != std::string::npos);
        } else {
            CHECK(used.status == 1);
            CHECK(nlohmann::json::parse(used.out)["shooter"] == shooter);
        }
    }
    CHECK(run_cli("solve --shooter auto " + quote(two)).status == 1); // target 2 unlit
}

TEST_CASE("solve reports tail and period of a rho-shaped cycle", "[cli][optics]") {
    TempDir dir;
    const std::string file = dir.write("rho.scene", rho_scene);
    const CliResult r = run_cli("solve --json " + quote(file));
    CHECK(r.status == 1);
    const nlohmann::json j = json_of(r);
    CHECK(j["reason"] == "cycle");
    CHECK(j["tail"] == 1);
    CHECK(j["period"] == 2);
    CHECK(j["reflections"] == 3);
    CHECK(j["engine"] == "lattice");
    // A purely periodic trajectory reports tail 0.
    const CliResult pure =
        run_cli("solve --json " + quote(instance("2d/unit-square-slope-2-3.scene")));
    CHECK(json_of(pure)["tail"] == 0);
    CHECK(json_of(pure)["period"] == 10);
}

TEST_CASE("solve writes the rho-cycle certificate: the cycle's start state and the tail",
          "[cli][optics][certificate]") {
    // States (0, 3, +x), (10, 3, -x), (5, 3, +x), (10, 3, -x): the cycle
    // starts at s_2 = (10, 3) going -x, tail 1, period 2.
    TempDir dir;
    const std::string file = dir.write("rho.scene", rho_scene);
    const std::string cert = dir.path("rho.cert"), jsonl = dir.path("rho.jsonl");
    const CliResult r = run_cli("solve " + quote(file) + " --certificate " + quote(cert));
    CHECK(r.status == 1);
    CHECK(slurp(cert) == "orthoray-certificate 1\ndim 2\npoint 2 3\npoint 0 3\npoint 10 3\n"
                         "point 5 3\npoint 10 3\nanswer no\nreason cycle\n"
                         "reflections 3\nstate 10 3 -1 0\nperiod 2\ntail 1\nend\n");
    REQUIRE(run_cli("solve " + quote(file) + " --certificate " + quote(jsonl) +
                    " --certificate-format jsonl")
                .status == 1);
    CHECK(slurp(jsonl).find(R"("state": {"point": ["10", "3"], "direction": ["-1", "0"]}, )"
                            R"("period": "2", "tail": "1"})") != std::string::npos);
}

TEST_CASE("render draws the new scenes, and refuses a certificate for them", "[cli][optics]") {
    TempDir dir;
    for (const std::string& scene : {splitter_scene, rho_scene}) {
        const std::string file = dir.write("scene.scene", scene);
        const std::string svg = dir.path("out.svg");
        const CliResult r = run_cli("render " + quote(file) + " -o " + quote(svg));
        INFO(r.err);
        CHECK(r.status == 0);
        CHECK(r.out.find("wrote ") == 0);
        const std::string text = slurp(svg);
        CHECK(text.find("class=\"trajectory\"") != std::string::npos);
        CHECK(text.find("branches: all ") != std::string::npos);
        const CliResult refused = run_cli("render " + quote(file) + " --certificate " +
                                          quote(file) + " -o " + quote(dir.path("no.svg")));
        CHECK(refused.status == 2);
        CHECK_FALSE(std::filesystem::exists(dir.path("no.svg")));
    }
    // The last one drawn, the rho scene: a single trajectory that cycles
    // after a tail, its target marked unlit.
    const std::string rho = slurp(dir.path("out.svg"));
    CHECK(rho.find("answer no, reason cycle, tail ") != std::string::npos);
    CHECK(rho.find("class=\"target-unlit\"") != std::string::npos);
}

TEST_CASE("solve writes illumination certificates in both formats", "[cli][optics]") {
    TempDir dir;
    const std::string file = dir.write("split.scene", splitter_scene);
    const std::string cert = dir.path("out.cert"), jsonl = dir.path("out.jsonl");
    CHECK(run_cli("solve " + quote(file) + " --certificate " + quote(cert)).status == 1);
    CHECK(slurp(cert) == "orthoray-certificate 1\ndim 2\nillumination\n"
                         "branch 0 0 1 0 ray 1 reflections 0\n"
                         "branch 2 0 1 0 ray 1 reflections 0\n"
                         "branch 2 0 -1 0 ray 1 reflections 1\n"
                         "lit 1 reflections 0 ray 1\nstep 0 0 1 0\nstep 2 0 1 0\n"
                         "lit 2 reflections 1 ray 1\nstep 0 0 1 0\nstep 2 0 -1 0\n"
                         "unlit 3\nanswer no\nreason unlit\nreflections 1\nstates 3\nend\n");
    CHECK(run_cli("solve " + quote(file) + " --certificate-format jsonl --certificate " +
                  quote(jsonl))
              .status == 1);
    CHECK(slurp(jsonl).find("{\"unlit\": \"3\"}\n{\"answer\": \"no\", \"reason\": \"unlit\", "
                            "\"reflections\": \"1\", \"states\": \"3\"}\n{\"end\": true}\n") !=
          std::string::npos);
    // The graph engine still writes none.
    const CliResult graph =
        run_cli("solve " + quote(file) + " --engine graph --certificate " + quote(cert));
    CHECK(graph.status == 2);
}

#ifndef ORTHORAY_SANITIZE // sanitizers reserve terabytes of address space and abort on failure
TEST_CASE("solve --max-memory stops the illumination search with no wrong answer",
          "[cli][optics]") {
    // 60 random mirrors in a closed box, every third one a splitter, and a
    // second target: about 3 * 10^4 branch states, some 3 MB.
    orthoray::RandomFamily family;
    family.mirrors = 60;
    family.box = true;
    family.seed = 3;
    orthoray::Scene s = orthoray::generate_random(family).scene;
    for (std::size_t i = 2; i < s.elements.size(); i += 3)
        s.elements[i].kind = orthoray::ElementKind::splitter;
    s.targets.push_back(orthoray::Vector{orthoray::Rational(1, 3), orthoray::Rational(1, 7), 0});
    TempDir dir;
    const std::string file = dir.write("maze.scene", orthoray::write_scene(s));
    const CliResult r = run_cli("solve --json --max-memory 1 " + quote(file));
    CHECK(r.status == 3);
    const nlohmann::json j = json_of(r);
    CHECK(j["reason"] == "limit");
    CHECK(j["limit"] == "memory");
    // The search itself stopped (its states are reported), not the process.
    REQUIRE(j["targets"].size() == 2);
    CHECK(j["states"] > 1000);
    for (const nlohmann::json& t : j["targets"]) CHECK(t["answer"] != "no");
}
#endif

TEST_CASE("the .scene writer round-trips splitters, sides and several rays", "[reader][optics]") {
    const std::string text = "dim 3\nsplitter z- 0 x 0 4 y 0 4\nmirror x+ 1 y 0 1 z 0 1\n"
                             "absorber y 2 x 0 1 z 0 1\nray 0 0 0 1 1 1\nray 1 2 3 -1 0 0\n"
                             "target 1 1 1\ntarget 2 2 2\n";
    const orthoray::Scene s = orthoray::read_scene(text);
    REQUIRE(s.elements.size() == 3);
    CHECK(s.elements[0].kind == orthoray::ElementKind::splitter);
    CHECK(s.elements[0].side == orthoray::Side::minus);
    CHECK(s.elements[1].side == orthoray::Side::plus);
    CHECK(s.rays.size() == 2);
    CHECK(s.targets.size() == 2);
    const std::string written = orthoray::write_scene(s);
    CHECK(orthoray::write_scene(orthoray::read_scene(written)) == written);
    const orthoray::Scene back = orthoray::read_scene(written);
    CHECK(back.elements[0].side == orthoray::Side::minus);
    CHECK(back.rays[1].direction == s.rays[1].direction);
    CHECK(back.targets[1] == s.targets[1]);
}

TEST_CASE("convert round-trips the new scenes through JSON", "[cli][optics]") {
    TempDir dir;
    const std::string text =
        dir.write("in.scene", splitter_scene + "ray 1 1 0 -1\n" + "mirror y- 4 x 0 1\n");
    const std::string json = dir.path("mid.json"), back = dir.path("back.scene");
    REQUIRE(run_cli("convert " + quote(text) + " " + quote(json)).status == 0);
    REQUIRE(run_cli("convert " + quote(json) + " " + quote(back)).status == 0);
    const orthoray::Scene original = orthoray::read_scene(slurp(text));
    CHECK(slurp(back) == orthoray::write_scene(original));
    // And both files get the same answer.
    CHECK(run_cli("solve --json " + quote(text)).out.substr(0, 60) ==
          run_cli("solve --json " + quote(json)).out.substr(0, 60));
}

TEST_CASE("verify judges a certificate by the scene's sides", "[cli][optics]") {
    // A certificate that is valid for the scene without the one-way mirror
    // must not pass for the scene with it: its front at x = 5 turns the ray
    // back before x = 10.
    TempDir dir;
    const std::string plain = dir.write("plain.scene", "dim 2\nmirror x 10 y 0 10\n"
                                                       "ray 2 3 1 0\ntarget 0 3\n");
    const std::string one_way = dir.write("one-way.scene", "dim 2\nmirror x 10 y 0 10\n"
                                                           "mirror x- 5 y 0 10\n"
                                                           "ray 2 3 1 0\ntarget 0 3\n");
    const std::string cert = dir.path("c.cert");
    REQUIRE(run_cli("solve " + quote(plain) + " --certificate " + quote(cert)).status == 0);
    REQUIRE(run_cli("verify " + quote(plain) + " " + quote(cert)).status == 0);
    const CliResult r = run_cli("verify " + quote(one_way) + " " + quote(cert));
    CHECK(r.status == 1);
    CHECK(r.out == "invalid: step 1: point 1 is (10, 3), but the ray from point 0 first meets an "
                   "element at (5, 3)\n");
}

TEST_CASE("verify checks illumination certificates: exit 0 valid, 1 invalid or partial",
          "[cli][optics]") {
    // The splitter scene above: target 1 straight through, target 2 on the
    // reflected branch, target 3 (2, -3) on neither.
    TempDir dir;
    const std::string scene = dir.write("split.scene", splitter_scene);
    const std::string branches = "orthoray-certificate 1\ndim 2\nillumination\n"
                                 "branch 0 0 1 0 ray 1 reflections 0\n"
                                 "branch 2 0 1 0 ray 1 reflections 0\n"
                                 "branch 2 0 -1 0 ray 1 reflections 1\n"
                                 "lit 1 reflections 0 ray 1\nstep 0 0 1 0\nstep 2 0 1 0\n"
                                 "lit 2 reflections 1 ray 1\nstep 0 0 1 0\nstep 2 0 -1 0\n";
    const std::string valid =
        dir.write("valid.cert",
                  branches + "unlit 3\nanswer no\nreason unlit\nreflections 1\nstates 3\nend\n");
    CliResult r = run_cli("verify " + quote(scene) + " " + quote(valid));
    CHECK(r.status == 0);
    CHECK(r.out == "valid: unlit, 1 reflections, 3 states\n");
    const std::string partial =
        dir.write("partial.cert", branches + "unknown 3\nanswer unknown\nreason limit\n"
                                             "reflections 1\nstates 3\npartial\nend\n");
    r = run_cli("verify " + quote(scene) + " " + quote(partial));
    CHECK(r.status == 1);
    CHECK(r.out.rfind("partial certificate: 2 lit", 0) == 0);
    const std::string wrong = dir.write(
        "wrong.cert", branches + "lit 3 reflections 0 ray 1\nstep 0 0 1 0\n"
                                 "answer yes\nreason lit\nreflections 1\nstates 3\nend\n");
    r = run_cli("verify " + quote(scene) + " " + quote(wrong));
    CHECK(r.status == 1);
    CHECK(r.out == "invalid: lit target 3 (line 13): the target (2, -3) is not on the segment "
                   "after step 0\n");
}
