// JSON scenes: every curated instance and many random scenes survive
// .scene -> JSON -> .scene unchanged, the file name picks the reader, and
// malformed JSON (bad syntax or a bad scene) gives one InputError at the
// line and column of the value at fault.
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"
#include "support/random_scene.hpp"

#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

using orthoray::InputError;
using orthoray::read_scene;
using orthoray::read_scene_json;
using orthoray::Scene;
using orthoray::SceneFormat;
using orthoray::write_scene;
using orthoray::write_scene_json;

namespace {

using orthoray::test::instance_files;

// Two scenes are the same when they write the same canonical .scene text:
// write_scene covers every field but the declaring line numbers.
void require_same(const Scene& a, const Scene& b) {
    REQUIRE(write_scene(a) == write_scene(b));
}

// Reads JSON that must be malformed and returns its one error.
InputError error_of(const std::string& text) {
    try {
        read_scene_json(text, "t.json");
    } catch (const InputError& e) {
        return e;
    }
    FAIL("no InputError for:\n" << text);
    return InputError("t.json", 0, 0, "unreachable");
}

const std::string valid = "{\n"
                          "  \"dim\": 2,\n"
                          "  \"elements\": [\n"
                          "    {\"kind\": \"mirror\", \"axis\": \"x\", \"offset\": \"3\", "
                          "\"extent\": {\"y\": [\"0\", \"5\"]}},\n"
                          "    {\"kind\": \"absorber\", \"axis\": \"y\", \"offset\": \"5/2\", "
                          "\"extent\": {\"x\": [\"-1\", \"4\"]}}\n"
                          "  ],\n"
                          "  \"ray\": {\"start\": [\"0\", \"0\"], \"direction\": [\"3\", \"1\"]},\n"
                          "  \"target\": [\"7/2\", \"1\"]\n"
                          "}\n";

// `valid` with its first occurrence of `from` replaced by `to`.
std::string edit(const std::string& from, const std::string& to) {
    std::string text = valid;
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("every instance round-trips through JSON exactly", "[json]") {
    const auto files = instance_files();
    REQUIRE(files.size() >= 27);
    for (const auto& path : files) {
        INFO(path.string());
        const Scene scene = orthoray::load_scene(path.string());
        const std::string json = write_scene_json(scene);
        const Scene back = read_scene_json(json, "round-trip.json");
        require_same(scene, back);
        CHECK(write_scene_json(back) == json);
    }
}

TEST_CASE("random 2D and 3D scenes round-trip through JSON", "[json]") {
    std::mt19937_64 rng(20261122);
    for (int dim : {2, 3}) {
        orthoray::test::RandomSceneShape shape;
        shape.dim = dim;
        shape.max_denominator = 7;
        for (int i = 0; i < 200; ++i) {
            Scene scene = orthoray::test::random_scene(rng, shape);
            scene.target() = orthoray::test::random_point(rng, shape);
            INFO(write_scene(scene));
            require_same(scene, read_scene_json(write_scene_json(scene)));
            // and back through the text format
            require_same(scene, read_scene(write_scene(read_scene_json(write_scene_json(scene)))));
        }
    }
}

TEST_CASE("the JSON reader fills in the same fields as the text reader", "[json]") {
    const Scene json = read_scene_json(valid, "v.json");
    const Scene text = read_scene("dim 2\nmirror x 3 y 0 5\nabsorber y 5/2 x -1 4\n"
                                  "ray 0 0 3 1\ntarget 7/2 1\n");
    require_same(json, text);
    REQUIRE(json.elements.size() == 2);
    CHECK(json.elements[0].line == 4); // the line of the element's object
    CHECK(json.elements[1].kind == orthoray::ElementKind::absorber);
}

TEST_CASE("huge and fractional rationals are kept exactly", "[json]") {
    const std::string big = "123456789012345678901234567890123456789/7";
    const Scene scene = read_scene_json(edit("\"7/2\"", "\"" + big + "\""));
    CHECK(orthoray::to_string(scene.target()[0]) == big);
    CHECK(orthoray::to_string(read_scene_json(edit("\"5/2\"", "\"10/4\"")).elements[1].offset()) ==
          "5/2");
}

TEST_CASE("integers may be JSON numbers, of any size, read exactly", "[json]") {
    const std::string huge = "-98765432109876543210987654321";
    auto replace = [](std::string text, const std::string& from, const std::string& to) {
        return text.replace(text.find(from), from.size(), to);
    };
    const Scene numbers = read_scene_json(
        replace(replace(edit("\"offset\": \"3\"", "\"offset\": 3"), "[\"-1\", \"4\"]", "[-1, 4]"),
                "\"direction\": [\"3\", \"1\"]", "\"direction\": [" + huge + ", 1]"));
    const Scene strings = read_scene_json(
        edit("\"direction\": [\"3\", \"1\"]", "\"direction\": [\"" + huge + "\", \"1\"]"));
    require_same(numbers, strings);
    // A number past 2^53 would lose digits through a double.
    CHECK(orthoray::to_string(numbers.ray().direction[0]) == huge);
}

TEST_CASE("the file name picks the format unless one is given", "[json]") {
    CHECK(orthoray::resolve_scene_format("a/b.json", SceneFormat::automatic) == SceneFormat::json);
    CHECK(orthoray::resolve_scene_format("a/b.scene", SceneFormat::automatic) == SceneFormat::text);
    CHECK(orthoray::resolve_scene_format("noext", SceneFormat::automatic) == SceneFormat::text);
    CHECK(orthoray::resolve_scene_format("a.json", SceneFormat::text) == SceneFormat::text);
    CHECK(orthoray::resolve_scene_format("a.txt", SceneFormat::json) == SceneFormat::json);

    const auto path = std::filesystem::temp_directory_path() /
                      ("orthoray-json-" + std::to_string(::getpid()) + ".json");
    std::ofstream(path) << valid;
    require_same(orthoray::load_scene(path.string()), read_scene_json(valid));
    // forced to the text reader, the JSON is a bad statement on line 1
    CHECK_THROWS_AS(orthoray::load_scene(path.string(), SceneFormat::text), InputError);
    std::filesystem::remove(path);
}

TEST_CASE("malformed JSON is reported at its line and column", "[json][errors]") {
    struct Case {
        std::string text, message;
    };
    const std::vector<Case> cases = {
        {"", "t.json:1:1: found end of file, expected '[', '{', or a literal"},
        {"{\"dim\": 2,}", "t.json:1:11: found '}', expected string literal"},
        {"{\"dim\": 2", "t.json:1:10: found end of file, expected '}'"},
        {"{\"dim\" 2}", "t.json:1:8: found '2', expected ':'"},
        {"{\n  \"dim\": 2 3}", "t.json:2:12: found '3', expected '}'"},
        {"[1,\n tru]", "t.json:2:2: found 'tru]', expected valid JSON (invalid literal)"},
        {"\"abc", "t.json:1:1: found '\"abc', expected valid JSON (invalid string: missing "
                  "closing quote)"},
        {"{} x", "t.json:1:4: found 'x', expected valid JSON (invalid literal)"},
        {"{\"dim\": 1e999}", "t.json:1:9: found '1e999', expected a number a double can hold "
                             "(write exact numbers as strings)"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK(std::string(error_of(c.text).what()) == c.message);
    }
}

TEST_CASE("valid JSON that is not a scene is reported at the value at fault", "[json][errors]") {
    struct Case {
        std::string text, message;
    };
    const std::vector<Case> cases = {
        {"[]", "t.json:1:1: found an array, expected a scene object {\"dim\": ..., ...}"},
        {edit("\"dim\": 2", "\"dim\": 4"),
         "t.json:2:10: found the number 4, expected the dimension 2 or 3"},
        {edit("\"dim\": 2", "\"dim\": \"2\""),
         "t.json:2:10: found the string \"2\", expected the dimension 2 or 3"},
        {edit("\"dim\": 2,", "\"dim\": 2, \"mirrors\": [],"),
         "t.json:2:13: found the key \"mirrors\", expected one of \"dim\", \"elements\", \"ray\", "
         "\"rays\", \"target\", \"targets\""},
        {edit("\"dim\": 2,", "\"dim\": 2, \"dim\": 3,"),
         "t.json:2:13: found a second key \"dim\" (the first is on line 2), expected each key "
         "once"},
        {edit("\"offset\": \"3\"", "\"offset\": 3.5"),
         "t.json:4:47: found the JSON number 3.5, expected the offset x = c: a JSON number only "
         "when it is an integer; write fractions and decimals as strings (\"3.5\") so that no "
         "tool rounds them"},
        {edit("\"offset\": \"3\"", "\"offset\": 3e0"),
         "t.json:4:47: found the JSON number 3e0, expected the offset x = c: a JSON number only "
         "when it is an integer; write fractions and decimals as strings (\"3e0\") so that no "
         "tool rounds them"},
        {edit("\"offset\": \"3\"", "\"offset\": \"1e3\""),
         "t.json:4:47: found the string \"1e3\", expected the offset x = c: an integer (3 or "
         "\"3\") or a rational as a JSON string (\"-7/2\", \"0.125\")"},
        {edit("\"offset\": \"3\"", "\"offset\": \"3/0\""),
         "t.json:4:47: found the string \"3/0\", expected the offset x = c with a nonzero "
         "denominator"},
        {edit("\"axis\": \"x\"", "\"axis\": \"z\""),
         "t.json:4:32: found the string \"z\", expected the normal axis \"x\" or \"y\" of a 2D "
         "scene"},
        {edit("\"kind\": \"mirror\"", "\"kind\": \"lens\""),
         "t.json:4:14: found the string \"lens\", expected \"mirror\", "
         "\"absorber\" or \"splitter\""},
        {edit("[\"0\", \"5\"]", "[\"5\", \"0\"]"),
         "t.json:4:74: found the string \"0\" as the upper end of the y extent, expected a "
         "number greater than 5"},
        {edit("{\"y\": [\"0\", \"5\"]}", "{\"x\": [\"0\", \"5\"]}"),
         "t.json:4:63: found the key \"x\", expected one of \"y\""},
        {edit("[\"0\", \"5\"]", "[\"0\"]"),
         "t.json:4:68: found an array of 1 values, expected the y extent as [lo, hi]"},
        {edit(", \"offset\": \"3\"", ""),
         "t.json:4:5: found an object without \"offset\", expected \"offset\": the offset x = c"},
        {edit("\"direction\": [\"3\", \"1\"]", "\"direction\": [\"0\", \"0\"]"),
         "t.json:7:45: found the direction 0, expected a nonzero direction"},
        {edit("\"target\": [\"7/2\", \"1\"]", "\"target\": [\"7/2\"]"),
         "t.json:8:13: found an array of 1 values, expected the target point as an array of 2 "
         "rationals"},
        {edit(",\n  \"target\": [\"7/2\", \"1\"]", ""),
         "t.json:1:1: found an object without \"target\", expected \"target\": a target "
         "point or \"targets\": [...]"},
        {std::string(100, '[') + std::string(100, ']'),
         "t.json:1:65: found JSON nested more than 64 levels deep, expected a flatter document"},
    };
    for (const Case& c : cases) {
        INFO(c.text);
        CHECK(std::string(error_of(c.text).what()) == c.message);
    }
}

TEST_CASE("JSON scenes carry splitters, sides and several rays and targets", "[json][optics]") {
    const Scene s = read_scene("dim 3\nsplitter z- 0 x 0 4 y 0 4\nmirror x+ 1 y 0 1 z 0 1\n"
                               "absorber y 2 x 0 1 z 0 1\nray 0 0 0 1 1 1\nray 1 2 3 -1 0 0\n"
                               "target 1 1 1\ntarget 2 2 2\n");
    const std::string json = write_scene_json(s);
    CHECK(json.find("\"kind\": \"splitter\", \"axis\": \"z\", \"side\": \"-\"") !=
          std::string::npos);
    CHECK(json.find("\"rays\": [") != std::string::npos);
    CHECK(json.find("\"targets\": [") != std::string::npos);
    const Scene back = read_scene_json(json);
    CHECK(write_scene(back) == write_scene(s));
    // One ray and one target keep the single forms that older readers know.
    Scene single = s;
    single.rays.resize(1);
    single.targets.resize(1);
    const std::string single_json = write_scene_json(single);
    CHECK(single_json.find("\"ray\": {") != std::string::npos);
    CHECK(single_json.find("\"target\": [") != std::string::npos);
    CHECK(write_scene(read_scene_json(single_json)) == write_scene(single));
}

TEST_CASE("bad sides, ray lists and target lists are one located error", "[json][optics]") {
    const std::string head = "{\"dim\": 2, \"elements\": [";
    const std::string mirror = "{\"kind\": \"mirror\", \"axis\": \"x\", \"offset\": \"1\", "
                               "\"extent\": {\"y\": [\"0\", \"1\"]}";
    const std::string tail = "\"ray\": {\"start\": [\"0\", \"0\"], \"direction\": [\"1\", \"0\"]}, "
                             "\"target\": [\"1\", \"1\"]}";
    auto message = [](const std::string& text) {
        try {
            read_scene_json(text, "t.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(message(head + mirror + ", \"side\": \"+-\"}], " + tail) ==
          "t.json:1:109: found the string \"+-\", expected the side \"+\" or \"-\" (no \"side\": "
          "two-sided)");
    CHECK(message(head + "], \"rays\": [], \"target\": [\"1\", \"1\"]}") ==
          "t.json:1:36: found an empty array, expected a nonempty array of {\"start\": [...], "
          "\"direction\": [...]}");
    CHECK(message(head + "], \"target\": [\"1\", \"1\"]}")
              .rfind("t.json:1:1: found an object "
                     "without \"ray\"",
                     0) == 0);
    CHECK(message(head + "], " + tail.substr(0, tail.size() - 1) + ", \"targets\": []}")
              .find("found both \"target\" and \"targets\"") != std::string::npos);
}
