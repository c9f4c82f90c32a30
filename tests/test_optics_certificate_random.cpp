// Certificates of optics scenes on random scenes: built from the engines'
// own step (tests/support/branch_certificate.cpp for illumination, the
// reference step for one-sided paths), checked by the verifier's separate
// reading of the rules. The two must agree with each other and with
// solve(), and tampered labels, dropped branch lines and longer tails must
// be rejected.
#include "support/branch_certificate.hpp"
#include "support/case_count.hpp"
#include "support/certificate_outcome.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

#include "engine/reference_step.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using orthoray::Integer;
using orthoray::Reason;
using orthoray::Scene;
using orthoray::TargetAnswer;
using orthoray::Vector;
namespace test = orthoray::test;
using orthoray::test::Outcome;
using orthoray::test::verify;

} // namespace

TEST_CASE("illumination certificates built from the reference step verify and agree with solve",
          "[certificate][optics][property][slow]") {
    // The certificate comes from the engines' own step (tests/support/
    // branch_certificate.cpp), the check from the verifier's: two readings
    // of the rules that must agree, on scenes with splitters, one-sided
    // elements and several rays and targets.
    std::mt19937_64 rng(1215);
    test::RandomOpticsShape shape;
    shape.scene.max_elements = 8;
    const int cases = test::case_count(1000);
    int checked = 0, lit = 0, unlit = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        const Scene s = test::random_optics_scene(rng, shape);
        if (s.single_trajectory()) continue;
        const std::optional<test::BranchCertificate> c = test::branch_certificate(s, 20000);
        if (!c) continue;
        ++checked;
        INFO("case " << i << "\n" << orthoray::write_scene(s) << "certificate:\n" << c->text);
        const orthoray::Answer a = orthoray::solve(s);
        REQUIRE(a.targets.size() == c->targets.size());
        for (std::size_t t = 0; t < a.targets.size(); ++t) {
            CHECK(a.targets[t].status == c->targets[t].status);
            CHECK(a.targets[t].reflections == c->targets[t].reflections);
            CHECK(a.targets[t].ray == c->targets[t].ray);
            (a.targets[t].status == TargetAnswer::Status::lit ? lit : unlit) += 1;
        }
        const Outcome text = verify(s, c->text);
        INFO("verify said: " << text.message);
        CHECK(text.valid);
        CHECK(verify(s, test::as_json_lines(c->text)).message == text.message);

        // Every branch line is needed, and every label is least.
        std::vector<std::string> lines;
        std::istringstream in(c->text);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        const std::size_t b = c->branch_lines[static_cast<std::size_t>(
            orthoray::uniform(rng, 0, static_cast<std::int64_t>(c->branch_lines.size()) - 1))];
        auto joined = [&](std::size_t skip, const std::string& instead) {
            std::string tampered;
            for (std::size_t k = 0; k < lines.size(); ++k) {
                if (k != skip)
                    tampered += lines[k] + "\n";
                else if (!instead.empty())
                    tampered += instead + "\n";
            }
            return tampered;
        };
        const Outcome dropped = verify(s, joined(b, ""));
        CHECK_FALSE(dropped.valid);
        CHECK((dropped.message.find("has no branch line") != std::string::npos));
        const std::size_t at = lines[b].rfind(' ');
        const Integer k(lines[b].substr(at + 1), 10);
        const Outcome raised =
            verify(s, joined(b, lines[b].substr(0, at + 1) + Integer(k + 1).get_str()));
        CHECK_FALSE(raised.valid);
        CHECK((raised.message.find("less than the label") != std::string::npos ||
               raised.message.find("start state") != std::string::npos));
    }
    CHECK(checked > cases / 3);
    CHECK(lit > 0);
    CHECK(unlit > 0);
}

TEST_CASE("path certificates of one-sided scenes built from the reference step verify",
          "[certificate][optics][property][slow]") {
    // Single trajectories with one-sided elements: the points from the
    // engines' step, the tail and period from solve(); a tail one longer
    // (told consistently) must fail as not least.
    std::mt19937_64 rng(1216);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 0;
    shape.one_sided_percent = 50;
    shape.max_rays = 1;
    shape.max_targets = 1;
    const int cases = test::case_count(1500);
    int tails = 0, cycles = 0, checked = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        shape.scene.box_percent = 70;
        const Scene s = test::random_optics_scene(rng, shape);
        orthoray::SolveOptions options;
        options.max_steps = 20000;
        const orthoray::Answer a = orthoray::solve(s, options);
        if (!a.decided() || !s.has_one_sided()) continue;
        ++checked;
        // The points p0 .. pm, m events; for a cycle with one more tail
        // state, `extra` events more.
        auto certificate = [&](std::uint64_t tail) {
            const int dim = s.dim;
            const std::uint64_t reflections = a.reflections.get_ui();
            const std::uint64_t period = reflections - a.tail.get_ui();
            const std::uint64_t events = a.reason == Reason::cycle      ? tail + period + 1
                                         : a.reason == Reason::absorbed ? reflections + 1
                                                                        : reflections;
            std::string text = "orthoray-certificate 1\ndim " + std::to_string(dim) + "\n";
            auto vec = [&](const Vector& x) {
                std::string t;
                for (int j = 0; j < dim; ++j) t.append(" ").append(orthoray::to_string(x[j]));
                return t;
            };
            Vector p = s.ray().start, v = s.ray().direction, state_p, state_v;
            text += "point" + vec(p) + "\n";
            for (std::uint64_t e = 1; e <= events; ++e) {
                const orthoray::engine::ReferenceEvent ev =
                    orthoray::engine::reference_step(s, p, v);
                p = ev.point;
                if (!ev.absorbed) v = ev.direction;
                if (e == tail + 1) state_p = p, state_v = v;
                text += "point" + vec(p) + "\n";
            }
            text += std::string("answer ") + (a.reason == Reason::hit ? "yes" : "no") +
                    "\nreason " + orthoray::to_string(a.reason) + "\nreflections " +
                    (a.reason == Reason::cycle ? std::to_string(tail + period)
                                               : a.reflections.get_str()) +
                    "\n";
            if (a.reason == Reason::hit) text += "target" + vec(s.target()) + "\n";
            if (a.reason == Reason::escape) text += "direction" + vec(v) + "\n";
            if (a.reason == Reason::cycle)
                text += "state" + vec(state_p) + vec(state_v) + "\nperiod " +
                        std::to_string(period) + "\ntail " + std::to_string(tail) + "\n";
            return text + "end\n";
        };
        INFO("case " << i << "\n" << orthoray::write_scene(s));
        const Outcome truth = verify(s, certificate(a.tail.get_ui()));
        INFO("verify said: " << truth.message);
        CHECK(truth.valid);
        if (a.reason != Reason::cycle) continue;
        ++cycles;
        tails += a.tail > 0;
        const Outcome longer = verify(s, certificate(a.tail.get_ui() + 1));
        CHECK_FALSE(longer.valid);
        CHECK(longer.message.find("so the tail is shorter") != std::string::npos);
    }
    CHECK(checked > cases / 3);
    CHECK(cycles > cases / 20);
    // The test sees tails, not only pure cycles: 23 in the full 1,500
    // cases, 3 in the quarter the sanitizer build runs.
    CHECK(tails > cases / 200);
}

TEST_CASE("the engines' own certificates of optics scenes verify in both formats",
          "[certificate][optics][property][slow]") {
    // The round trip none of the pieces checks alone: solve() streams the
    // certificate through CertificateWriter (branch states and witnesses
    // from the illumination search, rho cycles from the lattice engine), and
    // the verifier's separate reading of the rules must accept every one
    // and agree with the answer.
    std::mt19937_64 rng(2411);
    test::RandomOpticsShape shape;
    shape.scene.max_elements = 10;
    const int cases = test::case_count(1200);
    int illumination = 0, single = 0, tails = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        shape.max_rays = i % 3 == 0 ? 1 : 3;
        shape.max_targets = i % 3 == 0 ? 1 : 3;
        shape.splitter_percent = i % 3 == 0 ? 0 : 20;
        const Scene s = test::random_optics_scene(rng, shape);
        for (const auto format :
             {orthoray::CertificateFormat::text, orthoray::CertificateFormat::jsonl}) {
            std::ostringstream out;
            orthoray::CertificateWriter writer(out, s, format);
            orthoray::SolveOptions options;
            options.max_steps = 20000;
            writer.attach(options);
            const orthoray::Answer a = orthoray::solve(s, options);
            writer.finish(a);
            if (!a.decided()) continue;
            INFO("case " << i << "\n" << orthoray::write_scene(s) << "certificate:\n" << out.str());
            const Outcome outcome = verify(s, out.str());
            INFO("verify said: " << outcome.message);
            REQUIRE(outcome.valid);
            if (format == orthoray::CertificateFormat::jsonl) continue;
            if (a.illumination()) {
                ++illumination;
                CHECK(outcome.message.find(std::string("valid: ") + to_string(a.reason)) == 0);
            } else {
                ++single;
                tails += a.reason == Reason::cycle && a.tail > 0;
            }
        }
    }
    CHECK(illumination > cases / 4);
    CHECK(single > cases / 10);
    CHECK(tails > 0);
}
