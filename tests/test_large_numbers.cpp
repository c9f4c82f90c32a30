// Numbers of any size (docs/lattice.md): coordinates of 10^30 and fractions
// with 200-digit numerators and denominators, in 2D and 3D, mixed with tiny
// values, give exactly the answers of the same scenes in small numbers; and
// the choice of machine integers is right on both sides of its boundary.
#include "orthoray/certificate.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace orthoray;

// A 200-digit number: the first 200 digits of 1234567890 repeated, plus `k`.
Integer digits200(int k) {
    std::string text;
    while (text.size() < 200) text += "1234567890";
    return Integer(text) + k;
}

// The scene under x_j -> scale[j] * x_j + shift[j] (every scale > 0). An
// axis-wise positive affine map keeps every element axis-aligned, keeps the
// order of points along a line and commutes with negating a direction
// component, so the answer and the reflection count do not change.
Scene transformed(const Scene& s, const std::vector<Rational>& scale,
                  const std::vector<Rational>& shift) {
    Scene out = s;
    auto map = [&](Vector& x) {
        for (int j = 0; j < s.dim; ++j) x[j] = scale[j] * x[j] + shift[j];
    };
    for (Element& e : out.elements) {
        map(e.lo);
        map(e.hi);
    }
    map(out.ray().start);
    map(out.target());
    for (int j = 0; j < s.dim; ++j) out.ray().direction[j] = scale[j] * s.ray().direction[j];
    return out;
}

struct Solved {
    Answer answer;
    std::string certificate;
};

Solved solve_certified(const Scene& scene, SolveOptions options) {
    std::ostringstream text;
    CertificateWriter writer(text, scene);
    writer.attach(options);
    Solved s{solve(scene, options), ""};
    writer.finish(s.answer);
    s.certificate = text.str();
    return s;
}

// The curated instances of a dimension, which are small and answer fast.
std::vector<Scene> instances(int dim) {
    std::vector<Scene> scenes;
    const std::filesystem::path root =
        std::filesystem::path(ORTHORAY_SOURCE_DIR) / "instances" / (std::to_string(dim) + "d");
    for (const auto& entry : std::filesystem::directory_iterator(root))
        if (entry.path().extension() == ".scene")
            scenes.push_back(load_scene(entry.path().string()));
    return scenes;
}

void check_same_answer(const Scene& small, const Scene& big) {
    SolveOptions capped;
    capped.max_steps = 20000;
    const Answer expected = solve(small, capped);
    const Solved got = solve_certified(big, capped);
    CHECK(got.answer.reason == expected.reason);
    CHECK(got.answer.reflections == expected.reflections);
    CHECK(got.answer.arithmetic != ArithmeticUsed::int64); // the magnitudes are 2^99 and more
    std::istringstream in(got.certificate);
    const Verdict verdict = verify_certificate(big, in);
    CHECK(verdict.valid == expected.decided());
    if (expected.decided()) {
        SolveOptions reference = capped;
        reference.engine = Engine::reference;
        const Answer traced = solve(big, reference);
        CHECK(traced.reason == expected.reason);
        CHECK(traced.reflections == expected.reflections);
    }
}

} // namespace

TEST_CASE("coordinates of 10^30 and 200-digit fractions give the small scene's answer",
          "[numbers]") {
    const Integer e30 = Integer("1000000000000000000000000000000");
    const Rational huge_fraction(digits200(7), digits200(-3)); // about 1, 200 digits each
    const Rational tiny(1, digits200(1));                      // about 10^-200
    for (const int dim : {2, 3}) {
        for (const Scene& small : instances(dim)) {
            CAPTURE(dim, write_scene(small));
            // Huge scale, huge shift; 200-digit fractions; tiny and huge mixed
            // on different axes; a tiny scale shifted far away.
            const std::vector<std::vector<Rational>> scales = {
                {Rational(e30), Rational(e30), Rational(e30)},
                {huge_fraction, huge_fraction * 3, huge_fraction / 7},
                {tiny, Rational(e30), tiny * huge_fraction},
                {tiny, tiny, tiny},
            };
            const std::vector<std::vector<Rational>> shifts = {
                {Rational(e30), Rational(-e30), Rational(0)},
                {Rational(digits200(1), digits200(2)), huge_fraction, Rational(1, 3)},
                {Rational(-e30 * e30), tiny, Rational(e30)},
                {Rational(e30 * 7), Rational(-e30, 3), tiny},
            };
            for (std::size_t k = 0; k < scales.size(); ++k) {
                CAPTURE(k);
                check_same_answer(small, transformed(small, scales[k], shifts[k]));
            }
        }
    }
}

TEST_CASE("huge mirror boxes answer after few reflections", "[numbers]") {
    const Integer e30 = Integer("1000000000000000000000000000000");
    // The 3 x 5 and 3 x 5 x 7 boxes blown up by 10^30 keep their closed-form
    // answers (the ray from a corner at 45 degrees reaches a corner).
    for (const std::vector<Integer>& sides :
         {std::vector<Integer>{3 * e30, 5 * e30}, std::vector<Integer>{3 * e30, 5 * e30, 7 * e30},
          std::vector<Integer>{e30 * e30, e30 * e30}}) {
        BoxFamily family;
        family.sides = sides;
        const GeneratedScene generated = generate_box(family);
        REQUIRE(generated.expect);
        const Solved got = solve_certified(generated.scene, {});
        CHECK(got.answer.reason == generated.expect->reason);
        CHECK(got.answer.reflections == generated.expect->reflections);
        CHECK(got.answer.reflections < 100);
        std::istringstream in(got.certificate);
        CHECK(verify_certificate(generated.scene, in).valid);
    }
}

TEST_CASE("the machine-integer choice is right just below and above each limit", "[numbers]") {
    // The box [c, c + 3] x [c, c + 5] (x [c, c + 7]) has lattice magnitude
    // c + 5 (c + 7) at scale 1; c puts it one below or at each limit.
    struct Case {
        Integer magnitude;
        ArithmeticUsed arithmetic;
    };
    const Integer limit64 = lattice::int64_limit(), limit128 = lattice::int128_limit();
    const std::vector<Case> cases = {
        {limit64 - 1, ArithmeticUsed::int64},
        {limit64, ArithmeticUsed::int128},
        {limit64 + 1, ArithmeticUsed::int128},
        {Integer(1) << 63, ArithmeticUsed::int128}, // past what int64_t holds at all
        {limit128 - 1, ArithmeticUsed::int128},
        {limit128, ArithmeticUsed::gmp},
        {Integer(1) << 127, ArithmeticUsed::gmp},
    };
    for (const int dim : {2, 3}) {
        for (const bool negative : {false, true}) {
            for (const Case& c : cases) {
                const Integer largest = dim == 2 ? Integer(5) : Integer(7);
                BoxFamily family;
                family.sides =
                    dim == 2 ? std::vector<Integer>{3, 5} : std::vector<Integer>{3, 5, 7};
                const GeneratedScene small = generate_box(family);
                // Shifted so that the largest |coordinate| is the magnitude:
                // up by magnitude - largest, or down past zero.
                const Rational shift =
                    negative ? Rational(-c.magnitude) : Rational(c.magnitude - largest);
                const Scene big = transformed(small.scene, {1, 1, 1}, {shift, shift, shift});
                CAPTURE(dim, negative, c.magnitude.get_str(), to_string(c.arithmetic));
                REQUIRE(lattice::make_lattice(big).magnitude == c.magnitude);
                const Solved got = solve_certified(big, {});
                CHECK(got.answer.arithmetic == c.arithmetic);
                CHECK(got.answer.reason == small.expect->reason);
                CHECK(got.answer.reflections == small.expect->reflections);
                std::istringstream in(got.certificate);
                CHECK(verify_certificate(big, in).valid);
            }
        }
    }
}

TEST_CASE("long runs at the int64 boundary step exactly like GMP", "[numbers]") {
    // Coprime cuboids with largest side 2^k + 1, on both sides of 2^59: the
    // first 3000 reflections, point by point, equal those computed in GMP.
    for (const unsigned k : {57u, 58u, 59u}) {
        const Scene scene = generate_coprime_cuboid(k, BoxFamily::Target::far).scene;
        SolveOptions narrow;
        narrow.max_steps = 3000;
        SolveOptions wide = narrow;
        wide.arithmetic = Arithmetic::wide;
        const Solved a = solve_certified(scene, narrow), b = solve_certified(scene, wide);
        CAPTURE(k, to_string(a.answer.arithmetic));
        CHECK(a.answer.arithmetic == (k < 59 ? ArithmeticUsed::int64 : ArithmeticUsed::int128));
        CHECK(b.answer.arithmetic == ArithmeticUsed::gmp);
        CHECK(a.answer.reflections == 3000);
        CHECK(a.certificate == b.certificate);
    }
}
