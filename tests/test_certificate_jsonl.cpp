// JSON Lines certificates: the same evidence as the text format, one JSON
// object a line. Every instance's certificate verifies in both formats with
// the same verdict, every line is JSON another tool can read, tampering is
// rejected, and malformed lines are reported at their line and column.
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include "support/certificate_lines.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using orthoray::Answer;
using orthoray::CertificateFormat;
using orthoray::Scene;

namespace {

using orthoray::test::join;
using orthoray::test::split_lines;

using orthoray::test::instance_files;

std::string certify(const Scene& scene, CertificateFormat format,
                    orthoray::SolveOptions options = {}) {
    std::stringstream out;
    orthoray::CertificateWriter writer(out, scene, format);
    writer.attach(options);
    writer.finish(orthoray::solve(scene, options));
    return out.str();
}

// verify's message, or the InputError's text for a malformed certificate.
std::string verify(const Scene& scene, const std::string& text) {
    std::istringstream in(text);
    try {
        return orthoray::verify_certificate(scene, in, "c.jsonl").message;
    } catch (const orthoray::InputError& e) {
        return e.what();
    }
}

const char* box = "dim 2\n"
                  "mirror x 0 y 0 5\nmirror x 3 y 0 5\nmirror y 0 x 0 3\nmirror y 5 x 0 3\n"
                  "ray 0 0 1 1\ntarget 3 5\n";

} // namespace

TEST_CASE("every instance's JSON Lines certificate verifies like its text one",
          "[certificate][jsonl]") {
    for (const auto& path : instance_files()) {
        INFO(path.string());
        const Scene scene = orthoray::load_scene(path.string());
        const std::string text = certify(scene, CertificateFormat::text);
        const std::string jsonl = certify(scene, CertificateFormat::jsonl);
        const std::string verdict = verify(scene, jsonl);
        CHECK(verdict == verify(scene, text));
        CHECK((verdict.rfind("valid: ", 0) == 0 || verdict.rfind("partial", 0) == 0));
        // Every line is a JSON object another tool reads without help.
        const auto lines = split_lines(jsonl);
        REQUIRE(lines.size() >= 4);
        for (const std::string& line : lines) CHECK(nlohmann::json::parse(line).is_object());
        CHECK(nlohmann::json::parse(lines.back()) == nlohmann::json{{"end", true}});
        // One point line a point line of the text format.
        const auto points = [](const std::vector<std::string>& all, const char* prefix) {
            return std::count_if(all.begin(), all.end(),
                                 [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
        };
        CHECK(points(lines, "{\"point\"") == points(split_lines(text), "point "));
    }
}

TEST_CASE("the JSON Lines writer's text is exactly the documented format", "[certificate][jsonl]") {
    const Scene scene = orthoray::read_scene(box);
    const std::string jsonl = certify(scene, CertificateFormat::jsonl);
    CHECK(jsonl == "{\"orthoray-certificate\": 1, \"dim\": 2}\n"
                   "{\"point\": [\"0\", \"0\"]}\n"
                   "{\"point\": [\"3\", \"3\"]}\n"
                   "{\"point\": [\"1\", \"5\"]}\n"
                   "{\"point\": [\"0\", \"4\"]}\n"
                   "{\"point\": [\"3\", \"1\"]}\n"
                   "{\"point\": [\"2\", \"0\"]}\n"
                   "{\"point\": [\"0\", \"2\"]}\n"
                   "{\"answer\": \"yes\", \"reason\": \"hit\", \"reflections\": \"6\", "
                   "\"target\": [\"3\", \"5\"]}\n"
                   "{\"end\": true}\n");
    CHECK(verify(scene, jsonl) == "valid: hit, 6 reflections");
    // Key order inside a line does not matter.
    auto lines = split_lines(jsonl);
    lines[8] = "{\"target\": [\"3\", \"5\"], \"reflections\": \"6\", \"reason\": \"hit\", "
               "\"answer\": \"yes\"}";
    lines[0] = "{\"dim\": 2, \"orthoray-certificate\": 1}";
    CHECK(verify(scene, join(lines)) == "valid: hit, 6 reflections");
}

TEST_CASE("tampered JSON Lines certificates are rejected", "[certificate][jsonl]") {
    const Scene scene = orthoray::read_scene(box);
    const auto lines = split_lines(certify(scene, CertificateFormat::jsonl));
    auto changed = [&](std::size_t index, const std::string& line) {
        auto copy = lines;
        copy[index] = line;
        return verify(scene, join(copy));
    };
    CHECK(changed(3, "{\"point\": [\"1\", \"4\"]}") ==
          "invalid: step 2: point 2 is (1, 4), but the ray from point 1 first meets an element "
          "at (1, 5)");
    CHECK(changed(8, "{\"answer\": \"yes\", \"reason\": \"hit\", \"reflections\": \"5\", "
                     "\"target\": [\"3\", \"5\"]}") ==
          "invalid: verdict: reflections 5, but 7 points give 6 for reason hit");
    CHECK(changed(8, "{\"answer\": \"no\", \"reason\": \"escape\", \"reflections\": \"6\", "
                     "\"direction\": [\"1\", \"1\"]}")
              .rfind("invalid: verdict: ", 0) == 0);
    auto truncated = lines;
    truncated.pop_back();
    CHECK(verify(scene, join(truncated)) == "invalid: incomplete certificate (no 'end' line)");
    auto dropped = lines;
    dropped.erase(dropped.begin() + 4);
    CHECK(verify(scene, join(dropped)).rfind("invalid: step 3: ", 0) == 0);
}

TEST_CASE("malformed JSON Lines are reported at their line and column",
          "[certificate][jsonl][errors]") {
    const Scene scene = orthoray::read_scene(box);
    const auto lines = split_lines(certify(scene, CertificateFormat::jsonl));
    auto changed = [&](std::size_t index, const std::string& line) {
        auto copy = lines;
        copy[index] = line;
        return verify(scene, join(copy));
    };
    CHECK(changed(2, "{\"point\": [\"3\", \"3\"]") ==
          "c.jsonl:3:21: found end of file, expected '}'");
    CHECK(changed(2, "{\"point\": [\"3\", 3.5e1]}") ==
          "c.jsonl:3:17: found '3.5e1', expected a number");
    CHECK(changed(2, "{\"point\": [\"3\"]}") ==
          "c.jsonl:3:11: found no more values, expected a number");
    CHECK(changed(2, "{\"point\": [\"3\", \"3\", \"0\"]}") ==
          "c.jsonl:3:22: found '0', expected no more values");
    CHECK(changed(2, "{\"pointe\": [\"3\", \"3\"]}")
              .rfind("c.jsonl:3:2: found the key \"pointe\", expected one of ", 0) == 0);
    CHECK(changed(2, "[\"3\", \"3\"]") ==
          "c.jsonl:3:1: found an array, expected a JSON object (one statement a line)");
    CHECK(changed(0, "{\"orthoray-certificate\": 1, \"dim\": 3}") ==
          "c.jsonl:1:36: found '3', expected '2' (the scene's dim)");
    CHECK(changed(9, "{\"end\": false}") == "c.jsonl:10:9: found 'false', expected no more values");

    // The cycle's state object holds exactly a point and a direction.
    const Scene square = orthoray::read_scene("dim 2\nmirror x 0 y 0 1\nmirror x 1 y 0 1\n"
                                              "ray 0 1/2 1 0\ntarget 5 5\n");
    auto cycle = split_lines(certify(square, CertificateFormat::jsonl));
    REQUIRE(cycle[cycle.size() - 2].find("\"state\": {\"point\"") != std::string::npos);
    CHECK(verify(square, join(cycle)) == "valid: cycle, 2 reflections");
    std::string& verdict = cycle[cycle.size() - 2];
    verdict.replace(verdict.find("\"direction\""), 11, "\"heading\"");
    const std::string message = verify(square, join(cycle));
    CHECK(message.find("found the key \"heading\", expected \"point\" or \"direction\"") !=
          std::string::npos);
}
