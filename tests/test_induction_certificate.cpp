// Induction certificates (docs/induction-certificates.md): hand-derived
// certificates for tiny scenes verify, and each tampering is rejected for
// the reason it introduces (the message is matched, so a check that never
// fires fails the test).
#include "support/certificate_outcome.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace {

using orthoray::Integer;
using orthoray::Rational;
using orthoray::Scene;

using orthoray::test::expect_invalid;
using orthoray::test::expect_valid;
using orthoray::test::Outcome;
using orthoray::test::verify;

std::string replace(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    REQUIRE(text.find(from, at + 1) == std::string::npos); // the tampering is unambiguous
    text.replace(at, from.size(), to);
    return text;
}

void expect_malformed(const Scene& scene, const std::string& text, const std::string& reason) {
    const Outcome outcome = verify(scene, text);
    INFO("certificate:\n" << text << "verify said: " << outcome.message);
    CHECK_FALSE(outcome.valid);
    CHECK(outcome.input_error);
    CHECK(outcome.message.find(reason) != std::string::npos);
}

// ------------------------------------------------------------ hallway --
//
// Two mirrors y = 0 and y = 1 for x in [0, 6]; the ray starts at (0, 0)
// along (1, 1). It zigzags (1, 1), (2, 0), (3, 1), (4, 0), (5, 1), (6, 0)
// (the end of y = 0 reflects) and leaves along (1, 1): escape after 6.
//
// Lattice: scale 1 1 (all integral, direction already diagonal). The first
// state x is (1, 1) leaving along (1, -1): w(x) = -1 * 1 - 1 * 1 = -2.
// Reflections on y = 0 leave w alone and on y = 1 change it by +-2, so the
// modulus is 2: the states have even w.
//   transversal 0: the line Y = 1 with direction (1, -1), u = X in [0, 6]:
//     w = -1 - u even, so u = 1, 3, 5; w grows as u falls, so the states are
//     (5, 1), (3, 1), (1, 1): raw 0, 1, 2.
//   transversal 1: the line Y = 0 with direction (1, 1): w = -u even, u = 0,
//     2, 4, 6; in order of w: (6, 0), (4, 0), (2, 0), (0, 0): raw 3 to 6.
// x is state 2 of transversal 0, raw 2, so rotated = (raw - 2) mod 7:
//   (1,1) 0, (6,0) 1, (4,0) 2, (2,0) 3, (0,0) 4, (5,1) 5, (3,1) 6.
// The map: 0 -> 3 -> 6 -> 2 -> 5 -> 1 -> escape, 4 (the start point (0, 0),
// no predecessor) -> 0. The escaping state 1 is sent to the one state
// without a predecessor, 4. Rotated 2, 3 (raw 4, 5: transversal 1) go to 5,
// 6 (raw 0, 1: transversal 0), and 5, 6 to 1, 2: two pieces of length 2.
//
// The induction, (d, i, l, r, event) for each piece, L = 7:
//   P0 (0,3,1,1) P1 (1,4,1,1,escape@0) P2 (2,5,2,1) P3 (4,0,1,1) P4 (5,1,2,1)
//   D = P4 (domain ends at 7), R = P2 (image ends at 7), equal lengths:
//   equal 2 4: P2 (2,1,2,2); L = 5. D = P3, R = P1: equal 1 3: P1
//   (1,0,1,2,escape@0); L = 4. D = P2 (l 2), R = P0 (l 1): top 2 0: P0
//   image 1 + 2 - 1 = 2, r 3; P2 l 1; L = 3. D = P2, R = P0: equal 0 2: P0
//   (0,1,1,5); L = 2. D = P1, R = P0: equal 0 1: P0 gets P1's escape at
//   offset 0 + 5: escape after 6 reflections, as walked above.

Scene hallway() {
    return orthoray::read_scene("dim 2\n"
                                "mirror y 0 x 0 6\n"
                                "mirror y 1 x 0 6\n"
                                "ray 0 0 1 1\n"
                                "target 3 0\n");
}

const std::string hallway_certificate = "orthoray-certificate 1\n"
                                        "dim 2\n"
                                        "point 0 0\n"
                                        "point 1 1\n"
                                        "method induction\n"
                                        "direction 1 -1\n"
                                        "scale 1 1\n"
                                        "modulus 2\n"
                                        "transversal 1 1 0 6 1 -1\n"
                                        "transversal 1 0 0 6 1 1\n"
                                        "first 0 2\n"
                                        "piece 0 1 reflect 3\n"
                                        "piece 1 1 escape 4\n"
                                        "piece 2 2 reflect 5\n"
                                        "piece 4 1 reflect 0\n"
                                        "piece 5 2 reflect 1\n"
                                        "step equal 2 4\n"
                                        "step equal 1 3\n"
                                        "step top 2 0\n"
                                        "step equal 0 2\n"
                                        "step equal 0 1\n"
                                        "answer no\n"
                                        "reason escape\n"
                                        "reflections 6\n"
                                        "end\n";

// The same hallway with the target (5, 1), the fifth reflection point: the
// segments from (4, 0) (rotated 2) and from (5, 1) itself (rotated 5) hold
// it, so both are pieces of their own flagged hit. L = 7:
//   P0 (0,3) P1 (1,4,escape) P2 (2,5,hit) P3 (3,6) P4 (4,0) P5 (5,1,hit) P6 (6,2)
//   equal 3 6: P3 (3,2,r 2); L 6. equal 2 5: P2 (2,1,r 2,hit@0); L 5.
//   equal 1 4: P1 (1,0,r 2,escape@0); L 4. equal 0 3: P0 (0,2,r 3); L 3.
//   equal 0 2: P0 (0,1,r 5,hit@3); L 2. equal 0 1: P0 keeps hit@3; L 1.
// Hit at offset 3: 4 reflections, on the segment (4, 0) to (5, 1).
Scene hallway_hit() {
    Scene s = hallway();
    s.target() = {5, 1, 0};
    return s;
}

const std::string hallway_hit_certificate = "orthoray-certificate 1\n"
                                            "dim 2\n"
                                            "point 0 0\n"
                                            "point 1 1\n"
                                            "method induction\n"
                                            "direction 1 -1\n"
                                            "scale 1 1\n"
                                            "modulus 2\n"
                                            "transversal 1 1 0 6 1 -1\n"
                                            "transversal 1 0 0 6 1 1\n"
                                            "first 0 2\n"
                                            "piece 0 1 reflect 3\n"
                                            "piece 1 1 escape 4\n"
                                            "piece 2 1 reflect 5 hit\n"
                                            "piece 3 1 reflect 6\n"
                                            "piece 4 1 reflect 0\n"
                                            "piece 5 1 reflect 1 hit\n"
                                            "piece 6 1 reflect 2\n"
                                            "step equal 3 6\n"
                                            "step equal 2 5\n"
                                            "step equal 1 4\n"
                                            "step equal 0 3\n"
                                            "step equal 0 2\n"
                                            "step equal 0 1\n"
                                            "answer yes\n"
                                            "reason hit\n"
                                            "reflections 4\n"
                                            "end\n";

// The hallway with an absorber across its open end at x = 7: the ray from
// (6, 0) is absorbed at (7, 1). Same exchange, piece 1 absorbed.
Scene hallway_absorbed() {
    Scene s = hallway();
    s.add_absorber(0, 7, {{0, 1}});
    return s;
}

// ---------------------------------------------------------------- box --
//
// The box [0, 2] x [0, 1] of mirrors, the ray from the corner (0, 0) along
// (1, 1): (1, 1) along (1, -1), the corner (2, 0) (both components negate)
// along (-1, 1), (1, 1) along (-1, -1), the corner (0, 0) along (1, 1), and
// back to (1, 1) along (1, -1): a cycle of period 4. Each of the four
// states is a transversal of one state (w = -2, 2, 0, 0: all even, modulus
// 2), x is raw 0, and the exchange is the rotation 0 -> 1 -> 2 -> 3 -> 0.
// equal 2 3 (L 3), equal 1 2 (L 2), equal 0 1 (L 1): r = 4, no event.

Scene box() {
    return orthoray::read_scene("dim 2\n"
                                "mirror x 0 y 0 1\n"
                                "mirror x 2 y 0 1\n"
                                "mirror y 0 x 0 2\n"
                                "mirror y 1 x 0 2\n"
                                "ray 0 0 1 1\n"
                                "target 1 0\n");
}

const std::string box_certificate = "orthoray-certificate 1\n"
                                    "dim 2\n"
                                    "point 0 0\n"
                                    "point 1 1\n"
                                    "method induction\n"
                                    "direction 1 -1\n"
                                    "scale 1 1\n"
                                    "modulus 2\n"
                                    "transversal 1 1 1 1 1 -1\n"
                                    "transversal 1 0 2 2 -1 1\n"
                                    "transversal 1 1 1 1 -1 -1\n"
                                    "transversal 1 0 0 0 1 1\n"
                                    "first 0 0\n"
                                    "piece 0 1 reflect 1\n"
                                    "piece 1 1 reflect 2\n"
                                    "piece 2 1 reflect 3\n"
                                    "piece 3 1 reflect 0\n"
                                    "step equal 2 3\n"
                                    "step equal 1 2\n"
                                    "step equal 0 1\n"
                                    "answer no\n"
                                    "reason cycle\n"
                                    "reflections 4\n"
                                    "period 4\n"
                                    "end\n";

} // namespace

// ------------------------------------------------------------------ valid --

TEST_CASE("hand-derived induction certificates verify", "[induction-certificate]") {
    expect_valid(hallway(), hallway_certificate, "valid: escape, 6 reflections");
    expect_valid(hallway_hit(), hallway_hit_certificate, "valid: hit, 4 reflections");
    expect_valid(hallway_absorbed(),
                 replace(replace(hallway_certificate, "piece 1 1 escape 4", "piece 1 1 absorbed 4"),
                         "reason escape", "reason absorbed"),
                 "valid: absorbed, 6 reflections");
    expect_valid(box(), box_certificate, "valid: cycle, 4 reflections");
    // A top step is a top-cycle with M = 1 (S = 4 - (1 + 2) = 1 < l_D = 2).
    expect_valid(hallway(), replace(hallway_certificate, "step top 2 0", "step top-cycle 2 1"),
                 "valid: escape, 6 reflections");
    // Comments and blank lines are allowed, as in path certificates.
    expect_valid(hallway(), replace(hallway_certificate, "modulus 2\n", "modulus 2 # G\n\n"),
                 "valid: escape, 6 reflections");
}

TEST_CASE("the same numbers at a scale", "[induction-certificate]") {
    // The hallway with every coordinate halved: scale 2 2 brings it back.
    Scene half = orthoray::read_scene("dim 2\n"
                                      "mirror y 0 x 0 3\n"
                                      "mirror y 1/2 x 0 3\n"
                                      "ray 0 0 1 1\n"
                                      "target 3/2 0\n");
    std::string text = replace(hallway_certificate, "point 1 1\n", "point 1/2 1/2\n");
    text = replace(text, "scale 1 1", "scale 2 2");
    expect_valid(half, text, "valid: escape, 6 reflections");
    // A direction (2, 1) is diagonal at scale 1 2: the same lattice.
    Scene wide = orthoray::read_scene("dim 2\n"
                                      "mirror y 0 x 0 6\n"
                                      "mirror y 1/2 x 0 6\n"
                                      "ray 0 0 2 1\n"
                                      "target 3 0\n");
    text = replace(hallway_certificate, "point 1 1\n", "point 1 1/2\n");
    text = replace(text, "direction 1 -1", "direction 2 -1");
    text = replace(text, "scale 1 1", "scale 1 2");
    expect_valid(wide, text, "valid: escape, 6 reflections");
}

// --------------------------------------------------------------- tampered --

TEST_CASE("tampered induction certificates are rejected for their reason",
          "[induction-certificate]") {
    const Scene h = hallway();
    const std::string& c = hallway_certificate;

    SECTION("header") {
        expect_invalid(h, replace(c, "point 0 0", "point 0 1"), "not the start point");
        expect_invalid(h, replace(c, "point 1 1", "point 2 2"), "first meets an element at (1, 1)");
        expect_invalid(h, replace(c, "direction 1 -1", "direction 1 1"),
                       "is not the direction (1, -1)");
        Scene early = h;
        early.target() = {Rational(1, 2), Rational(1, 2), 0};
        expect_invalid(early, c, "step 1: the target lies on the segment from point 0 to point 1");
    }
    SECTION("path prefix") {
        const std::string two = "point 0 0\npoint 1 1\n";
        expect_valid(h, replace(c, two, two + "point 2 0\npoint 3 1\n"),
                     "valid: escape, 6 reflections");
        expect_invalid(h, replace(c, two, two + "point 2 0\npoint 3 0\n"),
                       "step 3: point 3 is (3, 0), but the ray from point 2 first meets an "
                       "element at (3, 1)");
        expect_invalid(hallway_hit(),
                       replace(hallway_hit_certificate, two,
                               two + "point 2 0\npoint 3 1\npoint 4 0\npoint 5 1\n"),
                       "step 5: the target lies on the segment from point 4 to point 5");
        expect_invalid(hallway_absorbed(),
                       replace(c, two,
                               two + "point 2 0\npoint 3 1\npoint 4 0\npoint 5 1\npoint 6 "
                                     "0\npoint 7 1\n"),
                       "header: the ray is absorbed at point 7 of the path prefix");
        expect_invalid(h, replace(c, two, "point 0 0\n"),
                       "header: the path prefix has only point 0");
    }
    SECTION("scale not integral, direction not diagonal") {
        expect_invalid(h, replace(c, "scale 1 1", "scale 1/2 1/2"), "not an integer");
        expect_invalid(h, replace(c, "scale 1 1", "scale 1 2"), "is not diagonal");
        expect_invalid(h, replace(c, "scale 1 1", "scale -1 -1"), "is not positive");
    }
    SECTION("transversals") {
        // Overlapping ranges on one line with one direction.
        expect_invalid(h, replace(c, "first 0 2", "transversal 1 0 4 6 1 1\nfirst 0 2"),
                       "transversal 2: shares the state u = 4 on its line with transversal 1");
        // A vertical and a horizontal transversal crossing at a common state.
        expect_invalid(box(),
                       replace(box_certificate, "first 0 0", "transversal 0 2 0 0 -1 1\nfirst 0 0"),
                       "transversal 4: shares the state at the lattice point (2, 0) with "
                       "transversal 1");
        expect_invalid(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 0 6 0 1 1"),
                       "LO 6 > HI 0");
        // u = 1 on Y = 0 with direction (1, 1) has w = -1: odd, no state.
        expect_invalid(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 0 1 1 1 1"),
                       "so it has no state");
        // Y = 2 is on no mirror.
        expect_invalid(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 2 0 6 1 1"),
                       "transversal 1: its state at the lattice point (0, 2) is on no mirror");
        expect_invalid(h, replace(c, "first 0 2", "first 0 1"),
                       "is the lattice point (3, 1) with direction (1, -1), not point 1");
        expect_invalid(h, replace(c, "first 0 2", "first 0 3"), "has 3 states, no state 3");
    }
    SECTION("tiling") {
        expect_invalid(h, replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 4"),
                       "images must tile");
        expect_invalid(h, replace(c, "piece 4 1 reflect 0", "piece 4 2 reflect 0"),
                       "piece 4: it starts at 5, but the pieces before it end at 6");
        expect_invalid(h,
                       replace(c, "piece 0 1 reflect 3\npiece 1 1 escape 4", "piece 0 2 reflect 3"),
                       "piece 0: it is [0, 2), not [0, 1)");
    }
    SECTION("a piece's image off by one") {
        // Images 4 for piece 0 and 3 for piece 1 still tile, but x = (1, 1)
        // is not mapped to its next state (2, 0).
        std::string t = replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 4");
        t = replace(t, "piece 1 1 escape 4", "piece 1 1 escape 3");
        expect_invalid(h, t,
                       "piece 0: its state at rotated coordinate 0 (lattice point (1, 1), "
                       "direction (1, -1)) is mapped to the lattice point (0, 0), which is not "
                       "ahead of it on its ray");
        // Images [4, 6) for piece 2: raw 6 and 0, across two transversals.
        t = replace(c, "piece 1 1 escape 4", "piece 1 1 escape 6");
        t = replace(t, "piece 2 2 reflect 5", "piece 2 2 reflect 4");
        expect_invalid(h, t,
                       "piece 2: a reflect piece's image must lie in one transversal, but it "
                       "spans transversals 1 and 0");
        // Swapping the images of pieces 0 and 3: x is mapped to itself.
        t = replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 0");
        t = replace(t, "piece 4 1 reflect 0", "piece 4 1 reflect 3");
        expect_invalid(h, t, "piece 0: its state at rotated coordinate 0");
    }
    SECTION("wrong kind") {
        expect_invalid(h, replace(c, "piece 2 2 reflect 5", "piece 2 2 escape 5"),
                       "piece 2: its state at rotated coordinate 2 (lattice point (4, 0), "
                       "direction (1, 1)) meets the mirror y = 1");
        expect_invalid(h, replace(c, "piece 2 2 reflect 5", "piece 2 2 absorbed 5"),
                       "first meets a mirror and no absorber, yet the piece is absorbed");
        expect_invalid(h, replace(c, "piece 1 1 escape 4", "piece 1 1 absorbed 4"),
                       "piece 1: its state at rotated coordinate 1 (lattice point (6, 0), "
                       "direction (1, 1)) meets no element, yet the piece is absorbed");
        expect_invalid(h, replace(c, "piece 1 1 escape 4", "piece 1 1 reflect 4"),
                       "piece 1: its state at rotated coordinate 1 (lattice point (6, 0), "
                       "direction (1, 1)) is mapped to the lattice point (0, 0)");
        // With the absorber, escape is wrong.
        expect_invalid(hallway_absorbed(), c, "meets the absorber x = 7");
    }
    SECTION("hit flags") {
        const Scene hit = hallway_hit();
        const std::string& ch = hallway_hit_certificate;
        expect_invalid(hit, replace(ch, "piece 2 1 reflect 5 hit", "piece 2 1 reflect 5"),
                       "piece 2: the target lies on the segment from its state at rotated "
                       "coordinate 2 (lattice point (4, 0), direction (1, 1)), but the piece is "
                       "not flagged hit");
        expect_invalid(hit, replace(ch, "piece 3 1 reflect 6", "piece 3 1 reflect 6 hit"),
                       "piece 3: it is flagged hit, but the target is not on the segment from "
                       "its state at rotated coordinate 3");
        // The escape certificate's pieces 2 (two states) flagged hit.
        expect_invalid(h, replace(c, "piece 2 2 reflect 5", "piece 2 2 reflect 5 hit"),
                       "piece 2: it is flagged hit");
    }
    SECTION("geometry fails for one state of a piece") {
        // A mirror x = 3 for y in [0, 1] is met by the state (2, 0) of piece
        // 2 at its claimed next point (3, 1), negating x, but not by (4, 0).
        Scene blocked = h;
        blocked.add_mirror(0, 3, {{0, 1}});
        expect_invalid(blocked, c,
                       "piece 2: its state at rotated coordinate 3 (lattice point (2, 0), "
                       "direction (1, 1)) meets the mirror x = 3");
        // With a gap in y = 1 around x = 3, the state (3, 1) of transversal
        // 0 is on no mirror.
        Scene gap = orthoray::read_scene("dim 2\n"
                                         "mirror y 0 x 0 6\n"
                                         "mirror y 1 x 0 2\n"
                                         "mirror y 1 x 4 6\n"
                                         "ray 0 0 1 1\n"
                                         "target 3 0\n");
        expect_invalid(gap, c,
                       "transversal 0: its state at the lattice point (3, 1) is on no mirror");
    }
    SECTION("steps") {
        expect_invalid(h, replace(c, "step equal 2 4", "step equal 4 2"),
                       "step 1 (step equal 4 2): piece 4's image [1, 3) does not end at L = 7");
        expect_invalid(h, replace(c, "step top 2 0", "step bottom 0 2"),
                       "step 3 (step bottom 0 2): needs l_R > l_D, but l(0) = 1 <= l(2) = 2");
        expect_invalid(h, replace(c, "step top 2 0", "step top-cycle 2 2"),
                       "needs M * S < l_D, but M * S = 2 * 1 = 2 >= l_D = 2");
        expect_invalid(h, replace(c, "step equal 0 1\n", ""), "after the last step L = 2, not 1");
        expect_invalid(h, replace(c, "step equal 0 1\n", "step equal 0 1\nstep invariant 0\n"),
                       "step 6 (step invariant 0): the induction has ended (L = 1)");
        expect_invalid(h, replace(c, "step equal 1 3", "step equal 1 7"), "there is no piece 7");
        expect_invalid(h, replace(c, "step equal 1 3", "step equal 1 4"),
                       "piece 4 was removed earlier");
        expect_invalid(h, replace(c, "step equal 2 4", "step invariant 4"),
                       "piece 4's image [1, 3) does not end at L = 7");
    }
    SECTION("verdict") {
        expect_invalid(h, replace(c, "reflections 6", "reflections 7"),
                       "verdict: reflections 7, but the induction gives 6");
        expect_invalid(h, replace(c, "reason escape", "reason absorbed"),
                       "reason absorbed, but the induction gives escape");
        expect_invalid(h, replace(c, "answer no", "answer yes"),
                       "answer yes does not go with reason escape");
        expect_invalid(box(), replace(box_certificate, "period 4", "period 3"),
                       "period 3, but the induction gives 4");
        expect_invalid(box(), replace(box_certificate, "reflections 4", "reflections 3"),
                       "reflections 3, but the induction gives 4");
    }
    SECTION("a scene with a one-sided element") {
        // One-sided elements give no exchange to induce on
        // (docs/induction-certificates.md): the same hallway with a one-way
        // wall is refused before any of its checks.
        Scene one_way = h;
        one_way.elements[1].side = orthoray::Side::minus;
        expect_invalid(one_way, c,
                       "induction certificates are for scenes without one-sided elements");
    }
    SECTION("partial") {
        // A run stopped by a limit while writing the steps.
        std::string cut = c.substr(0, c.find("step equal 0 2"));
        const Outcome partial =
            verify(h, cut + "answer unknown\nreason limit\nreflections 0\npartial\nend\n");
        CHECK_FALSE(partial.valid);
        CHECK(partial.message ==
              "partial certificate: the exchange and 3 induction steps checked, no answer proven");
        expect_invalid(h,
                       replace(cut, "step top 2 0", "step top 0 2") +
                           "answer unknown\nreason limit\nreflections 0\npartial\nend\n",
                       "step 3 (step top 0 2)");
        expect_invalid(h, cut + "answer no\nreason limit\nreflections 0\npartial\nend\n",
                       "answer no does not go with reason limit");
        expect_malformed(h, cut + "answer unknown\nreason limit\nreflections 0\nend\n",
                         "found 'end', expected 'partial'");
    }
    SECTION("truncated and malformed") {
        expect_invalid(h, replace(c, "end\n", ""), "incomplete certificate");
        expect_invalid(h, c.substr(0, c.find("step equal 0 2")), "incomplete certificate");
        expect_malformed(
            h, replace(c, "piece 1 1 escape 4", "piece 1 1 escaped 4"),
            "<test>:13:11: found 'escaped', expected reflect, escape, absorbed or cut");
        expect_malformed(h, replace(c, "transversal 1 0 0 6 1 1", "transversal 1 0 0 6 1 2"),
                         "<test>:10:23: found '2', expected 1 or -1");
        expect_malformed(h, replace(c, "step top 2 0", "step top 2"),
                         "expected a non-negative integer");
        expect_malformed(h, replace(c, "piece 0 1 reflect 3", "piece 0 1 reflect 3 hot"),
                         "found 'hot', expected 'hit' or end of line");
        expect_malformed(h, replace(c, "method induction", "method magic"),
                         "found 'magic', expected 'induction'");
        expect_malformed(h, replace(c, "reflections 6\n", "reflections 6\nperiod 6\n"),
                         "expected 'end'");
    }
}

// ----------------------------------------------------------------- random --

TEST_CASE("orthoray verify reads induction certificates", "[induction-certificate][cli]") {
    using orthoray::test::quote;
    using orthoray::test::run_cli;
    orthoray::test::TempDir dir;
    const std::string scene = dir.write("hallway.scene", orthoray::write_scene(hallway()));
    const std::string good = dir.write("good.cert", hallway_certificate);
    orthoray::test::CliResult r = run_cli("verify " + quote(scene) + " " + quote(good));
    CHECK(r.status == 0);
    CHECK(r.out == "valid: escape, 6 reflections\n");
    const std::string bad =
        dir.write("bad.cert", replace(hallway_certificate, "reflections 6", "reflections 5"));
    r = run_cli("verify " + quote(scene) + " " + quote(bad));
    CHECK(r.status == 1);
    CHECK(r.out == "invalid: verdict: reflections 5, but the induction gives 6 (x's first event "
                   "is escape at offset 5)\n");
    const std::string malformed =
        dir.write("malformed.cert", replace(hallway_certificate, "step top 2 0", "step top 2 x"));
    r = run_cli("verify " + quote(scene) + " " + quote(malformed));
    CHECK(r.status == 2);
    CHECK(r.err.find("malformed.cert:19:12: found 'x', expected a non-negative integer") !=
          std::string::npos);
}

// ------------------------------------------------------------------ large --
//
// The hallway of length 2m (mirrors y = 0 and y = 1 for x in [0, 2m]) for
// m = 10^30: 2m reflections, then escape. The same derivation as for m = 3
// (N = 2m + 1, x is raw m - 1): rotated 0 is (1, 1), 1 .. m + 1 are (2m, 0),
// (2m - 2, 0), ..., (0, 0), and m + 2 .. 2m are (2m - 1, 1), ..., (3, 1).
// Pieces: [0] -> m, [1] escape -> m + 1, [2, m + 1) -> m + 2, [m + 1] -> 0,
// [m + 2, 2m + 1) -> 1. Steps: equal 2 4 (L m + 2), equal 1 3 (L m + 1),
// then D = piece 2 (length m - 1) beats R = piece 0 (length 1) m - 2 times
// over S = 1: top-cycle 2 (m - 2) leaves piece 0 with r = 1 + 2 (m - 2) and
// L = 3; equal 0 2 (r 2m - 1), equal 0 1: escape at offset 2m - 1.

TEST_CASE("a hallway of length 2 * 10^30", "[induction-certificate]") {
    const Integer m("1000000000000000000000000000000");
    auto n = [](const Integer& v) { return v.get_str(); };
    const Scene scene =
        orthoray::read_scene("dim 2\nmirror y 0 x 0 " + n(2 * m) + "\nmirror y 1 x 0 " + n(2 * m) +
                             "\nray 0 0 1 1\ntarget 3 0\n");
    const std::string text =
        "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 1 1\nmethod induction\n"
        "direction 1 -1\nscale 1 1\nmodulus 2\n"
        "transversal 1 1 0 " +
        n(2 * m) +
        " 1 -1\n"
        "transversal 1 0 0 " +
        n(2 * m) +
        " 1 1\n"
        "first 0 " +
        n(m - 1) +
        "\n"
        "piece 0 1 reflect " +
        n(m) +
        "\n"
        "piece 1 1 escape " +
        n(m + 1) +
        "\n"
        "piece 2 " +
        n(m - 1) + " reflect " + n(m + 2) +
        "\n"
        "piece " +
        n(m + 1) +
        " 1 reflect 0\n"
        "piece " +
        n(m + 2) + " " + n(m - 1) +
        " reflect 1\n"
        "step equal 2 4\nstep equal 1 3\n"
        "step top-cycle 2 " +
        n(m - 2) +
        "\n"
        "step equal 0 2\nstep equal 0 1\n"
        "answer no\nreason escape\nreflections " +
        n(2 * m) + "\nend\n";
    expect_valid(scene, text, "valid: escape, " + n(2 * m) + " reflections");
    expect_invalid(scene, replace(text, "top-cycle 2 " + n(m - 2), "top-cycle 2 " + n(m - 1)),
                   "needs M * S < l_D, but M * S = " + n(m - 1) + " * 1 = " + n(m - 1) +
                       " >= l_D = " + n(m - 1));
    expect_invalid(scene, replace(text, "reflections " + n(2 * m), "reflections " + n(2 * m - 1)),
                   "reflections " + n(2 * m - 1) + ", but the induction gives " + n(2 * m));
    // One state too many in the middle piece: the tiling breaks.
    expect_invalid(scene, replace(text, "piece 2 " + n(m - 1), "piece 2 " + n(m)),
                   "piece 3: it starts at " + n(m + 1) + ", but the pieces before it end at " +
                       n(m + 2));
    // A mirror across the hallway far away is met by one state of piece 2.
    Scene blocked = scene;
    blocked.add_mirror(0, Rational(m + 1), {{0, 1}});
    expect_invalid(blocked, text, "meets the mirror x = " + n(m + 1));
}
