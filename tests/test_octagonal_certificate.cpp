// Induction certificates of octagonal scenes (docs/induction-certificates.md,
// "Octagonal scenes"): the engine's certificates of random octagonal
// trajectories (walks between collisions among them) verify in both
// formats, edited ones are rejected, and the
// closed forms of the diamond and the right triangle with sides 10^18 are
// certified and verified.
#include "support/case_count.hpp"
#include "support/certificate_lines.hpp"
#include "support/certificate_outcome.hpp"
#include "support/octagonal_families.hpp"
#include "support/portable_random.hpp"
#include "support/random_octagonal.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/exchange.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace orthoray;
using orthoray::test::Outcome;

namespace {

using orthoray::test::join;
using orthoray::test::split_lines;
using orthoray::test::tokens;
using orthoray::test::untokens;

using test::Certified;
using test::certify;
using test::diamond;
using test::shoot;
using test::triangle;

std::string expected_message(const Answer& a) {
    return std::string("valid: ") + to_string(a.reason) + ", " + a.reflections.get_str() +
           " reflections";
}

// One numeric operand of one statement starting with `keyword` moved by
// +-1..3; empty when the certificate has no such operand.
std::string nudged(const std::string& text, const std::string& keyword, std::size_t operand,
                   std::mt19937_64& rng) {
    std::vector<std::string> lines = split_lines(text);
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string> w = tokens(lines[i]);
        if (!w.empty() && w[0] == keyword && w.size() > operand) candidates.push_back(i);
    }
    if (candidates.empty()) return {};
    const std::size_t at = candidates[test::pick_index(rng, 0, candidates.size() - 1)];
    std::vector<std::string> w = tokens(lines[at]);
    const int size = test::pick(rng, 1, 3); // before the sign: operands of * are unsequenced
    const int delta = test::chance(rng, 50) ? size : -size;
    const Integer n(w[operand]);
    const Integer moved = n + delta;
    w[operand] = (moved < 0 ? Integer(n - delta) : moved).get_str(); // counts stay >= 0
    lines[at] = untokens(w);
    return join(lines);
}

// The certificate without its line starting with `prefix`; empty when it
// has none.
std::string without_line(const std::string& text, const std::string& prefix) {
    std::vector<std::string> lines = split_lines(text);
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].rfind(prefix, 0) == 0) {
            lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
            return join(lines);
        }
    return {};
}

// A cut piece's join moved by +-1..3 (a walk certificate's claim that the
// ray steps there); empty when there is no cut piece.
std::string join_nudged(const std::string& text, std::mt19937_64& rng) {
    std::vector<std::string> lines = split_lines(text);
    std::vector<std::size_t> cuts;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].rfind("piece ", 0) == 0 && tokens(lines[i])[3] == "cut") cuts.push_back(i);
    if (cuts.empty()) return {};
    const std::size_t at = cuts[test::pick_index(rng, 0, cuts.size() - 1)];
    std::vector<std::string> w = tokens(lines[at]);
    const Integer cut_at(w[5]);
    w[5] = Integer(cut_at + test::pick(rng, 1, 3)).get_str();
    lines[at] = untokens(w);
    return join(lines);
}

// A piece's kind swapped for another: the claim about its states changes.
std::string rekinded(const std::string& text, std::mt19937_64& rng) {
    std::vector<std::string> lines = split_lines(text);
    std::vector<std::size_t> pieces;
    for (std::size_t i = 0; i < lines.size(); ++i)
        if (lines[i].rfind("piece ", 0) == 0) pieces.push_back(i);
    const std::size_t at = pieces[test::pick_index(rng, 0, pieces.size() - 1)];
    std::vector<std::string> w = tokens(lines[at]);
    static const char* const kinds[] = {"reflect", "escape", "absorbed"};
    std::string other = w[3];
    while (other == w[3]) other = kinds[test::pick(rng, 0, 2)];
    w[3] = other;
    lines[at] = untokens(w);
    return join(lines);
}

} // namespace

TEST_CASE("octagonal induction certificates of random scenes verify, edited ones do not",
          "[octagonal][induction-certificate]") {
    std::mt19937_64 rng(14'401);
    test::RandomOctagonalShape shape;
    const int cases = test::case_count(600);
    int certified = 0, jsonl = 0, twins = 0, walks = 0, tails = 0, tampered = 0, rejected = 0;
    int by_reason[4] = {};
    for (int i = 0; i < cases; ++i) {
        shape.max_elements = 2 + i % 10;
        shape.box = 3 + i % 5;
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.single_trajectory() || !s.has_diagonal() || s.has_one_sided()) continue;
        const bool json = i % 2 == 0;
        const Certified c = certify(s, Engine::induction,
                                    json ? CertificateFormat::jsonl : CertificateFormat::text);
        INFO("case " << i << "\n" << write_scene(s) << "certificate:\n" << c.text);
        const Outcome outcome = test::verify(s, c.text);
        INFO("verify said: " << outcome.message);
        REQUIRE(outcome.valid);
        REQUIRE(outcome.message == expected_message(c.answer));
        if (c.answer.engine != EngineUsed::induction) continue; // a path certificate
        REQUIRE(c.text.find("octagonal-induction") != std::string::npos);
        ++certified;
        jsonl += json;
        twins += c.text.find("twin-search") != std::string::npos;
        if (c.text.find("walk-search") != std::string::npos) {
            ++walks;
            tails += c.answer.reason == Reason::cycle && c.answer.tail > 0;
        }
        ++by_reason[static_cast<int>(c.answer.reason)];
        if (json) continue; // the edits below are on the text format
        // A count, a position, a length, an image, a kind, a step, the
        // period, x or its twin, the twin search: each edit must be caught.
        const std::string edits[] = {nudged(c.text, "lifted", 5, rng),
                                     nudged(c.text, "lifted", 1 + test::pick(rng, 0, 1), rng),
                                     nudged(c.text, "piece", 2, rng),
                                     nudged(c.text, "piece", 4, rng),
                                     rekinded(c.text, rng),
                                     nudged(c.text, "step", 2, rng),
                                     nudged(c.text, "reflections", 1, rng),
                                     nudged(c.text, "period", 1, rng),
                                     nudged(c.text, "first", 2, rng),
                                     nudged(c.text, "twin", 2, rng),
                                     without_line(c.text, "twin-search"),
                                     without_line(c.text, "twin "),
                                     nudged(c.text, "walk-search", 1, rng),
                                     nudged(c.text, "walk-search", 3, rng),
                                     without_line(c.text, "walk-search"),
                                     join_nudged(c.text, rng)};
        for (const std::string& bad : edits) {
            if (bad.empty()) continue;
            const Outcome t = test::verify(s, bad);
            INFO("edited:\n" << bad << "verify said: " << t.message);
            ++tampered;
            // An edit may keep every claim true: a state no reflecting piece
            // maps to (a hole, never on x's orbit) moved to another point
            // whose ray also escapes or is absorbed. Then the verdict must
            // stay the same.
            if (t.valid) {
                CHECK(t.message == outcome.message);
                continue;
            }
            CHECK((t.input_error || t.message.rfind("invalid: ", 0) == 0));
            ++rejected;
        }
    }
    WARN("certified " << certified << " (hit/escape/absorbed/cycle " << by_reason[0] << "/"
                      << by_reason[1] << "/" << by_reason[2] << "/" << by_reason[3] << ", " << jsonl
                      << " as JSON Lines, " << twins << " with a twin search, " << walks
                      << " walks, " << tails << " with a tail), edited " << tampered
                      << ": rejected " << rejected);
    CHECK(walks >= cases / 20);
    CHECK(tails >= 1);
    CHECK(certified >= cases / 4);
    for (int count : by_reason) CHECK(count >= cases / 100);
    CHECK(twins > 0);
    CHECK(rejected * 100 >= tampered * 95);
}

TEST_CASE("huge octagonal closed forms are certified and verified",
          "[octagonal][induction-certificate]") {
    // The closed forms of tests/test_octagonal_induction.cpp, far beyond any
    // path certificate: the diamond's period 2(|p| + |q|) and the right
    // triangle's 2|a| + 2|b| + |a + b| + |a - b|, both with sides 10^18,
    // from the induction engine and from the default one, in both formats.
    const Integer n("1000000000000000000");
    struct Case {
        Scene scene;
        Reason reason;
        Integer reflections;
    };
    std::vector<Case> cases;
    for (const Integer& m : {Integer("1000000000000000001"), Integer("999999999999999999999")}) {
        Scene s = diamond(n);
        shoot(s, Rational(1, 2), Rational(1, 2), 1, m);
        cases.push_back({s, Reason::cycle, 2 * m});
    }
    for (const auto& [a, b] :
         {std::pair<Integer, Integer>{3, 7}, {Integer(1), Integer("3000000000000000001")}}) {
        Scene s = triangle(n);
        shoot(s, Rational(1, 3), Rational(1, 7), a, b);
        cases.push_back({s, Reason::cycle,
                         2 * abs(a) + 2 * abs(b) + Integer(abs(a + b)) + Integer(abs(a - b))});
    }
    // Along an axis on the double cover: a hit after 2, a cycle of 4.
    Scene axis = diamond(n);
    shoot(axis, 5, 7, 1, 0);
    axis.target() = {0, -7, 0};
    cases.push_back({axis, Reason::hit, 2});
    axis.target() = {1, 2, 0};
    cases.push_back({axis, Reason::cycle, 4});
    for (const Case& c : cases)
        for (const Engine engine : {Engine::induction, Engine::automatic})
            for (const CertificateFormat format :
                 {CertificateFormat::text, CertificateFormat::jsonl}) {
                const Certified got = certify(c.scene, engine, format);
                INFO(write_scene(c.scene) << "certificate:\n" << got.text);
                CHECK(got.answer.reason == c.reason);
                CHECK(got.answer.reflections == c.reflections);
                if (c.reflections > 100)
                    CHECK(got.text.find("octagonal-induction") != std::string::npos);
                const Outcome outcome = test::verify(c.scene, got.text);
                INFO("verify said: " << outcome.message);
                CHECK(outcome.valid);
                CHECK(outcome.message == expected_message(got.answer));
                if (format == CertificateFormat::jsonl || c.reflections < 100) continue;
                // The period one off, or twice as long, is refused.
                for (const Integer& wrong :
                     {Integer(c.reflections + 1), Integer(2 * c.reflections)}) {
                    std::string bad = got.text;
                    const std::string from = "period " + c.reflections.get_str();
                    const std::size_t at = bad.find(from);
                    REQUIRE(at != std::string::npos);
                    bad.replace(at, from.size(), "period " + wrong.get_str());
                    const std::string reflections = "reflections " + c.reflections.get_str();
                    bad.replace(bad.find(reflections), reflections.size(),
                                "reflections " + wrong.get_str());
                    const Outcome t = test::verify(c.scene, bad);
                    CHECK(!t.valid);
                    CHECK(t.message.find("the induction gives") != std::string::npos);
                }
            }
}

TEST_CASE("solve --engine induction --certificate, verify and render on a huge diamond",
          "[octagonal][induction-certificate][cli]") {
    // Once refused (exit 2); now the certificate is written, verifies, and
    // render draws the path by simulating it, as for axis-parallel scenes.
    test::TempDir dir;
    const std::string scene =
        dir.write("diamond.scene", "dim 2\n"
                                   "mirror / 0 -1000000000000000000 1000000000000000000 0\n"
                                   "mirror \\ -1000000000000000000 0 0 -1000000000000000000\n"
                                   "mirror \\ 0 1000000000000000000 1000000000000000000 0\n"
                                   "mirror / -1000000000000000000 0 0 1000000000000000000\n"
                                   "ray 1/2 1/2 1 1000000000000000001\n"
                                   "target 2000000000000000000 2000000000000000000\n");
    for (const char* engine : {"induction", "auto"}) {
        const std::string cert = dir.path(std::string(engine) + ".cert");
        const test::CliResult solved =
            test::run_cli("solve " + test::quote(scene) + " --engine " + engine +
                          " --certificate " + test::quote(cert));
        INFO(solved.out << solved.err);
        CHECK(solved.status == 1); // the answer no
        CHECK(test::slurp(cert).find("method octagonal-induction") != std::string::npos);
        const test::CliResult verified =
            test::run_cli("verify " + test::quote(scene) + " " + test::quote(cert));
        CHECK(verified.status == 0);
        CHECK(verified.out == "valid: cycle, 2000000000000000002 reflections\n");
        const std::string svg = dir.path(std::string(engine) + ".svg");
        CHECK(test::run_cli("render " + test::quote(scene) + " --certificate " + test::quote(cert) +
                            " -o " + test::quote(svg))
                  .status == 0);
        CHECK(test::slurp(svg).find("<svg") != std::string::npos);
    }
}

TEST_CASE("malformed octagonal induction statements are one located error",
          "[octagonal][certificate][bad-input]") {
    // The diamond |x| + |y| = 5 shot along (1, 3): its certificate's line 5
    // is the method, lines 8 and 9 the first two transversals.
    test::TempDir dir;
    const std::string scene = dir.write("diamond.scene", "dim 2\n"
                                                         "mirror / -5 0 0 5\n"
                                                         "mirror \\ 0 5 5 0\n"
                                                         "mirror / 0 -5 5 0\n"
                                                         "mirror \\ -5 0 0 -5\n"
                                                         "ray 1/2 1/2 1 3\n"
                                                         "target 100 100\n");
    const std::string cert = dir.path("diamond.cert");
    REQUIRE(test::run_cli("solve --engine induction --certificate " + test::quote(cert) + " " +
                          test::quote(scene))
                .status == 1);
    std::vector<std::string> lines;
    {
        std::istringstream in(read_file(cert));
        for (std::string line; std::getline(in, line);) lines.push_back(line);
    }
    REQUIRE(lines.size() > 9);
    REQUIRE(lines[4] == "method octagonal-induction");
    const struct {
        std::size_t line;
        std::string text, message;
    } cases[] = {
        {4, "method octagonal", "bad.cert:5:8: found 'octagonal', expected 'induction'"},
        {7, lines[7].substr(0, lines[7].rfind(' ')),
         "bad.cert:8:" + std::to_string(lines[7].rfind(' ') + 1) +
             ": found end of line, expected an integer"},
        {8, "lifted 48 -192 120 120 two -1 3",
         "bad.cert:9:24: found 'two', expected a non-negative integer"},
    };
    for (const auto& c : cases) {
        std::vector<std::string> edited = lines;
        edited[c.line] = c.text;
        std::string text;
        for (const std::string& line : edited) text += line + '\n';
        const std::string bad = dir.write("bad.cert", text);
        const test::CliResult r =
            test::run_cli("verify " + test::quote(scene) + " " + test::quote(bad));
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err == bad.substr(0, bad.size() - 8) + c.message + "\n");
    }
}

TEST_CASE("a walk of 10^18 reflections after a tail is certified and verified",
          "[octagonal][induction-certificate]") {
    // The slide box of bench/octagonal_induction_bench.cpp at sides near
    // 10^18: a mirror of length sqrt(2) on the floor, a ray along (1, 1).
    // Two states step to one, the cycle comes after a tail of 6.7 x 10^17,
    // and the certificate is a few searches, in both formats.
    const Integer n("1000000000000000000");
    const Integer w = n + 3, h = n - 11, x0 = n / 3 + 1;
    const Scene s = test::slide_box(w, h, x0, Rational(n / 2 + 5), Rational(n / 7 + 2),
                                    {Rational(2 * w), Rational(2 * h), 0});
    for (const CertificateFormat format : {CertificateFormat::text, CertificateFormat::jsonl}) {
        const Certified c = certify(s, Engine::induction, format);
        INFO(c.text);
        CHECK(c.answer.engine == EngineUsed::induction);
        CHECK(c.answer.reason == Reason::cycle);
        CHECK(c.answer.tail > Integer("100000000000000000"));
        CHECK(c.text.find("walk-search") != std::string::npos);
        const Outcome v = test::verify(s, c.text);
        CHECK(v.valid);
        CHECK(v.message == expected_message(c.answer));
    }
}
