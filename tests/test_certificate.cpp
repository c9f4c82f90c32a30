// Certificates (docs/certificates.md): every example instance certifies with
// the simulation engines and the certificate verifies, also on wide
// arithmetic and with the other cycle detector; and partial (limit)
// certificates are never valid. Tampering is test_certificate_tampering.cpp's;
// the exact text of the format is test_certificate_format.cpp's.
#include "support/certificate_lines.hpp"
#include "support/certificate_outcome.hpp"
#include "support/curated_scenes.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace orthoray::test;
using orthoray::Engine;
using orthoray::Rational;
using orthoray::Reason;
using orthoray::Scene;
using orthoray::SolveOptions;

namespace {

const Rational one_seventh(1, 7);

} // namespace

// ------------------------------------------------------ valid certificates --

TEST_CASE("every instance certifies and verifies with the lattice and reference engines",
          "[certificate]") {
    REQUIRE(curated_scenes().size() >= 20);
    for (const CuratedScene& instance : curated_scenes()) {
        INFO("instance " << instance.name);
        std::string texts[2];
        int n = 0;
        for (Engine engine : {Engine::lattice, Engine::reference}) {
            INFO("engine " << (engine == Engine::lattice ? "lattice" : "reference"));
            const Certified c = certify(instance.scene, engine);
            REQUIRE(c.answer.decided());
            const Outcome outcome = verify(instance.scene, c.text);
            INFO("certificate:\n" << c.text << "verify said: " << outcome.message);
            CHECK(outcome.valid);
            CHECK_FALSE(outcome.input_error);
            CHECK(outcome.message.starts_with("valid"));
            // The message names the reason and the count that were proven.
            CHECK(outcome.message.find(orthoray::to_string(c.answer.reason)) != std::string::npos);
            CHECK(outcome.message.find(c.answer.reflections.get_str()) != std::string::npos);
            texts[n++] = c.text;
        }
        // Both engines walk the same trajectory, so they write the same text.
        CHECK(texts[0] == texts[1]);
    }
}

namespace {

// Certifies every instance with `options` (engine lattice and reference) and
// demands that each certificate verifies.
void expect_all_verify(SolveOptions options, const char* label) {
    for (const CuratedScene& instance : curated_scenes()) {
        for (Engine engine : {Engine::lattice, Engine::reference}) {
            options.engine = engine;
            const Certified c = certify(instance.scene, options);
            const Outcome outcome = verify(instance.scene, c.text);
            INFO("instance " << instance.name << ", engine "
                             << (engine == Engine::lattice ? "lattice" : "reference") << ", "
                             << label << "\nanswer " << orthoray::to_string(c.answer.reason) << " "
                             << c.answer.reflections.get_str() << "\ncertificate:\n"
                             << c.text << "verify said: " << outcome.message);
            CHECK(outcome.valid);
        }
    }
}

} // namespace

TEST_CASE("certificates verify with wide lattice arithmetic", "[certificate]") {
    SolveOptions options;
    options.arithmetic = orthoray::Arithmetic::wide;
    expect_all_verify(options, "arithmetic wide");
}

TEST_CASE("certificates verify with the brent cycle detector", "[certificate]") {
    // The certificate describes the trajectory, not how the solver noticed
    // the cycle: a cycle certificate is p0 .. p(L+1) whatever the detector
    // (docs/certificates.md), and `orthoray solve --cycle-detector brent
    // --certificate OUT` is accepted by the CLI.
    SolveOptions options;
    options.cycle_detector = orthoray::CycleDetector::brent;
    expect_all_verify(options, "detector brent");
}

TEST_CASE("comments, blank lines and tabs in a certificate are ignored", "[certificate]") {
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        Lines lines;
        lines.push_back("# a comment before the header");
        for (const std::string& line : split_lines(c.text)) {
            auto t = tokens(line);
            std::string spaced;
            for (const std::string& token : t) spaced += "\t " + token;
            lines.push_back(spaced + "   # trailing comment");
            lines.push_back("");
        }
        const Outcome outcome = verify(instance.scene, join(lines));
        INFO("instance " << instance.name << "\nverify said: " << outcome.message);
        CHECK(outcome.valid);
    }
}

TEST_CASE("a certificate with no statement is malformed, one cut short is invalid",
          "[certificate]") {
    const Scene& scene = curated_scenes().front().scene;
    // Nothing to read: the header is missing, as in any file that does not
    // start with it (exit 2), not a proof stopped midway (exit 1).
    for (const std::string& text : {std::string(), std::string("\n\n# only a comment\n")}) {
        const Outcome outcome = verify(scene, text);
        INFO("certificate:\n" << text << "verify said: " << outcome.message);
        CHECK(outcome.input_error);
        CHECK(outcome.message.find("found end of file, expected 'orthoray-certificate'") !=
              std::string::npos);
    }
    const Outcome header_only = verify(scene, "orthoray-certificate 1\n");
    CHECK_FALSE(header_only.input_error);
    CHECK(header_only.message == "invalid: incomplete certificate (no 'end' line)");
}

TEST_CASE("the graph engine does not write certificates", "[certificate]") {
    const Scene& scene = curated_scenes().front().scene;
    std::stringstream out;
    orthoray::CertificateWriter writer(out, scene);
    SolveOptions options;
    options.engine = Engine::graph;
    writer.attach(options);
    CHECK_THROWS_AS(orthoray::solve(scene, options), std::invalid_argument);
}

// ----------------------------------------------------- limit certificates --

TEST_CASE("a limit certificate checks its steps but is only partial", "[certificate]") {
    int checked = 0;
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified full = certify(instance.scene, Engine::lattice);
        // The solvers stop with a limit for any cap below the reflections they
        // need: a hit after j or an escape after m needs j or m; an absorption
        // after m is seen before the cap m is tested; a cycle of period L is
        // seen at reflection L + 1.
        unsigned long needed = full.answer.reflections.get_ui();
        if (full.answer.reason == Reason::cycle) needed += 1;
        for (Engine engine : {Engine::lattice, Engine::reference}) {
            for (unsigned long cap = 0; cap < needed; ++cap) {
                INFO("instance " << instance.name << ", max_steps " << cap);
                SolveOptions options;
                options.engine = engine;
                options.max_steps = cap;
                const Certified c = certify(instance.scene, options);
                REQUIRE(c.answer.reason == Reason::limit);
                CHECK(c.answer.reflections.get_ui() == cap);
                const Lines lines = split_lines(c.text);
                CHECK(lines_with(lines, "point").size() == cap + 1);
                CHECK(lines_with(lines, "partial").size() == 1);
                const Outcome outcome = verify(instance.scene, c.text);
                INFO("certificate:\n" << c.text << "verify said: " << outcome.message);
                CHECK_FALSE(outcome.valid);
                CHECK_FALSE(outcome.input_error);
                CHECK(outcome.message.starts_with("partial"));
                ++checked;
                // A partial certificate with a wrong step is invalid, not partial.
                const auto points = lines_with(lines, "point");
                Lines moved = lines;
                moved[points.back()] = with_number(lines[points.back()], 1, [](const Rational& x) {
                    return Rational(x + one_seventh);
                });
                const Outcome bad = verify(instance.scene, join(moved));
                INFO("tampered verify said: " << bad.message);
                CHECK_FALSE(bad.valid);
                CHECK(bad.message.starts_with("invalid"));
                // Claiming an answer on a partial path is a lie too.
                Lines claimed = lines;
                claimed[line_with(lines, "answer")] = "answer no";
                expect_rejected(instance.scene, join(claimed), "answer no on a limit");
            }
        }
    }
    CHECK(checked >= 50);
}
