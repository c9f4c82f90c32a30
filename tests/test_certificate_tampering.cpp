// Certificates (docs/certificates.md) changed after the fact: every kind of
// tampering with an example instance's certificate (points, counts, words,
// the target, the escape direction, a cycle's period and state, the end
// line, another scene) is rejected.
#include "support/certificate_lines.hpp"
#include "support/certificate_outcome.hpp"
#include "support/curated_scenes.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

using namespace orthoray::test;
using orthoray::Engine;
using orthoray::Rational;
using orthoray::Reason;
using orthoray::Scene;

namespace {

const Rational one_seventh(1, 7);

} // namespace

// ------------------------------------------------------------ tampering --

TEST_CASE("tampered points are rejected", "[certificate]") {
    for (const CuratedScene& instance : curated_scenes()) {
        for (Engine engine : {Engine::lattice, Engine::reference}) {
            const Certified c = certify(instance.scene, engine);
            const Lines lines = split_lines(c.text);
            const auto points = lines_with(lines, "point");
            REQUIRE(!points.empty());
            INFO("instance " << instance.name);
            for (std::size_t k = 0; k < points.size(); ++k) {
                const std::size_t at = points[k];
                // Move point k by +-1/7 on each axis.
                for (int axis = 0; axis < instance.scene.dim; ++axis) {
                    for (int sign : {1, -1}) {
                        Lines moved = lines;
                        moved[at] = with_number(lines[at], 1 + axis, [&](const Rational& x) {
                            return Rational(x + sign * one_seventh);
                        });
                        expect_rejected(instance.scene, join(moved),
                                        "point " + std::to_string(k) + " moved on axis " +
                                            std::to_string(axis));
                    }
                }
                // Drop point k.
                Lines dropped = lines;
                dropped.erase(dropped.begin() + static_cast<std::ptrdiff_t>(at));
                expect_rejected(instance.scene, join(dropped),
                                "point " + std::to_string(k) + " dropped");
                // Duplicate point k.
                Lines doubled = lines;
                doubled.insert(doubled.begin() + static_cast<std::ptrdiff_t>(at), lines[at]);
                expect_rejected(instance.scene, join(doubled),
                                "point " + std::to_string(k) + " duplicated");
            }
            // Swap two consecutive points.
            for (std::size_t k = 0; k + 1 < points.size(); ++k) {
                if (lines[points[k]] == lines[points[k + 1]]) continue;
                Lines swapped = lines;
                std::swap(swapped[points[k]], swapped[points[k + 1]]);
                expect_rejected(instance.scene, join(swapped),
                                "points " + std::to_string(k) + " and " + std::to_string(k + 1) +
                                    " swapped");
            }
        }
    }
}

TEST_CASE("a wrong reflections count is rejected", "[certificate]") {
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        const Lines lines = split_lines(c.text);
        const std::size_t at = line_with(lines, "reflections");
        INFO("instance " << instance.name);
        for (int delta : {1, -1, 1000}) {
            Lines changed = lines;
            changed[at] =
                with_number(lines[at], 1, [&](const Rational& x) { return Rational(x + delta); });
            expect_rejected(instance.scene, join(changed),
                            "reflections changed by " + std::to_string(delta));
        }
    }
}

TEST_CASE("wrong answer and reason words are rejected", "[certificate]") {
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        const Lines lines = split_lines(c.text);
        const std::size_t answer_at = line_with(lines, "answer");
        const std::size_t reason_at = line_with(lines, "reason");
        INFO("instance " << instance.name);
        for (const char* word : {"yes", "no", "unknown", "maybe", "YES"}) {
            if (tokens(lines[answer_at])[1] == word) continue;
            Lines changed = lines;
            changed[answer_at] = std::string("answer ") + word;
            expect_rejected(instance.scene, join(changed), std::string("answer ") + word);
        }
        for (const char* word : {"hit", "escape", "absorbed", "cycle", "limit", "timeout"}) {
            if (tokens(lines[reason_at])[1] == word) continue;
            Lines changed = lines;
            changed[reason_at] = std::string("reason ") + word;
            expect_rejected(instance.scene, join(changed), std::string("reason ") + word);
        }
        // A reason word that agrees with a changed answer word is still a lie.
        const bool yes = c.answer.yes();
        Lines flipped = lines;
        flipped[answer_at] = yes ? "answer no" : "answer yes";
        flipped[reason_at] = yes ? "reason escape" : "reason hit";
        expect_rejected(instance.scene, join(flipped), "answer and reason flipped together");
    }
}

TEST_CASE("a certificate without its final end line never verifies", "[certificate]") {
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        const Lines lines = split_lines(c.text);
        REQUIRE(lines.back() == "end");
        INFO("instance " << instance.name);
        // Without `end`: reported as incomplete, not as a syntax error.
        const Lines no_end(lines.begin(), lines.end() - 1);
        const Outcome outcome = verify(instance.scene, join(no_end));
        INFO("verify said: " << outcome.message);
        CHECK_FALSE(outcome.valid);
        CHECK_FALSE(outcome.input_error);
        CHECK(outcome.message.find("incomplete") != std::string::npos);
        // Every shorter prefix (a solver stopped while writing) is incomplete too.
        for (std::size_t n = 0; n < lines.size(); ++n) {
            const Lines prefix(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(n));
            expect_rejected(instance.scene, join(prefix),
                            "only the first " + std::to_string(n) + " lines");
        }
        // Cut in the middle of the last line (no newline, `en`).
        std::string cut = c.text.substr(0, c.text.size() - 2);
        expect_rejected(instance.scene, cut, "the end line cut to 'en'");
    }
}

TEST_CASE("a changed target line is rejected", "[certificate]") {
    int hits = 0;
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        if (!c.answer.yes()) continue;
        ++hits;
        const Lines lines = split_lines(c.text);
        const std::size_t at = line_with(lines, "target");
        INFO("instance " << instance.name);
        for (int axis = 0; axis < instance.scene.dim; ++axis) {
            for (int sign : {1, -1}) {
                Lines changed = lines;
                changed[at] = with_number(lines[at], 1 + axis, [&](const Rational& x) {
                    return Rational(x + sign * one_seventh);
                });
                expect_rejected(instance.scene, join(changed),
                                "target moved on axis " + std::to_string(axis));
            }
        }
        // The target line is required for a hit.
        Lines dropped = lines;
        dropped.erase(dropped.begin() + static_cast<std::ptrdiff_t>(at));
        expect_rejected(instance.scene, join(dropped), "target line dropped");
    }
    CHECK(hits >= 10);
}

TEST_CASE("a changed escape direction is rejected", "[certificate]") {
    int escapes = 0;
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        if (c.answer.reason != Reason::escape) continue;
        ++escapes;
        const Lines lines = split_lines(c.text);
        const std::size_t at = line_with(lines, "direction");
        INFO("instance " << instance.name);
        for (int axis = 0; axis < instance.scene.dim; ++axis) {
            const Rational v = number(tokens(lines[at])[1 + axis]);
            if (v != 0) {
                Lines negated = lines;
                negated[at] = with_number(lines[at], 1 + axis,
                                          [](const Rational& x) { return Rational(-x); });
                expect_rejected(instance.scene, join(negated),
                                "direction negated on axis " + std::to_string(axis));
            }
            Lines shifted = lines;
            shifted[at] = with_number(lines[at], 1 + axis,
                                      [](const Rational& x) { return Rational(x + one_seventh); });
            expect_rejected(instance.scene, join(shifted),
                            "direction shifted on axis " + std::to_string(axis));
        }
        // Directions are written exactly as the ray travels, not normalised.
        Lines doubled = lines;
        for (int axis = 0; axis < instance.scene.dim; ++axis)
            doubled[at] = with_number(doubled[at], 1 + axis,
                                      [](const Rational& x) { return Rational(2 * x); });
        expect_rejected(instance.scene, join(doubled), "direction doubled");
    }
    CHECK(escapes >= 3);
}

TEST_CASE("a wrong cycle period or state is rejected", "[certificate]") {
    int cycles = 0;
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        if (c.answer.reason != Reason::cycle) continue;
        ++cycles;
        INFO("instance " << instance.name);
        const Lines lines = split_lines(c.text);
        const auto points = lines_with(lines, "point");
        const std::size_t period_at = line_with(lines, "period");
        const std::size_t reflections_at = line_with(lines, "reflections");
        const std::size_t state_at = line_with(lines, "state");
        const std::size_t L = c.answer.reflections.get_ui();
        REQUIRE(points.size() == L + 2);
        REQUIRE(lines[points[L + 1]] == lines[points[1]]);

        const Lines head(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(points[0]));
        const Lines tail(lines.begin() + static_cast<std::ptrdiff_t>(points.back()) + 1,
                         lines.end());
        // The certificate with period M: points p0 .. p(M+1) along the
        // periodic path (p(k) = p(1 + (k-1) mod L)), and `reflections` and
        // `period` either both M (a consistent lie) or left at L.
        auto with_period = [&](std::size_t M, bool change_count, bool change_period) {
            Lines out = head;
            out.push_back(lines[points[0]]);
            for (std::size_t k = 1; k <= M + 1; ++k) out.push_back(lines[points[1 + (k - 1) % L]]);
            for (std::string line : tail) {
                if (change_count && keyword(line) == "reflections")
                    line = "reflections " + std::to_string(M);
                if (change_period && keyword(line) == "period")
                    line = "period " + std::to_string(M);
                out.push_back(line);
            }
            return join(out);
        };
        // Sanity: rebuilding with M = L gives back the original text.
        REQUIRE(with_period(L, true, true) == c.text);

        for (std::size_t M : {L - 1, L + 1, 2 * L, 3 * L}) {
            const std::string m = std::to_string(M);
            expect_rejected(instance.scene, with_period(M, true, true),
                            "period and reflections " + m + " with matching points");
            expect_rejected(instance.scene, with_period(M, false, true),
                            "period " + m + " with matching points");
            expect_rejected(instance.scene, with_period(M, true, false),
                            "reflections " + m + " with matching points");
            // Only the period line changed.
            Lines changed = lines;
            changed[period_at] = "period " + m;
            expect_rejected(instance.scene, join(changed), "only the period line " + m);
            // Period and reflections lines changed, points left alone.
            changed[reflections_at] = "reflections " + m;
            expect_rejected(instance.scene, join(changed), "period and reflections lines " + m);
        }
        // The state must be state 1, point and direction.
        const int dim = instance.scene.dim;
        for (int slot = 0; slot < 2 * dim; ++slot) {
            Lines changed = lines;
            changed[state_at] = with_number(lines[state_at], 1 + slot, [](const Rational& x) {
                return Rational(x + one_seventh);
            });
            expect_rejected(instance.scene, join(changed),
                            "state slot " + std::to_string(slot) + " shifted");
            const Rational x = number(tokens(lines[state_at])[1 + slot]);
            if (slot >= dim && x != 0) {
                changed[state_at] = with_number(lines[state_at], 1 + slot,
                                                [](const Rational& y) { return Rational(-y); });
                expect_rejected(instance.scene, join(changed),
                                "state direction negated on axis " + std::to_string(slot - dim));
            }
        }
        // The state of reflection 2 instead of reflection 1, with the points
        // rotated by one so that they close on it.
        {
            Lines out = head;
            // p0 then p2 .. p(L+1), p2: the path from the start skips p1.
            out.push_back(lines[points[0]]);
            for (std::size_t k = 2; k <= L + 2; ++k) out.push_back(lines[points[1 + (k - 1) % L]]);
            for (const std::string& line : tail) out.push_back(line);
            expect_rejected(instance.scene, join(out), "path starting its cycle at p2");
        }
    }
    CHECK(cycles >= 3);
}

TEST_CASE("a verdict the listed path contradicts is rejected", "[certificate]") {
    // Points true to the scene, with a verdict they refute. An escape whose
    // final ray passes the target: the answer is yes, with 0 reflections.
    const Scene open = orthoray::read_scene("dim 2\nray 0 0 1 0\ntarget 5 0\n", "<scene>");
    expect_invalid(open,
                   "orthoray-certificate 1\ndim 2\npoint 0 0\nanswer no\nreason escape\n"
                   "reflections 0\ndirection 1 0\nend\n",
                   "the target lies on the final ray from point 0");
    // A hit claimed for a target behind the absorber that stops the ray at
    // (3, 0), with its count one past the absorption point.
    const Scene stopped =
        orthoray::read_scene("dim 2\nabsorber x 3 y -1 1\nray 0 0 1 0\ntarget 5 0\n", "<scene>");
    const std::string absorbed = "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 3 0\n"
                                 "answer no\nreason absorbed\nreflections 0\nend\n";
    expect_valid(stopped, absorbed, "valid: absorbed, 0 reflections");
    expect_invalid(stopped,
                   "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 3 0\nanswer yes\n"
                   "reason hit\nreflections 1\ntarget 5 0\nend\n",
                   "the ray is absorbed at point 1, yet the reason is hit");
}

TEST_CASE("a certificate of a different scene is rejected", "[certificate]") {
    const auto& all = curated_scenes();
    std::vector<std::string> texts;
    for (const CuratedScene& instance : all)
        texts.push_back(certify(instance.scene, Engine::lattice).text);
    for (std::size_t i = 0; i < all.size(); ++i) {
        for (std::size_t j = 0; j < all.size(); ++j) {
            if (i == j) continue;
            INFO("certificate of " << all[i].name << " checked against " << all[j].name);
            const Outcome outcome = verify(all[j].scene, texts[i]);
            INFO("verify said: " << outcome.message);
            CHECK_FALSE(outcome.valid);
            // A 2D certificate for a 3D scene fails on its `dim` line.
            if (all[i].scene.dim != all[j].scene.dim) CHECK(outcome.input_error);
        }
    }
}

TEST_CASE("a certificate is rejected when the scene changes under it", "[certificate]") {
    // Moving the start point by 1/7, or an element the path touches along
    // its normal axis so that the answer changes, invalidates the
    // certificate.
    int changed = 0;
    for (const CuratedScene& instance : curated_scenes()) {
        const Certified c = certify(instance.scene, Engine::lattice);
        INFO("instance " << instance.name);
        for (int axis = 0; axis < instance.scene.dim; ++axis) {
            Scene moved = instance.scene;
            moved.ray().start[axis] += one_seventh;
            expect_rejected(moved, c.text, "start moved on axis " + std::to_string(axis));
            // (When the target is the start, any direction reaches it at once.)
            Scene turned = instance.scene;
            if (turned.ray().direction[axis] != 0 && turned.target() != turned.ray().start) {
                turned.ray().direction[axis] = -turned.ray().direction[axis];
                expect_rejected(turned, c.text,
                                "direction negated on axis " + std::to_string(axis));
            }
        }
        // An element moved by 1/7 along its normal axis: where that changes
        // the answer (the path touched it), the certificate must fail.
        for (std::size_t k = 0; k < instance.scene.elements.size(); ++k) {
            if (instance.scene.elements[k].is_diagonal()) continue;
            Scene moved = instance.scene;
            orthoray::Element& e = moved.elements[k];
            e.lo[e.axis] += one_seventh;
            e.hi[e.axis] += one_seventh;
            const orthoray::Answer truth = orthoray::solve(moved);
            if (truth.reason == c.answer.reason && truth.reflections == c.answer.reflections)
                continue;
            ++changed;
            expect_rejected(moved, c.text, "element " + std::to_string(k + 1) + " moved");
        }
        // With every element removed, only a zero-reflection escape or hit
        // could still hold.
        Scene empty = instance.scene;
        empty.elements.clear();
        if (c.answer.reflections != 0 || c.answer.reason == Reason::absorbed)
            expect_rejected(empty, c.text, "all elements removed");
    }
    CHECK(changed > 10);
}
