// Octagonal scenes (docs/octagonal.md): the engines that follow diagonals
// held to each other on seeded random scenes, and their certificates to the
// independent verifier.
#include "engine/branch_state_set.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "orthoray/state_graph.hpp"
#include "support/case_count.hpp"
#include "support/certificate_lines.hpp"
#include "support/certificate_outcome.hpp"
#include "support/random_octagonal.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace orthoray;
using Status = TargetAnswer::Status;

TEST_CASE("the branch state set tells swapped directions apart exactly",
          "[octagonal][illumination]") {
    // With a diagonal, (1, 2) can turn into (2, 1), (-2, -1), ...: eight
    // directions in two classes, (|1|, |2|) and (|2|, |1|), each with four
    // sign masks. Every one is a state of its own and decodes to itself.
    const Scene s = read_scene("dim 2\nmirror / 0 0 1 1\nray 0 0 1 2\ntarget 5 5\n");
    engine::ByteBudget budget(std::nullopt);
    engine::BranchStateSet set(s, budget);
    std::vector<Vector> directions;
    for (const int a : {1, -1})
        for (const int b : {2, -2}) {
            directions.push_back({a, b, 0});
            directions.push_back({b, a, 0});
        }
    const Vector p{Rational(1, 3), 2, 0};
    for (std::size_t i = 0; i < directions.size(); ++i) {
        const auto at = set.insert(p, directions[i]);
        REQUIRE(at);
        CHECK(at->added);
        CHECK(at->index == i);
    }
    for (std::uint32_t i = 0; i < directions.size(); ++i) {
        Vector q, v;
        set.state(i, q, v);
        CHECK(q == p);
        CHECK(v == directions[i]);
        const auto again = set.insert(p, directions[i]);
        CHECK((again && !again->added && again->index == i));
    }
    // Along a diagonal direction the swap is the same class: (1, 1) and
    // (-1, -1) are two states, not four.
    const Scene along = read_scene("dim 2\nmirror \\ 0 1 1 0\nray 0 0 1 1\ntarget 5 5\n");
    engine::BranchStateSet diagonal_set(along, budget);
    CHECK(diagonal_set.insert(p, Vector{1, 1, 0})->added);
    CHECK(diagonal_set.insert(p, Vector{-1, -1, 0})->added);
    CHECK_FALSE(diagonal_set.insert(p, Vector{1, 1, 0})->added);
    CHECK(diagonal_set.size() == 2);
}

TEST_CASE("reference tracer and state graph agree on random octagonal trajectories",
          "[octagonal][property][slow]") {
    // Two readings of one trajectory: stepping with Brent's detector (and
    // the second pass for the tail), and breadth-first search with strong
    // components on the graph of the states reached. Both take their steps
    // from reference_step, so what this checks is the bookkeeping of cycles,
    // tails and counts; the step itself is checked against engines that
    // share nothing with it (the octagonal lattice engine and induction,
    // test_octagonal_lattice.cpp, test_octagonal_induction.cpp).
    std::mt19937_64 rng(14'001);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 25;
    const int cases = test::case_count(5000);
    int hits = 0, escapes = 0, absorbed = 0, cycles = 0, tails = 0;
    SolveOptions reference;
    reference.engine = Engine::reference;
    reference.max_steps = 100'000;
    for (int i = 0; i < cases; ++i) {
        shape.max_elements = 3 + i % 8;
        const Scene s = test::random_octagonal_scene(rng, shape);
        INFO("case " << i << "\n" << write_scene(s));
        const Answer a = solve(s, reference);
        const std::optional<StateGraphReport> g = explore_state_graph(s, 200'000);
        REQUIRE(a.decided());
        REQUIRE(g);
        CHECK(a.reason == g->answer.reason);
        CHECK(a.reflections == g->answer.reflections);
        CHECK(a.tail == g->answer.tail);
        switch (a.reason) {
        case Reason::hit:
            ++hits;
            break;
        case Reason::escape:
            ++escapes;
            break;
        case Reason::absorbed:
            ++absorbed;
            break;
        default:
            ++cycles;
            tails += a.tail > 0;
        }
    }
    // Every outcome is common enough to be exercised.
    CHECK(hits > cases / 10);
    CHECK(escapes > cases / 50);
    CHECK(absorbed > cases / 50);
    CHECK(cycles > cases / 10);
    CHECK(tails > cases / 100);
}

TEST_CASE("branches, reference and graph illumination agree on random octagonal scenes",
          "[octagonal][property][slow]") {
    // Three readings of the illumination question with diagonal splitters:
    // the branch-state search, the reference Dijkstra over every state, and
    // Boost.Graph's BFS and Dijkstra over the explicit graph.
    std::mt19937_64 rng(14'002);
    test::RandomOctagonalShape shape;
    shape.splitter_percent = 30;
    shape.one_sided_percent = 25;
    shape.max_rays = 3;
    shape.max_targets = 3;
    const int cases = test::case_count(5000);
    int compared = 0, lit = 0, unlit = 0;
    SolveOptions reference;
    reference.engine = Engine::reference;
    for (int i = 0; i < cases; ++i) {
        shape.max_elements = 3 + i % 6;
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (s.single_trajectory()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const Answer graph = explore_illumination_graph(s, 100'000);
        REQUIRE(graph.decided());
        const Answer branches = solve(s);
        const Answer by_reference = solve(s, reference);
        REQUIRE(branches.decided());
        REQUIRE(by_reference.decided());
        ++compared;
        CHECK(branches.reason == graph.reason);
        CHECK(by_reference.reason == graph.reason);
        CHECK(branches.reflections == graph.reflections);
        for (std::size_t t = 0; t < s.targets.size(); ++t) {
            const TargetAnswer &b = branches.targets[t], &r = by_reference.targets[t],
                               &g = graph.targets[t];
            CHECK(b.status == g.status);
            CHECK(r.status == g.status);
            if (g.status != Status::lit) {
                ++unlit;
                continue;
            }
            ++lit;
            CHECK(b.reflections == g.reflections);
            CHECK(r.reflections == g.reflections);
            CHECK(b.ray == g.ray);
            CHECK(r.ray == g.ray);
        }
    }
    CHECK(compared > cases / 2);
    CHECK(lit > cases / 2);
    CHECK(unlit > cases / 10);
}

namespace {

using orthoray::test::join;
using orthoray::test::split_lines;

// The first line starting with `keyword` (and a space), with the count
// after its word "reflections" raised by one; "" when there is none.
std::string raise_reflections(std::vector<std::string> lines, const std::string& keyword) {
    for (std::string& line : lines) {
        if (line.rfind(keyword + " ", 0) != 0) continue;
        std::istringstream words(line);
        std::string word, raised;
        while (words >> word) {
            if (!raised.empty()) raised += ' ';
            raised += word;
            if (word != "reflections" || !(words >> word)) continue;
            raised += ' ';
            raised += Integer(Integer(word) + 1).get_str();
        }
        line = raised;
        return join(lines);
    }
    return "";
}

} // namespace

TEST_CASE("certificates of random octagonal scenes verify, tampered ones fail",
          "[octagonal][certificate][property][slow]") {
    // The certificate is written from the engines' event rule, the check is
    // the verifier's own reading of diagonals (certify/acting_rule.cpp): the
    // two must agree on every scene, and a changed count, point or dropped
    // branch must be caught.
    std::mt19937_64 rng(14'003);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 25;
    const int cases = test::case_count(800);
    int single = 0, illumination = 0, tails = 0, moved = 0, dropped = 0;
    for (int i = 0; i < cases; ++i) {
        const bool optics = i % 2 == 1;
        shape.splitter_percent = optics ? 30 : 0;
        shape.max_rays = shape.max_targets = optics ? 3 : 1;
        const Scene s = test::random_octagonal_scene(rng, shape);
        SolveOptions options;
        options.max_steps = 100'000;
        if (s.single_trajectory()) options.engine = Engine::reference;
        for (const auto format : {CertificateFormat::text, CertificateFormat::jsonl}) {
            std::ostringstream out;
            CertificateWriter writer(out, s, format);
            writer.attach(options);
            const Answer a = solve(s, options);
            writer.finish(a);
            REQUIRE(a.decided());
            INFO("case " << i << "\n" << write_scene(s) << "certificate:\n" << out.str());
            const test::Outcome outcome = test::verify(s, out.str());
            INFO("verify said: " << outcome.message);
            REQUIRE(outcome.valid);
            CHECK(outcome.message.find(std::string("valid: ") + to_string(a.reason)) == 0);
            if (format == CertificateFormat::jsonl) continue;

            const std::vector<std::string> lines = split_lines(out.str());
            if (!a.illumination()) {
                ++single;
                tails += a.reason == Reason::cycle && a.tail > 0;
                CHECK_FALSE(test::verify(s, raise_reflections(lines, "reflections")).valid);
                // A reflection point moved along x by 1/7 is not where the
                // ray first meets an element.
                if (lines.size() > 3 && lines[3].rfind("point ", 0) == 0) {
                    std::vector<std::string> shifted = lines;
                    const std::size_t space = lines[3].find(' ', 6);
                    const Rational x = Rational(lines[3].substr(6, space - 6)) + Rational(1, 7);
                    shifted[3] = "point " + to_string(x) + lines[3].substr(space);
                    ++moved;
                    test::expect_invalid(s, join(shifted), "first meets an element");
                }
                continue;
            }
            ++illumination;
            for (std::size_t t = 0; t < a.targets.size(); ++t)
                if (a.targets[t].status == TargetAnswer::Status::lit) {
                    CHECK_FALSE(test::verify(s, raise_reflections(lines, "lit")).valid);
                    break;
                }
            // Every branch line but the rays' starts is needed for closure.
            for (std::size_t k = 0; k < lines.size(); ++k) {
                if (lines[k].rfind("branch ", 0) != 0 ||
                    lines[k].find(" reflections 0") != std::string::npos)
                    continue;
                std::vector<std::string> fewer = lines;
                fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(k));
                ++dropped;
                CHECK_FALSE(test::verify(s, join(fewer)).valid);
                break;
            }
        }
    }
    CHECK(single > cases / 4);
    CHECK(illumination > cases / 4);
    CHECK(tails > 0);
    CHECK(moved > cases / 10);
    CHECK(dropped > cases / 20);
}

TEST_CASE("the verifier reads a diagonal corner as sending the ray back",
          "[octagonal][certificate]") {
    // The diamond's corner (4, 2) joins both slopes: the ray along x comes
    // back. A certificate that turns it up the '/' instead, as a diagonal
    // alone would, and lets it escape, is refused; the true one passes.
    const Scene s = read_scene("dim 2\nmirror \\ 0 2 2 0\nmirror / 2 0 4 2\nmirror / 0 2 2 4\n"
                               "mirror \\ 2 4 4 2\nray 2 2 1 0\ntarget 9 9\n");
    test::expect_invalid(s,
                         "orthoray-certificate 1\ndim 2\npoint 2 2\npoint 4 2\nanswer no\n"
                         "reason escape\nreflections 1\ndirection 0 1\nend\n",
                         "meets an element at (0, 2)");
    test::expect_valid(s,
                       "orthoray-certificate 1\ndim 2\npoint 2 2\npoint 4 2\npoint 0 2\n"
                       "point 4 2\npoint 0 2\npoint 4 2\nanswer no\nreason cycle\n"
                       "reflections 2\nstate 4 2 -1 0\nperiod 2\ntail 0\nend\n",
                       "valid: cycle, 2 reflections");
    // Without its tail line a diagonal scene's cycle is refused: diagonals
    // can merge states, so the tail is not known to be 0.
    test::expect_invalid(s,
                         "orthoray-certificate 1\ndim 2\npoint 2 2\npoint 4 2\npoint 0 2\n"
                         "point 4 2\npoint 0 2\npoint 4 2\nanswer no\nreason cycle\n"
                         "reflections 2\nstate 4 2 -1 0\nperiod 2\nend\n",
                         "needs its 'tail' line");
}
