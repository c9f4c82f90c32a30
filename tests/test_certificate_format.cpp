// The certificate writer's text is exactly the format docs/certificates.md
// documents, line for line, and hand-made certificates are accepted when
// true and rejected at a wrong step.
#include "support/certificate_outcome.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace {

using orthoray::Engine;
using orthoray::Scene;
using orthoray::SolveOptions;
using orthoray::test::Certified;
using orthoray::test::certify;
using orthoray::test::expect_rejected;
using orthoray::test::Outcome;
using orthoray::test::verify;

// Solves `scene_text` with both simulation engines and compares the whole
// certificate text with `expected`; it must also verify as `valid`.
void expect_certificate(const char* scene_text, const std::string& expected,
                        std::optional<std::uint64_t> max_steps = std::nullopt) {
    const Scene scene = orthoray::read_scene(scene_text, "<format>");
    for (Engine engine : {Engine::lattice, Engine::reference}) {
        INFO("engine " << (engine == Engine::lattice ? "lattice" : "reference"));
        SolveOptions options;
        options.engine = engine;
        options.max_steps = max_steps;
        const Certified c = certify(scene, options);
        CHECK(c.text == expected);
        const Outcome outcome = verify(scene, c.text);
        INFO("verify said: " << outcome.message);
        if (max_steps) {
            CHECK(outcome.message.starts_with("partial"));
            CHECK_FALSE(outcome.valid);
        } else {
            CHECK(outcome.valid);
        }
    }
}

} // namespace

TEST_CASE("the writer's text is exactly the documented format", "[certificate]") {
    // From (0,0) (on mirror x=0: nothing at t=0) along (3,1): p1 = (3,1) on
    // x=3, v -> (-3,1); p2 = (0,2) on x=0, v -> (3,1); the target (1,7/3) =
    // p2 + (1/3)(3,1) is on the segment after p2: yes after 2.
    const char* hit = R"(dim 2
mirror x 3 y 0 5
mirror x 0 y 0 5
ray 0 0 3 1
target 1 7/3
)";
    SECTION("hit") {
        expect_certificate(hit, "orthoray-certificate 1\n"
                                "dim 2\n"
                                "point 0 0\n"
                                "point 3 1\n"
                                "point 0 2\n"
                                "answer yes\n"
                                "reason hit\n"
                                "reflections 2\n"
                                "target 1 7/3\n"
                                "end\n");
    }
    SECTION("limit") {
        // Stopped after 1 reflection: p0, p1 and `partial`.
        expect_certificate(hit,
                           "orthoray-certificate 1\n"
                           "dim 2\n"
                           "point 0 0\n"
                           "point 3 1\n"
                           "answer unknown\n"
                           "reason limit\n"
                           "reflections 1\n"
                           "partial\n"
                           "end\n",
                           1);
    }
    SECTION("escape") {
        // p1 = (3,1), v -> (-3,1); nothing else: escape after 1, with the
        // final direction as the ray travels it (not normalised).
        expect_certificate(R"(dim 2
mirror x 3 y 0 5
ray 0 0 3 1
target 9 9
)",
                           "orthoray-certificate 1\n"
                           "dim 2\n"
                           "point 0 0\n"
                           "point 3 1\n"
                           "answer no\n"
                           "reason escape\n"
                           "reflections 1\n"
                           "direction -3 1\n"
                           "end\n");
    }
    SECTION("absorbed") {
        // From (0,1/2) along (1,0) the absorber x=2 is met at (2,1/2): the
        // absorption point is listed, and reflections = points - 2 = 0.
        expect_certificate(R"(dim 2
absorber x 2 y 0 4
ray 0 1/2 1 0
target 5 5
)",
                           "orthoray-certificate 1\n"
                           "dim 2\n"
                           "point 0 1/2\n"
                           "point 2 1/2\n"
                           "answer no\n"
                           "reason absorbed\n"
                           "reflections 0\n"
                           "end\n");
    }
    SECTION("cycle") {
        // From (1,0) along (1,0): p1 = (3,0), v -> (-1,0); p2 = (0,0),
        // v -> (1,0); p3 = (3,0) = p1 with v = (-1,0) = v1: period 2.
        expect_certificate(R"(dim 2
mirror x 0 y -1 1
mirror x 3 y -1 1
ray 1 0 1 0
target 1 1
)",
                           "orthoray-certificate 1\n"
                           "dim 2\n"
                           "point 1 0\n"
                           "point 3 0\n"
                           "point 0 0\n"
                           "point 3 0\n"
                           "answer no\n"
                           "reason cycle\n"
                           "reflections 2\n"
                           "state 3 0 -1 0\n"
                           "period 2\n"
                           "end\n");
    }
    SECTION("3D cycle with fractions") {
        // Unit cube faces x=0, x=1, y=0, y=1 (z in [0,1]); the ray keeps
        // z = 1/2 and moves along (1,1,0) from (1/2,0,1/2) (on the floor-side
        // wall y=0, nothing at t=0): p1 = (1,1/2,1/2) on x=1, v -> (-1,1,0);
        // p2 = (1/2,1,1/2) on y=1, v -> (-1,-1,0); p3 = (0,1/2,1/2) on x=0,
        // v -> (1,-1,0); p4 = (1/2,0,1/2) on y=0, v -> (1,1,0); p5 = p1 with
        // v = (-1,1,0) = v1: period 4. The target (0,0,1/2) is on none.
        expect_certificate(R"(dim 3
mirror x 0 y 0 1 z 0 1
mirror x 1 y 0 1 z 0 1
mirror y 0 x 0 1 z 0 1
mirror y 1 x 0 1 z 0 1
ray 1/2 0 1/2 1 1 0
target 0 0 1/2
)",
                           "orthoray-certificate 1\n"
                           "dim 3\n"
                           "point 1/2 0 1/2\n"
                           "point 1 1/2 1/2\n"
                           "point 1/2 1 1/2\n"
                           "point 0 1/2 1/2\n"
                           "point 1/2 0 1/2\n"
                           "point 1 1/2 1/2\n"
                           "answer no\n"
                           "reason cycle\n"
                           "reflections 4\n"
                           "state 1 1/2 1/2 -1 1 0\n"
                           "period 4\n"
                           "end\n");
    }
}

TEST_CASE("hand-made certificates: the verifier accepts the truth and rejects a wrong step",
          "[certificate]") {
    const Scene scene = orthoray::read_scene(R"(dim 2
mirror x 3 y 0 5
mirror x 0 y 0 5
ray 0 0 3 1
target 1 7/3
)",
                                             "<hand>");
    // Decimals and non-canonical fractions in the certificate are the same
    // numbers.
    CHECK(verify(scene, "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 3.0 2/2\npoint 0 "
                        "4/2\nanswer yes\nreason hit\nreflections 2\ntarget 1 14/6\nend\n")
              .valid);
    // The target is on the segment p1 p2? No: it is after p2. Claiming it
    // after p1 (dropping p2, 1 reflection) must fail.
    expect_rejected(scene,
                    "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 3 1\nanswer yes\nreason "
                    "hit\nreflections 1\ntarget 1 7/3\nend\n",
                    "hit claimed one segment early");
    // Claiming it one segment late (listing p3 = (3,3)) must fail: the target
    // lies on an earlier listed segment.
    expect_rejected(scene,
                    "orthoray-certificate 1\ndim 2\npoint 0 0\npoint 3 1\npoint 0 2\npoint 3 "
                    "3\nanswer yes\nreason hit\nreflections 3\ntarget 1 7/3\nend\n",
                    "hit claimed one segment late");
    // A wrong header or dim is malformed input.
    CHECK(verify(scene, "orthoray-certificate 2\ndim 2\npoint 0 0\nanswer yes\nreason "
                        "hit\nreflections 0\ntarget 1 7/3\nend\n")
              .input_error);
    CHECK(verify(scene, "orthoray-certificate 1\ndim 3\npoint 0 0 0\nanswer yes\nreason "
                        "hit\nreflections 0\ntarget 1 7/3 0\nend\n")
              .input_error);
    // A point with the wrong number of coordinates is malformed.
    CHECK(verify(scene, "orthoray-certificate 1\ndim 2\npoint 0 0 0\npoint 3 1\npoint 0 "
                        "2\nanswer yes\nreason hit\nreflections 2\ntarget 1 7/3\nend\n")
              .input_error);
}
