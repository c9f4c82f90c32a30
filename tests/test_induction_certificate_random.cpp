// Certificates of many scenes: the brute-force writer's
// (support/brute_induction_certificate.hpp) and the induction engine's on
// seeded random scenes verify with the reference tracer's verdict, the
// engine's tampered one token at a time are rejected, and the engines'
// certificates of huge family instances verify.
#include "support/brute_induction_certificate.hpp"
#include "support/case_count.hpp"
#include "support/certificate_outcome.hpp"
#include "support/portable_random.hpp"
#include "support/random_scene.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using orthoray::Integer;
using orthoray::Rational;
using orthoray::Scene;

using orthoray::test::Brute;
using orthoray::test::brute_certificate;
using orthoray::test::Outcome;
using orthoray::test::verify;

} // namespace

TEST_CASE("brute-force induction certificates of random scenes verify",
          "[induction-certificate][slow]") {
    std::mt19937_64 rng(20261122);
    orthoray::test::RandomSceneShape shape;
    shape.max_elements = 10;
    shape.range = 4;
    shape.max_denominator = 2;
    shape.max_direction = 2;
    int verified = 0, cycle_steps = 0, tampered = 0, rejected = 0;
    int by_reason[4] = {};
    // A quarter of the scenes under sanitizers (support/case_count.hpp), and
    // every threshold below with them.
    const int wanted = orthoray::test::case_count(400);
    for (int round = 0; round < 10 * wanted && verified < wanted; ++round) {
        Scene scene = orthoray::test::random_scene(rng, shape);
        scene.target() = orthoray::test::random_target(rng, scene, shape);
        orthoray::SolveOptions o;
        o.engine = orthoray::Engine::reference;
        o.max_steps = 100000;
        const orthoray::Answer truth = orthoray::solve(scene, o);
        if (!truth.decided()) continue;
        const std::optional<Brute> brute = brute_certificate(scene, rng, 3000);
        if (!brute) continue;
        // A hit on the first segment is a path certificate's business.
        if (truth.reason == orthoray::Reason::hit && truth.reflections == 0) continue;
        INFO("scene:\n" << orthoray::write_scene(scene));
        const std::string expected = std::string("valid: ") + orthoray::to_string(truth.reason) +
                                     ", " + truth.reflections.get_str() + " reflections";
        REQUIRE(brute->verdict == expected);
        const Outcome outcome = verify(scene, brute->text);
        INFO("certificate:\n" << brute->text << "verify said: " << outcome.message);
        REQUIRE(outcome.valid);
        REQUIRE(outcome.message == expected);
        ++verified;
        ++by_reason[static_cast<int>(truth.reason)];
        cycle_steps += brute->cycle_steps;

        // One number changed by one: rejected, or still the true verdict.
        std::vector<std::string> lines;
        {
            std::istringstream in(brute->text);
            for (std::string line; std::getline(in, line);) lines.push_back(line);
        }
        for (int attempt = 0; attempt < 3; ++attempt) {
            const std::size_t at = orthoray::test::pick_index(rng, 2, lines.size() - 2);
            std::istringstream words(lines[at]);
            std::vector<std::string> t;
            for (std::string w; words >> w;) t.push_back(w);
            std::vector<std::size_t> numeric;
            for (std::size_t j = 1; j < t.size(); ++j)
                if (orthoray::read_number(t[j]).status == orthoray::NumberToken::Status::ok)
                    numeric.push_back(j);
            if (numeric.empty()) continue;
            const std::size_t j = numeric[orthoray::test::pick_index(rng, 0, numeric.size() - 1)];
            const Rational v = orthoray::read_number(t[j]).value;
            const Rational changed = v + (orthoray::test::chance(rng, 50) ? 1 : -1);
            t[j] = orthoray::to_string(changed);
            std::vector<std::string> copy = lines;
            copy[at].clear();
            for (std::size_t w = 0; w < t.size(); ++w) copy[at] += (w ? " " : "") + t[w];
            std::string text;
            for (const std::string& line : copy) text += line + "\n";
            const Outcome tamper = verify(scene, text);
            INFO("tampered line " << at + 1 << ": " << copy[at]
                                  << "\nverify said: " << tamper.message);
            ++tampered;
            if (tamper.valid)
                CHECK(tamper.message == expected);
            else
                ++rejected;
        }
    }
    INFO("verified " << verified << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                     << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3]
                     << "), cycle steps " << cycle_steps << ", tampered " << tampered
                     << ", rejected " << rejected);
    CHECK(verified * 4 >= wanted * 3);
    for (int count : by_reason) CHECK(count * 40 >= wanted);
    CHECK(cycle_steps * 4 >= wanted);
    CHECK(rejected * 10 >= tampered * 8);
    WARN("verified " << verified << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                     << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3]
                     << "), cycle steps " << cycle_steps << ", tampered " << tampered
                     << ", rejected " << rejected);
}

// -------------------------------------------------------------------- cli --

// ------------------------------------------------------ the engine's own --

namespace {

// Another word of the same statement slot, so a tamper stays well formed.
std::string other_word(const std::string& word, std::mt19937_64& rng) {
    const std::vector<std::vector<std::string>> families = {
        {"reflect", "escape", "absorbed"},
        {"top", "bottom", "equal", "invariant", "top-cycle", "bottom-cycle"},
        {"yes", "no"},
        {"hit", "escape", "absorbed", "cycle"}};
    for (const auto& family : families)
        for (const std::string& w : family)
            if (w == word) {
                std::string pick = word;
                while (pick == word)
                    pick = family[orthoray::test::pick_index(rng, 0, family.size() - 1)];
                return pick;
            }
    return word;
}

// One token of one statement changed: a number moved by one to three, a
// word swapped for another of its kind, or a trailing `hit` dropped.
std::string tamper_once(const std::string& text, std::mt19937_64& rng, std::string& what) {
    std::vector<std::string> lines;
    {
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
    }
    for (;;) {
        const std::size_t at = orthoray::test::pick_index(rng, 2, lines.size() - 2);
        std::vector<std::string> t;
        {
            std::istringstream words(lines[at]);
            for (std::string w; words >> w;) t.push_back(w);
        }
        if (t.size() < 2) continue;
        const std::size_t j = orthoray::test::pick_index(rng, 1, t.size() - 1);
        const orthoray::NumberToken n = orthoray::read_number(t[j]);
        std::string changed;
        if (n.status == orthoray::NumberToken::Status::ok) {
            const int delta = orthoray::test::pick(rng, 1, 3);
            changed =
                orthoray::to_string(n.value + (orthoray::test::chance(rng, 50) ? delta : -delta));
        } else if (t[j] == "hit" && j + 1 == t.size() && t[0] == "piece") {
            changed = "";
        } else {
            changed = other_word(t[j], rng);
            if (changed == t[j]) continue;
        }
        what = "line " + std::to_string(at + 1) + ": '" + lines[at] + "' token " +
               std::to_string(j) + " -> '" + changed + "'";
        t[j] = changed;
        lines[at].clear();
        for (const std::string& w : t)
            if (!w.empty()) lines[at] += (lines[at].empty() ? "" : " ") + w;
        std::string result;
        for (const std::string& line : lines) result += line + "\n";
        return result;
    }
}

} // namespace

TEST_CASE("the induction engine's certificates of random scenes verify, tampered ones do not",
          "[induction-certificate][engine][slow]") {
    std::mt19937_64 rng(8101);
    struct Family {
        orthoray::test::RandomSceneShape shape;
        int goal;
    };
    std::vector<Family> families(3);
    families[0].shape = {2, 12, 6, 3, 3};
    // A quarter of the scenes under sanitizers (support/case_count.hpp).
    families[0].goal = orthoray::test::case_count(150);
    families[1].shape = {2, 12, 6, 1, 2};
    families[1].goal = orthoray::test::case_count(100);
    families[2].shape = {2, 30, 10, 2, 5};
    families[2].goal = orthoray::test::case_count(100);
    const int wanted = orthoray::test::case_count(350);
    int induced = 0, tampered = 0, rejected = 0, neutral = 0, jsonl = 0;
    int by_reason[4] = {};
    for (Family& family : families) {
        family.shape.box_percent = 90;
        int got = 0;
        for (int attempt = 0; got < family.goal && attempt < 20 * family.goal; ++attempt) {
            Scene scene = orthoray::test::random_scene(rng, family.shape);
            scene.target() = orthoray::test::random_target(rng, scene, family.shape);
            const bool json = orthoray::test::chance(rng, 25);
            std::stringstream out;
            orthoray::CertificateWriter writer(out, scene,
                                               json ? orthoray::CertificateFormat::jsonl
                                                    : orthoray::CertificateFormat::text);
            orthoray::SolveOptions o;
            o.engine = orthoray::Engine::induction;
            writer.attach(o);
            const orthoray::Answer answer = orthoray::solve(scene, o);
            writer.finish(answer);
            if (answer.engine != orthoray::EngineUsed::induction)
                continue; // answered on the first segments
            const std::string text = out.str();
            INFO("scene:\n" << orthoray::write_scene(scene) << "certificate:\n" << text);
            REQUIRE(text.find("induction") != std::string::npos);
            const Outcome outcome = verify(scene, text);
            INFO("verify said: " << outcome.message);
            const std::string expected = std::string("valid: ") +
                                         orthoray::to_string(answer.reason) + ", " +
                                         answer.reflections.get_str() + " reflections";
            REQUIRE(outcome.valid);
            REQUIRE(outcome.message == expected);
            ++got;
            ++induced;
            jsonl += json;
            ++by_reason[static_cast<int>(answer.reason)];
            if (json) continue; // the tampering below edits the text format
            for (int k = 0; k < 4; ++k) {
                std::string what;
                const std::string bad = tamper_once(text, rng, what);
                const Outcome t = verify(scene, bad);
                INFO("tampered " << what << "\nverify said: " << t.message);
                ++tampered;
                if (t.valid) {
                    // Some edits change nothing that matters (a transversal's
                    // LO or HI moved past its last state): the verdict stays true.
                    CHECK(t.message == expected);
                    ++neutral;
                } else {
                    CHECK((t.input_error || t.message.rfind("invalid: ", 0) == 0));
                    ++rejected;
                }
            }
        }
        CHECK(got == family.goal);
    }
    WARN("induced " << induced << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                    << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3] << ", " << jsonl
                    << " as JSON Lines), tampered " << tampered << ": rejected " << rejected
                    << ", neutral " << neutral);
    for (int count : by_reason) CHECK(count * 35 >= wanted);
    CHECK(rejected * 10 >= tampered * 9);
}

TEST_CASE("the engines' certificates of huge family instances verify",
          "[induction-certificate][engine][slow]") {
    using orthoray::BoxFamily;
    std::vector<orthoray::GeneratedScene> scenes;
    const Integer big_a = (Integer(1) << 61) - 1, big_b("1000000000000000000");
    for (BoxFamily::Target target :
         {BoxFamily::Target::reached, BoxFamily::Target::far, BoxFamily::Target::generic}) {
        BoxFamily box;
        box.sides = {big_a, big_b};
        box.target = target;
        scenes.push_back(orthoray::generate_box(box));
        scenes.push_back(orthoray::generate_coprime_box(30, target));
    }
    scenes.push_back(orthoray::generate_hallway(
        Rational(Integer("1000000000000000000000000000000")), Rational(1, 3)));
    scenes.push_back(orthoray::generate_square(Integer("123456789012345678901"),
                                               Integer("98765432109876543210")));
    orthoray::RandomFamily maze;
    maze.mirrors = 200;
    maze.box = true;
    maze.range = std::int64_t(1) << 40;
    maze.seed = 11;
    scenes.push_back(orthoray::generate_random(maze));
    int induced = 0;
    for (const orthoray::GeneratedScene& g : scenes) {
        for (orthoray::Engine engine : {orthoray::Engine::induction, orthoray::Engine::automatic}) {
            // The default engine streams its whole simulated prefix (for the
            // maze about 300,000 points, 12 s to check): the maze is checked
            // through --engine induction only.
            if (engine == orthoray::Engine::automatic && &g == &scenes.back()) continue;
            INFO("scene:\n" << orthoray::write_generated(g));
            std::stringstream out;
            orthoray::CertificateWriter writer(out, g.scene);
            orthoray::SolveOptions o;
            o.engine = engine;
            writer.attach(o);
            const orthoray::Answer answer = orthoray::solve(g.scene, o);
            writer.finish(answer);
            REQUIRE(answer.decided());
            if (g.expect) {
                CHECK(answer.reason == g.expect->reason);
                CHECK(answer.reflections == g.expect->reflections);
            }
            induced += answer.engine == orthoray::EngineUsed::induction;
            const Outcome outcome = verify(g.scene, out.str());
            INFO("verify said: " << outcome.message);
            CHECK(outcome.message == std::string("valid: ") + orthoray::to_string(answer.reason) +
                                         ", " + answer.reflections.get_str() + " reflections");
        }
    }
    CHECK(induced >= 15);
}
