// Certificates of optics scenes (docs/certificates.md; the agreed format is
// docs of the one-sided rho cycle and the illumination question): hand-made
// certificates of small scenes, derived below in the comments, verify; and
// each tampered copy is rejected for the reason it was tampered for, which
// the message must name. The writer is not used here: these literals are
// the verifier's own specification.
#include "support/case_count.hpp"
#include "support/certificate_lines.hpp"
#include "support/certificate_outcome.hpp"
#include "support/portable_random.hpp"

#include "orthoray/parse.hpp"

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using orthoray::Scene;
namespace test = orthoray::test;
using orthoray::test::expect_invalid;
using orthoray::test::expect_valid;
using orthoray::test::Outcome;
using orthoray::test::replaced;
using orthoray::test::verify;

Scene scene_of(const std::string& text) {
    return orthoray::read_scene(text, "<scene>");
}

// Malformed: one located message, exactly `message`.
void expect_malformed(const Scene& scene, const std::string& text, const std::string& message) {
    const Outcome outcome = verify(scene, text);
    INFO("certificate:\n" << text);
    CHECK(outcome.input_error);
    CHECK(outcome.message == message);
}

// Two-sided mirrors at x = 0 and x = 10 and a one-way mirror x+ 5, which
// acts only on rays moving toward -x. From (2,3) along (-1,0):
//   s1 = (0,3) (1,0)    the one-way mirror is behind the start
//   s2 = (10,3) (-1,0)  passing x = 5 from its back: no event
//   s3 = (5,3) (1,0)    its front
//   s4 = (10,3) (-1,0) = s2
// So the cycle starts at s2: tail 1, period 2, reflections 3, and s1 is not
// on the cycle (s1 != s3).
const std::string rho_scene = "dim 2\nmirror x 0 y 0 10\nmirror x 10 y 0 10\n"
                              "mirror x+ 5 y 0 10\nray 2 3 -1 0\ntarget 100 100\n";
const std::string rho_cert = "orthoray-certificate 1\ndim 2\n"
                             "point 2 3\npoint 0 3\npoint 10 3\npoint 5 3\npoint 10 3\n"
                             "answer no\nreason cycle\nreflections 3\n"
                             "state 10 3 -1 0\nperiod 2\ntail 1\nend\n";

// A splitter at x = 2 on the ray's line. The start state's stretch ends
// there at once (w = 0): through, (2,0) (1,0) with label <= (0, 1);
// reflected, (2,0) (-1,0) with label <= (1, 1). Both then escape, passing
// (5,0) and (-3,0) respectively.
const std::string split_scene =
    "dim 2\nsplitter x 2 y -1 1\nray 0 0 1 0\ntarget 5 0\ntarget -3 0\n";
const std::string split_cert = "orthoray-certificate 1\ndim 2\nillumination\n"
                               "branch 0 0 1 0 ray 1 reflections 0\n"
                               "branch 2 0 1 0 ray 1 reflections 0\n"
                               "branch 2 0 -1 0 ray 1 reflections 1\n"
                               "lit 1 reflections 0 ray 1\nstep 0 0 1 0\nstep 2 0 1 0\n"
                               "lit 2 reflections 1 ray 1\nstep 0 0 1 0\nstep 2 0 -1 0\n"
                               "answer yes\nreason lit\nreflections 1\nstates 3\nend\n";

// Ray 1 runs along y = 1 between mirrors x = 0 and x = 4 through a splitter
// at x = 2; ray 2 bounces for ever between mirrors x = 10 and x = 12.
//   A (1,1) (1,0) (0,1): to the splitter, w = 0: B = (2,1) (1,0) <= (0,1),
//     C = (2,1) (-1,0) <= (1,1).
//   B: (4,1) reflects (w = 1), back to the splitter from the right:
//     (2,1) (-1,0) <= (1,1) = C's label, (2,1) (1,0) <= (2,1).
//   C: (0,1) reflects (w = 1), back to the splitter from the left:
//     (2,1) (1,0) <= (2,1), (2,1) (-1,0) <= (3,1).
//   D (11,1) (1,0) (0,2): (12,1), (10,1), (12,1), ... a cycle with no
//     splitter, which Brent's method closes; it passes (21/2, 1) after
//     w = 1, on the way from (12,1) to (10,1).
// Target 1 (1,3) is on no stretch: unlit. Target 2 (3,1) is first passed
// by B at w = 0: (0, 1). Target 3 by D: (1, 2).
const std::string closed_scene = "dim 2\nmirror x 0 y 0 2\nmirror x 4 y 0 2\n"
                                 "splitter x 2 y 0 2\nmirror x 10 y 0 2\nmirror x 12 y 0 2\n"
                                 "ray 1 1 1 0\nray 11 1 1 0\n"
                                 "target 1 3\ntarget 3 1\ntarget 21/2 1\n";
const std::string closed_cert = "orthoray-certificate 1\ndim 2\nillumination\n"
                                "branch 1 1 1 0 ray 1 reflections 0\n"
                                "branch 2 1 1 0 ray 1 reflections 0\n"
                                "branch 2 1 -1 0 ray 1 reflections 1\n"
                                "branch 11 1 1 0 ray 2 reflections 0\n"
                                "unlit 1\n"
                                "lit 2 reflections 0 ray 1\nstep 1 1 1 0\nstep 2 1 1 0\n"
                                "lit 3 reflections 1 ray 2\nstep 11 1 1 0\nstep 12 1 -1 0\n"
                                "answer no\nreason unlit\nreflections 1\nstates 4\nend\n";

// A mirror along y = 1. Ray 1 from (0,0) along (1,1) reflects at (1,1) and
// passes (2,0) on its way down; ray 2 from (4,0) along (-1,1) reflects at
// (3,1) and passes (2,0) too: both after one reflection, so ray 1 wins.
const std::string tie_scene = "dim 2\nmirror y 1 x -10 10\nray 0 0 1 1\nray 4 0 -1 1\n"
                              "target 2 0\n";
const std::string tie_cert = "orthoray-certificate 1\ndim 2\nillumination\n"
                             "branch 0 0 1 1 ray 1 reflections 0\n"
                             "branch 4 0 -1 1 ray 2 reflections 0\n"
                             "lit 1 reflections 1 ray 1\nstep 0 0 1 1\nstep 1 1 1 -1\n"
                             "answer yes\nreason lit\nreflections 1\nstates 2\nend\n";

// A one-way mirror x+ 5 and a mirror x = 0 (y in [2, 4]). Ray 1 from (0,1)
// along +x sees the one-way mirror's back: no event, it escapes through
// (9,1). Ray 2 from (8,3) along -x meets its front at (5,3), reflects and
// escapes through (9,3): one reflection.
const std::string sided_scene = "dim 2\nmirror x+ 5 y 0 10\nmirror x 0 y 2 4\n"
                                "ray 0 1 1 0\nray 8 3 -1 0\ntarget 9 1\ntarget 9 3\n";
const std::string sided_cert = "orthoray-certificate 1\ndim 2\nillumination\n"
                               "branch 0 1 1 0 ray 1 reflections 0\n"
                               "branch 8 3 -1 0 ray 2 reflections 0\n"
                               "lit 1 reflections 0 ray 1\nstep 0 1 1 0\n"
                               "lit 2 reflections 1 ray 2\nstep 8 3 -1 0\nstep 5 3 1 0\n"
                               "answer yes\nreason lit\nreflections 1\nstates 2\nend\n";

} // namespace

TEST_CASE("a one-way mirror's rho cycle: tail, period and sides", "[certificate][optics]") {
    const Scene scene = scene_of(rho_scene);
    expect_valid(scene, rho_cert, "valid: cycle, 3 reflections");
    // The same in JSON Lines, the tail in the verdict object.
    expect_valid(scene,
                 "{\"orthoray-certificate\": 1, \"dim\": 2}\n{\"point\": [\"2\", \"3\"]}\n"
                 "{\"point\": [\"0\", \"3\"]}\n{\"point\": [\"10\", \"3\"]}\n"
                 "{\"point\": [\"5\", \"3\"]}\n{\"point\": [\"10\", \"3\"]}\n"
                 "{\"answer\": \"no\", \"reason\": \"cycle\", \"reflections\": \"3\", "
                 "\"state\": {\"point\": [\"10\", \"3\"], \"direction\": [\"-1\", \"0\"]}, "
                 "\"period\": \"2\", \"tail\": \"1\"}\n{\"end\": true}\n",
                 "valid: cycle, 3 reflections");
    // Brent's detector lists a few more points: still valid.
    expect_valid(scene, replaced(rho_cert, "answer", "point 5 3\npoint 10 3\nanswer"),
                 "valid: cycle, 3 reflections");

    // A changed tail, told consistently (state s3, reflections 4, points
    // to p5): s2 = s4, so the state before s3 is already on the cycle.
    std::string longer = replaced(rho_cert, "tail 1", "tail 2");
    longer = replaced(longer, "state 10 3 -1 0", "state 5 3 1 0");
    longer = replaced(longer, "reflections 3", "reflections 4");
    longer = replaced(longer, "answer", "point 5 3\nanswer");
    expect_invalid(scene, longer,
                   "tail 2, but the state at point 2 returns at point 4: it is on the cycle");
    // Tail 0 with s1 as the state: s1 never returns.
    std::string shorter = replaced(rho_cert, "tail 1", "tail 0");
    shorter = replaced(shorter, "state 10 3 -1 0", "state 0 3 1 0");
    shorter = replaced(shorter, "reflections 3", "reflections 2");
    expect_invalid(scene, shorter,
                   "period 2, but the state at point 3 is not the state at point 1");
    // Only the tail line changed: s2 is not the state at point 1.
    expect_invalid(scene, replaced(rho_cert, "tail 1", "tail 0"),
                   "state (10, 3) (-1, 0) is not the state at point 1");
    // A changed period (4 = twice the least), with points and reflections
    // to match.
    std::string doubled = replaced(rho_cert, "period 2", "period 4");
    doubled = replaced(doubled, "reflections 3", "reflections 5");
    doubled = replaced(doubled, "answer", "point 5 3\npoint 10 3\nanswer");
    expect_invalid(scene, doubled, "period 4, but the state at point 2 returns at point 4");
    // Period 1 from s3, a state first met at point 3, not at tail + 1 = 2:
    // the states between must be checked against it too.
    std::string late = replaced(rho_cert, "period 2", "period 1");
    late = replaced(late, "state 10 3 -1 0", "state 5 3 1 0");
    late = replaced(late, "reflections 3", "reflections 2");
    late = replaced(late, "point 5 3\npoint 10 3\n", "point 5 3\n");
    expect_invalid(scene, late, "state (5, 3) (1, 0) is not the state at point 2 (tail + 1)");
    // A one-sided scene's cycle must state its tail.
    expect_invalid(scene, replaced(rho_cert, "tail 1\n", ""), "needs its 'tail' line");
    // A wrong side: the path from (10,3) along -x runs through the front of
    // the one-way mirror to x = 0.
    expect_invalid(scene, replaced(rho_cert, "point 5 3", "point 0 3"),
                   "step 3: point 3 is (0, 3), but the ray from point 2 first meets an "
                   "element at (5, 3)");
    // And reflecting at its back (on the way from x = 0 to x = 10).
    expect_invalid(scene, replaced(rho_cert, "point 10 3\npoint 5", "point 5 3\npoint 5"),
                   "step 2: point 2 is (5, 3), but the ray from point 1 first meets an element "
                   "at (10, 3)");
}

TEST_CASE("two-sided path certificates verify as before, tail 0 allowed", "[certificate][optics]") {
    // The unit square from (1/2, 0) along (1, 1): p1 (1, 1/2) v (-1, 1),
    // p2 (1/2, 1), p3 (0, 1/2), p4 (1/2, 0), p5 = p1 with v1: period 4.
    const Scene scene = scene_of("dim 2\nmirror x 0 y 0 1\nmirror x 1 y 0 1\n"
                                 "mirror y 0 x 0 1\nmirror y 1 x 0 1\nray 1/2 0 1 1\n"
                                 "target 0 0\n");
    const std::string cert = "orthoray-certificate 1\ndim 2\npoint 1/2 0\npoint 1 1/2\n"
                             "point 1/2 1\npoint 0 1/2\npoint 1/2 0\npoint 1 1/2\n"
                             "answer no\nreason cycle\nreflections 4\nstate 1 1/2 -1 1\n"
                             "period 4\nend\n";
    expect_valid(scene, cert, "valid: cycle, 4 reflections");
    expect_valid(scene, replaced(cert, "end", "tail 0\nend"), "valid: cycle, 4 reflections");
    // A bijective step map has no tail: a state on the cycle comes before.
    std::string tailed = replaced(cert, "end", "tail 1\nend");
    tailed = replaced(tailed, "state 1 1/2 -1 1", "state 1/2 1 -1 -1");
    tailed = replaced(tailed, "reflections 4", "reflections 5");
    tailed = replaced(tailed, "answer", "point 1/2 1\nanswer");
    expect_invalid(scene, tailed, "tail 1, but the state at point 1 returns at point 5");
}

TEST_CASE("a splitter lights two targets: the certificate and its tamperings",
          "[certificate][optics]") {
    const Scene scene = scene_of(split_scene);
    expect_valid(scene, split_cert, "valid: lit, 1 reflections, 3 states");
    // JSON Lines, with the statements of the format page.
    const std::string jsonl =
        "{\"orthoray-certificate\": 1, \"dim\": 2}\n{\"illumination\": true}\n"
        "{\"branch\": {\"point\": [\"0\",\"0\"], \"direction\": [\"1\",\"0\"], \"ray\": \"1\", "
        "\"reflections\": \"0\"}}\n"
        "{\"branch\": {\"ray\": \"1\", \"reflections\": \"0\", \"point\": [\"2\",\"0\"], "
        "\"direction\": [\"1\",\"0\"]}}\n"
        "{\"branch\": {\"point\": [\"2\",\"0\"], \"direction\": [\"-1\",\"0\"], \"ray\": \"1\", "
        "\"reflections\": \"1\"}}\n"
        "{\"lit\": {\"target\": \"1\", \"reflections\": \"0\", \"ray\": \"1\"}}\n"
        "{\"step\": {\"point\": [\"0\",\"0\"], \"direction\": [\"1\",\"0\"]}}\n"
        "{\"step\": {\"point\": [\"2\",\"0\"], \"direction\": [\"1\",\"0\"]}}\n"
        "{\"lit\": {\"target\": \"2\", \"reflections\": \"1\", \"ray\": \"1\"}}\n"
        "{\"step\": {\"point\": [\"0\",\"0\"], \"direction\": [\"1\",\"0\"]}}\n"
        "{\"step\": {\"point\": [\"2\",\"0\"], \"direction\": [\"-1\",\"0\"]}}\n"
        "{\"answer\": \"yes\", \"reason\": \"lit\", \"reflections\": \"1\", \"states\": \"3\"}\n"
        "{\"end\": true}\n";
    expect_valid(scene, jsonl, "valid: lit, 1 reflections, 3 states");

    // An unlit claim for a lit target (answer and reflections told to match).
    std::string unlit = replaced(
        split_cert, "lit 2 reflections 1 ray 1\nstep 0 0 1 0\nstep 2 0 -1 0\n", "unlit 2\n");
    unlit = replaced(unlit, "answer yes\nreason lit\nreflections 1",
                     "answer no\nreason unlit\nreflections 0");
    expect_invalid(scene, unlit,
                   "target 2 (line 10) is claimed unlit, but the stretch of the branch on line "
                   "6 passes it");
    // The reflected branch dropped (states told to match).
    std::string dropped = replaced(split_cert, "branch 2 0 -1 0 ray 1 reflections 1\n", "");
    dropped = replaced(dropped, "states 3", "states 2");
    expect_invalid(scene, dropped,
                   "the stretch of the branch on line 4 ends at the splitter event (2, 0), but "
                   "its outgoing state (2, 0) (-1, 0) has no branch line");
    // A witness that takes a direction the splitter does not give.
    expect_invalid(scene, replaced(split_cert, "step 2 0 -1 0", "step 2 0 0 1"),
                   "lit target 2 (line 10): step 1 leaves (2, 0) along (0, 1), which the "
                   "elements there do not allow");
    // A witness that leaves the ray's start in another direction, toward a
    // target (0, 5) no branch reaches: it must start as the ray does.
    const Scene aside = scene_of("dim 2\nray 0 0 1 0\ntarget 5 0\ntarget 0 5\n");
    expect_invalid(aside,
                   "orthoray-certificate 1\ndim 2\nillumination\n"
                   "branch 0 0 1 0 ray 1 reflections 0\n"
                   "lit 1 reflections 0 ray 1\nstep 0 0 1 0\n"
                   "lit 2 reflections 0 ray 1\nstep 0 0 0 1\n"
                   "answer yes\nreason lit\nreflections 0\nstates 1\nend\n",
                   "step 0 is (0, 0) (0, 1), not ray 1's start (0, 0) (1, 0)");
    // A witness whose changes of direction are not its K.
    expect_invalid(scene, replaced(split_cert, "lit 2 reflections 1", "lit 2 reflections 0"),
                   "the witness changes direction 1 times, not 0");
    // The verdict's counts.
    expect_invalid(scene, replaced(split_cert, "states 3", "states 4"),
                   "verdict: states 4, but there are 3 branch lines");
    expect_invalid(scene, replaced(split_cert, "reflections 1\nstates", "reflections 2\nstates"),
                   "verdict: reflections 2, but the largest lit target's count is 1");
    expect_invalid(scene, replaced(split_cert, "answer yes", "answer no"),
                   "verdict: answer no, but the target lines give yes");
    // A target left out, and one claimed twice.
    expect_invalid(
        scene, replaced(split_cert, "lit 2 reflections 1 ray 1\nstep 0 0 1 0\nstep 2 0 -1 0\n", ""),
        "target 2 has no lit, unlit or unknown line");
    expect_invalid(scene, replaced(split_cert, "lit 2 reflections 1", "lit 1 reflections 1"),
                   "line 10: target 1 is already claimed on line 7");
    // A missing end: incomplete, never valid.
    const Outcome cut = verify(scene, replaced(split_cert, "end\n", ""));
    CHECK_FALSE(cut.valid);
    CHECK(cut.message == "invalid: incomplete certificate (no 'end' line)");
}

TEST_CASE("an unlit target's closed set, with a cycle for Brent's method",
          "[certificate][optics]") {
    const Scene scene = scene_of(closed_scene);
    expect_valid(scene, closed_cert, "valid: unlit, 1 reflections, 4 states");
    // A dropped branch line.
    std::string dropped = replaced(closed_cert, "branch 2 1 -1 0 ray 1 reflections 1\n", "");
    dropped = replaced(dropped, "states 4", "states 3");
    expect_invalid(scene, dropped,
                   "the stretch of the branch on line 4 ends at the splitter event (2, 1), but "
                   "its outgoing state (2, 1) (-1, 0) has no branch line");
    // A label too high: C is reached from A after 1 reflection.
    expect_invalid(
        scene,
        replaced(closed_cert, "branch 2 1 -1 0 ray 1 reflections 1",
                 "branch 2 1 -1 0 ray 1 reflections 2"),
        "the stretch of the branch on line 4 reaches (2, 1) (-1, 0) with label (1 reflections, "
        "ray 1), less than the label (2 reflections, ray 1) of its branch on line 6");
    // A ray's start state labelled above (0, r).
    expect_invalid(scene,
                   replaced(closed_cert, "branch 11 1 1 0 ray 2 reflections 0",
                            "branch 11 1 1 0 ray 2 reflections 1"),
                   "ray 2's start state (11, 1) (1, 0): the branch on line 7 has label (1 "
                   "reflections, ray 2), more than (0 reflections, ray 2)");
    // A duplicate branch line (states told to match).
    std::string twice =
        replaced(closed_cert, "unlit 1\n", "branch 2 1 1 0 ray 1 reflections 0\nunlit 1\n");
    twice = replaced(twice, "states 4", "states 5");
    expect_invalid(scene, twice,
                   "the branches on line 5 and line 8 name the same state (2, 1) (1, 0)");
    // A lit claim with a K that is not least: a true witness through the
    // mirror at x = 4, passing (3,1) after one reflection, while B passes it
    // after none.
    std::string later =
        replaced(closed_cert, "lit 2 reflections 0 ray 1\nstep 1 1 1 0\nstep 2 1 1 0\n",
                 "lit 2 reflections 1 ray 1\nstep 1 1 1 0\nstep 2 1 1 0\n"
                 "step 4 1 -1 0\n");
    expect_invalid(scene, later,
                   "target 2 (line 9) is claimed lit with (1 reflections, ray 1), but the "
                   "stretch of the branch on line 5 passes it with (0 reflections, ray 1)");
    // The branch lines after a target line are out of order: malformed.
    expect_malformed(
        scene, replaced(closed_cert, "answer no", "branch 1 1 1 0 ray 1 reflections 0\nanswer no"),
        "<test>:15:1: found 'branch', expected 'step', 'lit', 'unlit', 'unknown' or "
        "'answer'");
    // A partial certificate proves its witnesses only.
    const std::string partial = "orthoray-certificate 1\ndim 2\nillumination\n"
                                "branch 1 1 1 0 ray 1 reflections 0\n"
                                "unknown 1\n"
                                "lit 2 reflections 0 ray 1\nstep 1 1 1 0\nstep 2 1 1 0\n"
                                "unknown 3\n"
                                "answer unknown\nreason limit\nreflections 0\nstates 1\n"
                                "partial\nend\n";
    const Outcome outcome = verify(scene, partial);
    CHECK_FALSE(outcome.valid);
    CHECK(outcome.message ==
          "partial certificate: 1 lit targets' witnesses checked, no answer proven");
    expect_invalid(scene, replaced(partial, "step 2 1 1 0", "step 4 1 -1 0"),
                   "step 1 is at (4, 1), but the first acting event from step 0 is at (2, 1)");
    expect_invalid(scene, replaced(partial, "unknown 1", "unlit 1"),
                   "target 1 is claimed unlit, which a partial certificate cannot prove");
    expect_invalid(scene, replaced(closed_cert, "unlit 1", "unknown 1"),
                   "only a partial certificate may leave a target unknown");
}

TEST_CASE("two rays tie: the least-numbered ray is the answer", "[certificate][optics]") {
    const Scene scene = scene_of(tie_scene);
    expect_valid(scene, tie_cert, "valid: lit, 1 reflections, 2 states");
    // Ray 2's true witness, but ray 1 ties with it and comes first.
    expect_invalid(scene,
                   replaced(tie_cert, "lit 1 reflections 1 ray 1\nstep 0 0 1 1\nstep 1 1 1 -1",
                            "lit 1 reflections 1 ray 2\nstep 4 0 -1 1\nstep 3 1 -1 -1"),
                   "target 1 (line 6) is claimed lit with (1 reflections, ray 2), but the "
                   "stretch of the branch on line 4 passes it with (1 reflections, ray 1)");
    // A ray number the scene does not have.
    expect_invalid(scene,
                   replaced(tie_cert, "lit 1 reflections 1 ray 1", "lit 1 reflections 1 ray 3"),
                   "line 6: ray 3, but the scene has 2 rays");
    // A witness that does not start at its ray.
    expect_invalid(scene,
                   replaced(tie_cert, "lit 1 reflections 1 ray 1", "lit 1 reflections 1 ray 2"),
                   "step 0 is (0, 0) (1, 1), not ray 2's start (4, 0) (-1, 1)");
}

TEST_CASE("one-sided elements in an illumination certificate", "[certificate][optics]") {
    const Scene scene = scene_of(sided_scene);
    expect_valid(scene, sided_cert, "valid: lit, 1 reflections, 2 states");
    // A wrong side: ray 2's witness runs through the one-way mirror's front
    // to the mirror at x = 0 and back.
    expect_invalid(scene, replaced(sided_cert, "step 5 3 1 0", "step 0 3 1 0"),
                   "lit target 2 (line 8): step 1 is at (0, 3), but the first acting event "
                   "from step 0 is at (5, 3)");
    // And a reflection at its back: from (0,1) along +x nothing acts.
    std::string back = replaced(sided_cert, "lit 1 reflections 0 ray 1\nstep 0 1 1 0\n",
                                "lit 1 reflections 1 ray 1\nstep 0 1 1 0\nstep 5 1 -1 0\n");
    expect_invalid(scene, back,
                   "lit target 1 (line 6): the ray from step 0 meets no acting element, yet a "
                   "step follows");
}

TEST_CASE("each question has its own certificate form", "[certificate][optics]") {
    // Points for an illumination scene, illumination for a single trajectory.
    expect_invalid(scene_of(split_scene),
                   "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 2 0\nanswer yes\nreason "
                   "hit\nreflections 1\ntarget 5 0\nend\n",
                   "its certificate must answer the illumination question");
    expect_invalid(scene_of("dim 2\nray 0 0 1 0\ntarget 5 0\n"),
                   "orthoray-certificate 1\ndim 2\nillumination\nbranch 0 0 1 0 ray 1 "
                   "reflections 0\nlit 1 reflections 0 ray 1\nstep 0 0 1 0\nanswer yes\nreason "
                   "lit\nreflections 0\nstates 1\nend\n",
                   "its certificate lists the path's points, not illumination");
}

TEST_CASE("malformed illumination statements are located", "[certificate][optics]") {
    const Scene scene = scene_of(split_scene);
    expect_malformed(scene, replaced(split_cert, "branch 0 0 1 0 ray 1", "branch 0 0 1 0 rays 1"),
                     "<test>:4:16: found 'rays', expected 'ray'");
    expect_malformed(scene,
                     replaced(split_cert, "ray 1 reflections 0\nbranch 2 0 1",
                              "ray 1 reflections\nbranch 2 0 1"),
                     "<test>:4:33: found end of line, expected a non-negative integer");
    expect_malformed(scene, replaced(split_cert, "lit 1 reflections 0 ray 1", "lit one"),
                     "<test>:7:5: found 'one', expected a non-negative integer");
    expect_malformed(scene, replaced(split_cert, "step 2 0 1 0", "step 2 0 1"),
                     "<test>:9:11: found end of line, expected a number");
    expect_malformed(scene, replaced(split_cert, "states 3", "states"),
                     "<test>:16:7: found end of line, expected a non-negative integer");
    expect_malformed(scene, replaced(split_cert, "reason lit", "reason hit"),
                     "<test>:14:8: found 'hit', expected lit, unlit or limit");
    expect_malformed(scene, replaced(split_cert, "illumination", "illumination yes"),
                     "<test>:3:14: found 'yes', expected end of line");
    // JSON Lines: an unknown key inside a statement's object.
    expect_malformed(scene,
                     "{\"orthoray-certificate\": 1, \"dim\": 2}\n{\"illumination\": true}\n"
                     "{\"branch\": {\"point\": [\"0\",\"0\"], \"direction\": [\"1\",\"0\"], "
                     "\"rays\": \"1\"}}\n",
                     "<test>:3:57: found the key \"rays\", expected \"point\", \"direction\", "
                     "\"ray\", \"reflections\" or \"intensity\"");
}

TEST_CASE("random mutations of the hand-made certificates never prove a false answer",
          "[certificate][optics][property]") {
    // Each mutation drops, repeats or swaps lines, or moves one number by
    // one. Whatever verify makes of the result, a valid verdict must be the
    // true one (the reason and the count of the original).
    struct Case {
        std::string scene, certificate, truth;
    };
    const Case cases[] = {
        {rho_scene, rho_cert, "valid: cycle, 3 reflections"},
        {split_scene, split_cert, "valid: lit, 1 reflections"},
        {closed_scene, closed_cert, "valid: unlit, 1 reflections"},
        {tie_scene, tie_cert, "valid: lit, 1 reflections"},
        {sided_scene, sided_cert, "valid: lit, 1 reflections"},
    };
    std::mt19937_64 rng(1217);
    int rejected = 0, total = 0;
    for (const Case& c : cases) {
        const Scene scene = scene_of(c.scene);
        std::vector<std::string> lines;
        std::istringstream in(c.certificate);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        const auto last = static_cast<std::int64_t>(lines.size()) - 1;
        for (int i = 0; i < test::case_count(400); ++i) {
            std::vector<std::string> m = lines;
            const auto a = static_cast<std::size_t>(orthoray::uniform(rng, 0, last));
            const auto b = static_cast<std::size_t>(orthoray::uniform(rng, 0, last));
            switch (orthoray::uniform(rng, 0, 3)) {
            case 0:
                m.erase(m.begin() + static_cast<std::ptrdiff_t>(a));
                break;
            case 1:
                m.insert(m.begin() + static_cast<std::ptrdiff_t>(a), m[b]);
                break;
            case 2:
                std::swap(m[a], m[b]);
                break;
            default: { // one number token of line a, moved by +-1
                std::istringstream words(m[a]);
                std::vector<std::string> t;
                for (std::string w; words >> w;) t.push_back(w);
                const auto k = static_cast<std::size_t>(
                    orthoray::uniform(rng, 0, static_cast<std::int64_t>(t.size()) - 1));
                const orthoray::NumberToken n = orthoray::read_number(t[k]);
                if (n.status != orthoray::NumberToken::Status::ok) continue;
                t[k] = orthoray::to_string(n.value + (orthoray::uniform(rng, 0, 1) ? 1 : -1));
                m[a].clear();
                for (const std::string& w : t) m[a].append(m[a].empty() ? "" : " ").append(w);
            }
            }
            std::string text;
            for (const std::string& line : m) text.append(line).append("\n");
            const Outcome outcome = verify(scene, text);
            ++total;
            rejected += !outcome.valid;
            INFO("mutated certificate:\n" << text << "verify said: " << outcome.message);
            if (outcome.valid) CHECK(outcome.message.rfind(c.truth, 0) == 0);
        }
    }
    CHECK(rejected > total / 2);
}
