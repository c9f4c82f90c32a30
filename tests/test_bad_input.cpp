// The bad-input corpus (tests/bad_input/): every malformed scene and
// certificate gives exit status 2, nothing on stdout, and exactly the one
// message tests/bad_input/expected.txt lists for it.
#include "support/run_cli.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace {

namespace fs = std::filesystem;
using orthoray::test::run_cli;
using orthoray::test::source_path;

const fs::path corpus = source_path("tests/bad_input");

// File name -> message, from the lines `NAME<TAB>MESSAGE` of expected.txt.
std::map<std::string, std::string> expectations() {
    std::map<std::string, std::string> expected;
    std::ifstream in(corpus / "expected.txt");
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t tab = line.find('\t');
        REQUIRE(tab != std::string::npos);
        expected[line.substr(0, tab)] = line.substr(tab + 1);
    }
    return expected;
}

} // namespace

TEST_CASE("every file of the bad-input corpus has its exact message", "[cli][bad-input][slow]") {
    const std::map<std::string, std::string> expected = expectations();
    CHECK(expected.size() >= 40);
    int scenes = 0, json_scenes = 0, certificates = 0;
    for (const auto& entry : fs::directory_iterator(corpus)) {
        const std::string name = entry.path().filename().string();
        if (name == "expected.txt" || name == "certificate-scene.txt") continue;
        CAPTURE(name);
        // A file nobody wrote an expectation for is a test nobody checks.
        REQUIRE(expected.count(name) == 1);
    }
    for (const auto& [name, message] : expected) {
        CAPTURE(name);
        REQUIRE(fs::exists(corpus / name));
        const bool certificate = name.size() > 5 && name.substr(name.size() - 5) == ".cert";
        const bool json = name.size() > 5 && name.substr(name.size() - 5) == ".json";
        (certificate ? certificates : json ? json_scenes : scenes) += 1;
        const std::string path = (corpus / name).string();
        const auto r = certificate
                           ? run_cli("verify '" + (corpus / "certificate-scene.txt").string() +
                                     "' '" + path + "'")
                           : run_cli("solve --json '" + path + "'");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        // expected.txt names the file as `NAME:LINE:COL: ...`; the CLI was
        // given the full path.
        CHECK(r.err == corpus.string() + "/" + message + "\n");
    }
    CHECK(scenes >= 30);
    CHECK(json_scenes >= 10);
    CHECK(certificates >= 8);
}
