// The lattice engine on 2D scenes with diagonal elements (docs/octagonal.md,
// docs/lattice.md "Diagonal elements"): the lattice's scale, hand-traced
// scenes (a diamond of four diagonals in closed form, a diagonal's end, a
// corner of a diagonal and a wall, a rho cycle through a one-way mirror),
// the shooters that refuse diagonals, and agreement with the reference
// tracer on random octagonal scenes.
#include "engine/reference_step.hpp"
#include "engine/reference_tracer.hpp"
#include "lattice/octagonal_lattice.hpp"
#include "orthoray/bounds.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "shoot/octagonal_bvh.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_octagonal.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

using namespace orthoray;

namespace {

Vector at(const Rational& x, const Rational& y) {
    return {x, y, Rational(0)};
}

// A diamond of four diagonal mirrors with corners (n, 0), (2n, n), (n, 2n),
// (0, n), and a ray along +x at height h inside it.
std::string diamond(const Integer& n, const std::string& h, const std::string& direction = "1 0") {
    std::ostringstream s;
    s << "dim 2\nmirror \\ 0 " << n << ' ' << n << " 0\nmirror / " << n << " 0 " << 2 * n << ' '
      << n << "\nmirror \\ " << n << ' ' << 2 * n << ' ' << 2 * n << ' ' << n << "\nmirror / 0 "
      << n << ' ' << n << ' ' << 2 * n << "\nray " << n << ' ' << h << ' ' << direction
      << "\ntarget -7 -7\n";
    return s.str();
}

Answer lattice_solve(const Scene& scene, PathSink* path = nullptr) {
    SolveOptions options;
    options.path = path;
    return solve(scene, options);
}

} // namespace

TEST_CASE("octagonal lattice: one scale for both axes, N from a, b, a - b and a + b",
          "[octagonal][lattice]") {
    // u = (1, 2): N = lcm(1, 2, 1, 3) = 6; denominators 2 (start) and 3.
    Scene s = read_scene("dim 2\nmirror / 0 0 1/3 1/3\nray 1/2 0 1 2\ntarget 0 0\n");
    const lattice::OctagonalLattice l = lattice::make_octagonal_lattice(s);
    CHECK(l.scale == 36);
    CHECK(l.distinct_directions == 8);
    CHECK(l.start[0] == 18);
    CHECK(l.w[5] == std::array<Integer, 2>{-2, 1}); // swapped, then x negated
    CHECK(l.direction(5) == at(-2, 1));
    // u = (1, 1): N = lcm(1, 1, 2) = 2, four distinct directions.
    s = read_scene("dim 2\nmirror \\ 0 1 1 0\nray 0 0 -3 -3\ntarget 0 0\n");
    const lattice::OctagonalLattice d = lattice::make_octagonal_lattice(s);
    CHECK(d.scale == 2);
    CHECK(d.distinct_directions == 4);
    CHECK(d.canonical[4] == 0);
    // Along an axis: N = 1.
    s = read_scene("dim 2\nmirror \\ 0 1 1 0\nray 0 0 0 5\ntarget 0 0\n");
    CHECK(lattice::make_octagonal_lattice(s).scale == 1);
}

TEST_CASE("octagonal lattice: a diamond of diagonals, period 4 off its axis and 2 on it",
          "[octagonal][lattice]") {
    // At height h the ray turns up at (n + h, h), left at (n + h, 2n - h),
    // down at (n - h, 2n - h) and right at (n - h, h): period 4. At h = n it
    // meets the corner (2n, n) of two slopes and goes back: period 2.
    for (int n = 1; n <= 6; ++n)
        for (int twice_h = 1; twice_h < 4 * n; ++twice_h) {
            Rational h(twice_h, 2);
            h.canonicalize();
            const Scene s = read_scene(diamond(n, h.get_str()));
            INFO(write_scene(s));
            PathRecorder path;
            const Answer a = lattice_solve(s, &path);
            CHECK(a.reason == Reason::cycle);
            CHECK(a.tail == 0);
            CHECK(a.reflections == (h == n ? 2 : 4));
            if (n <= h) continue; // above the axis: the mirror image of below
            REQUIRE(path.points.size() >= 5);
            CHECK(path.points[1] == at(n + h, h));
            CHECK(path.points[2] == at(n + h, 2 * n - h));
            CHECK(path.points[3] == at(n - h, 2 * n - h));
            CHECK(path.points[4] == at(n - h, h));
            CHECK(path.directions[1] == at(0, 1));
            CHECK(path.directions[4] == at(1, 0));
        }
    // Coordinates past 2^59 and 2^123 run on int128 and GMP integers.
    for (const auto& [digits, arithmetic] :
         {std::pair{20, ArithmeticUsed::int128}, std::pair{40, ArithmeticUsed::gmp}}) {
        Integer n;
        mpz_ui_pow_ui(n.get_mpz_t(), 10, static_cast<unsigned long>(digits));
        PathRecorder path;
        const Answer a = lattice_solve(read_scene(diamond(n, "1/3")), &path);
        CHECK(a.arithmetic == arithmetic);
        CHECK(a.reason == Reason::cycle);
        CHECK(a.reflections == 4);
        REQUIRE(path.points.size() >= 2);
        CHECK(path.points[1] == at(Rational(n + Rational(1, 3)), Rational(1, 3)));
    }
    // Along a diagonal the ray slides along two sides and meets the other
    // two head on: straight back, period 2.
    const Answer a = lattice_solve(read_scene(diamond(4, "1", "1 1")));
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 2);
}

TEST_CASE("octagonal lattice: a ray along x in a box with a '/' and a '\\'",
          "[octagonal][lattice]") {
    // From (1/2, 1) along +x: the '\' (x + y = 2) turns it down at (1, 1);
    // at (1, 0) the wall y = 0 and the end of the '/' (y = x - 1) meet, a
    // corner of two orientations: back up; the '\' turns it left at (1, 1);
    // the wall x = 0 sends it right at (0, 1); period 4.
    const std::string box = "dim 2\nmirror x 0 y 0 4\nmirror x 4 y 0 4\nmirror y 0 x 0 4\n"
                            "mirror y 4 x 0 4\nmirror / 1 0 3 2\nmirror \\ 0 2 2 0\n"
                            "ray 1/2 1 1 0\n";
    PathRecorder path;
    Answer a = lattice_solve(read_scene(box + "target 9 9\n"), &path);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.reflections == 4);
    CHECK(a.tail == 0);
    REQUIRE(path.points.size() >= 5);
    CHECK(path.points[1] == at(1, 1));
    CHECK(path.points[2] == at(1, 0));
    CHECK(path.directions[2] == at(0, 1));
    CHECK(path.points[3] == at(1, 1));
    CHECK(path.directions[3] == at(-1, 0));
    CHECK(path.points[4] == at(0, 1));
    // Targets on the way: after one reflection, and after three.
    a = lattice_solve(read_scene(box + "target 1 1/2\n"));
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 1);
    a = lattice_solve(read_scene(box + "target 1/4 1\n"));
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 3);
}

TEST_CASE("octagonal lattice: a diagonal's endpoint reflects like its inside",
          "[octagonal][lattice]") {
    // '/' from (2, 0) to (3, 1): the ray along +x at y = 0 meets its end
    // (2, 0), turns to +y and escapes.
    PathRecorder path;
    const Answer a =
        lattice_solve(read_scene("dim 2\nmirror / 2 0 3 1\nray 0 0 5/2 0\ntarget 2 7\n"), &path);
    CHECK(a.reason == Reason::hit);
    CHECK(a.reflections == 1);
    const Answer escape =
        lattice_solve(read_scene("dim 2\nmirror / 2 0 3 1\nray 0 0 5/2 0\ntarget 3 7\n"), &path);
    CHECK(escape.reason == Reason::escape);
    CHECK(escape.reflections == 1);
    CHECK(path.points.back() == at(2, 0));
    CHECK(path.directions.back() == at(0, Rational(5, 2)));
    // The lower end (3, 1) of a '\' from (2, 2), met by a ray along
    // (-1, 2) from (4, -1) (a direction of neither kind).
    const Answer far =
        lattice_solve(read_scene("dim 2\nmirror \\ 2 2 3 1\nray 4 -1 -1 2\ntarget -9 -9\n"), &path);
    CHECK(far.reason == Reason::escape);
    CHECK(far.reflections == 1);
    CHECK(path.points.back() == at(3, 1));
    CHECK(path.directions.back() == at(-2, 1)); // '\': (v_x, v_y) -> (-v_y, -v_x)
}

TEST_CASE("octagonal lattice: one-way mirrors and a diagonal make a rho cycle with a tail",
          "[octagonal][lattice]") {
    // Down from (1/2, 2) past the end of the wall y = 1 (x in [2, 4]): the
    // '\' x + y = 1 sends it right at (1/2, 1/2); it passes the back of the
    // one-way mirror x+ 1; the '/' y = x - 5/2 turns it up at (3, 1/2); the
    // wall y = 1 sends it down at (3, 1); the '/' left at (3, 1/2); the
    // one-way mirror right at (1, 1/2), and again up at (3, 1/2). The first
    // state is not on the cycle: tail 1, period 4.
    const Scene s = read_scene("dim 2\nmirror \\ 0 1 1 0\nmirror x+ 1 y 0 1\nmirror / 5/2 0 7/2 1\n"
                               "mirror y 1 x 2 4\nray 1/2 2 0 -1\ntarget 9 9\n");
    PathRecorder path;
    const Answer a = lattice_solve(s, &path);
    CHECK(a.reason == Reason::cycle);
    CHECK(a.tail == 1);
    CHECK(a.period() == 4);
    CHECK(a.reflections == 5);
    const Answer want = engine::solve_by_reference(s, SolveOptions{});
    CHECK(want.tail == a.tail);
    CHECK(want.reflections == a.reflections);
}

TEST_CASE("octagonal lattice: grid, piece tables and cross-section grid refuse diagonals",
          "[octagonal][lattice]") {
    const Scene s = read_scene(diamond(3, "1"));
    for (const Shooter shooter : {Shooter::grid, Shooter::pieces, Shooter::section}) {
        SolveOptions options;
        options.shooter = shooter;
        CHECK_THROWS_AS(solve(s, options), UnsupportedScene);
    }
    SolveOptions bvh;
    bvh.shooter = Shooter::bvh;
    CHECK(solve(s, bvh).shooter == ShooterUsed::bvh);
}

TEST_CASE("octagonal lattice: agrees with the reference tracer on random octagonal scenes",
          "[octagonal][lattice][property][slow]") {
    std::mt19937_64 rng(1401);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 30;
    const Arithmetic arithmetics[] = {Arithmetic::automatic, Arithmetic::int128, Arithmetic::wide};
    const int cases = test::case_count(6500);
    int compared = 0, tails = 0, limits = 0, cycles = 0, hits = 0;
    for (int i = 0; i < cases; ++i) {
        shape.box = test::pick(rng, 2, 6);
        shape.max_elements = test::pick(rng, 1, 12);
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.has_diagonal()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        SolveOptions reference;
        reference.engine = Engine::reference;
        // Now and then a cap: both run Brent's detector on the same states.
        if (test::chance(rng, 15))
            reference.max_steps = static_cast<std::uint64_t>(test::pick(rng, 0, 30));
        const Answer want = engine::solve_by_reference(s, reference);
        SolveOptions options;
        options.max_steps = reference.max_steps;
        options.arithmetic = arithmetics[test::pick(rng, 0, 2)];
        if (test::chance(rng, 50)) options.engine = Engine::lattice;
        const Answer got = solve(s, options);
        ++compared;
        tails += want.tail > 0;
        limits += !want.decided();
        cycles += want.reason == Reason::cycle;
        hits += want.reason == Reason::hit;
        CHECK(got.engine == EngineUsed::lattice);
        CHECK(got.reason == want.reason);
        CHECK(got.reflections == want.reflections);
        CHECK(got.tail == want.tail);
        CHECK(got.period() == want.period());
    }
    CHECK(compared >= cases * 8 / 10);
    CHECK(tails > 0);
    CHECK(limits > 0);
    CHECK(cycles > cases / 10);
    CHECK(hits > cases / 10);
}

namespace {

// The integer points of the octagonal lattice on the elements, one by one
// over the elements' bounding box (machine integers: small scenes only), and
// the states among them keeping the line invariant.
std::pair<Integer, Integer> enumerate_states(const lattice::OctagonalLattice& l) {
    auto value = [](const Integer& x) { return x.get_si(); };
    long lo[2] = {value(l.elements[0].lo[0]), value(l.elements[0].lo[1])};
    long hi[2] = {value(l.elements[0].hi[0]), value(l.elements[0].hi[1])};
    for (const lattice::OctagonalElement& e : l.elements)
        for (int j = 0; j < 2; ++j) {
            lo[j] = std::min(lo[j], value(e.lo[j]));
            hi[j] = std::max(hi[j], value(e.hi[j]));
        }
    const long N = value(l.modulus);
    Integer points = 0, refined = 0;
    for (long x = lo[0]; x <= hi[0]; ++x)
        for (long y = lo[1]; y <= hi[1]; ++y) {
            bool on = false;
            for (const lattice::OctagonalElement& e : l.elements) {
                if (x < value(e.lo[0]) || value(e.hi[0]) < x || y < value(e.lo[1]) ||
                    value(e.hi[1]) < y)
                    continue;
                // In its box, a diagonal's points are those on its line.
                const long k = value(e.offset);
                on = on || (e.orientation == lattice::rising    ? x - y == k
                            : e.orientation == lattice::falling ? x + y == k
                                                                : true);
            }
            if (!on) continue;
            ++points;
            for (unsigned d = 0; d < lattice::direction_count; ++d)
                if (l.canonical[d] == d && (value(l.w[d][0]) * y - value(l.w[d][1]) * x) % N == 0)
                    ++refined;
        }
    return {points, refined};
}

} // namespace

TEST_CASE("octagonal bounds: exact point counts, states visited within them",
          "[octagonal][bounds][property][slow]") {
    // The box of the '/' and '\' above, at scale 2: 32 wall points, 5 on
    // each diagonal, minus the three diagonal ends on walls and the crossing
    // (3, 1); the ray along x takes 4 directions.
    const StateBounds box = compute_bounds(
        read_scene("dim 2\nmirror x 0 y 0 4\nmirror x 4 y 0 4\nmirror y 0 x 0 4\nmirror y 4 x 0 4\n"
                   "mirror / 1 0 3 2\nmirror \\ 0 2 2 0\nray 1/2 1 1 0\ntarget 9 9\n"));
    CHECK(box.octagonal);
    CHECK(box.points == 38);
    CHECK(box.directions == 4);
    CHECK(box.lattice_states == 152);
    CHECK(box.refined_states == 152); // N = 1: every state keeps it
    CHECK_FALSE(box.pieces);

    std::mt19937_64 rng(1402);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 20;
    const int cases = test::case_count(600);
    int enumerated = 0, refined_below = 0;
    for (int i = 0; i < cases; ++i) {
        shape.box = test::pick(rng, 2, 4);
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.has_diagonal()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const StateBounds b = compute_bounds(s);
        CHECK(b.refined_states <= b.lattice_states);
        refined_below += b.refined_states < b.lattice_states;
        const lattice::OctagonalLattice l = lattice::make_octagonal_lattice(s);
        if (l.scale <= 12) { // the counts, against enumeration
            const auto [points, refined] = enumerate_states(l);
            CHECK(b.points == points);
            CHECK(b.refined_states == refined);
            ++enumerated;
        }
        // Every state of the trajectory keeps the line invariant, and the
        // states visited stay within the refined bound.
        PathRecorder path;
        SolveOptions options;
        options.path = &path;
        options.max_steps = 2000;
        const Answer a = solve(s, options);
        for (std::size_t k = 1; k < path.points.size(); ++k) {
            const Integer x = Rational(path.points[k][0] * l.scale).get_num();
            const Integer y = Rational(path.points[k][1] * l.scale).get_num();
            const Vector& v = path.directions[k];
            bool keeps = false;
            for (unsigned d = 0; d < lattice::direction_count; ++d)
                if (l.direction(d) == v) keeps = (l.w[d][0] * y - l.w[d][1] * x) % l.modulus == 0;
            CHECK(keeps);
        }
        if (const std::optional<Integer> visited = states_visited(a))
            CHECK(*visited <= b.refined_states);
    }
    CHECK(enumerated > cases / 2);
    CHECK(refined_below > cases / 10);
}

TEST_CASE("bounds of several rays: each ray's own lattice, summed", "[octagonal][bounds]") {
    const std::string walls = "dim 2\nmirror x 0 y 0 3\nmirror x 5 y 0 3\nmirror y 0 x 0 5\n"
                              "mirror y 3 x 0 5\ntarget 1 1\n";
    const Scene first = read_scene(walls + "ray 0 0 1 1\n");
    const Scene second = read_scene(walls + "ray 1/2 0 1 2\n");
    const Scene both = read_scene(walls + "ray 0 0 1 1\nray 1/2 0 1 2\n");
    const StateBounds a = compute_bounds(first), b = compute_bounds(second),
                      sum = compute_bounds(both);
    CHECK(sum.rays == 2);
    CHECK(sum.points == a.points + b.points);
    CHECK(sum.lattice_states == a.lattice_states + b.lattice_states);
    CHECK(sum.refined_states == a.refined_states + b.refined_states);
    CHECK(sum.scale == a.scale); // the first ray's lattice describes the rest
    CHECK(b.lattice_states != a.lattice_states);
}

TEST_CASE("octagonal lattice: its certificates verify, and are the reference tracer's",
          "[octagonal][lattice][certificate][slow]") {
    // The independent verifier accepts the lattice engine's certificate
    // exactly when it answered, and the certificate is byte for byte the
    // reference tracer's: the same points, directions, cycle start and
    // verdict, in both formats, capped runs included.
    std::mt19937_64 rng(1403);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 30;
    int compared = 0;
    for (int i = 0; i < test::case_count(400); ++i) {
        const Scene s = test::random_octagonal_scene(rng, shape);
        if (!s.has_diagonal()) continue;
        INFO("case " << i << "\n" << write_scene(s));
        const CertificateFormat format =
            i % 2 == 0 ? CertificateFormat::text : CertificateFormat::jsonl;
        const std::optional<std::uint64_t> cap =
            test::chance(rng, 20) ? std::optional<std::uint64_t>(test::pick(rng, 0, 20))
                                  : std::nullopt;
        std::string text[2];
        bool decided = false;
        for (int k = 0; k < 2; ++k) {
            std::ostringstream out;
            CertificateWriter writer(out, s, format);
            SolveOptions options;
            options.engine = k == 0 ? Engine::lattice : Engine::reference;
            options.max_steps = cap;
            writer.attach(options);
            const Answer a = solve(s, options);
            writer.finish(a);
            text[k] = out.str();
            if (k == 0) decided = a.decided();
        }
        CHECK(text[0] == text[1]);
        std::istringstream in(text[0]);
        const Verdict verdict = verify_certificate(s, in);
        INFO(verdict.message);
        CHECK(verdict.valid == decided);
        ++compared;
    }
    // About 3 in 4 of the drawn scenes hold a diagonal and are compared.
    CHECK(compared > test::case_count(400) * 6 / 10);
}

namespace {

// One shot of the hierarchy on integer type Int, against the reference
// step (a rational scan of every element) from the same state. Whether the
// shot met an element (beyond agreeing that it escapes).
template <class Int>
bool check_shot(const Scene& s, const lattice::OctagonalLattice& l,
                const lattice::OctagonalOutcomes& outcomes, const shoot::OctagonalBvh<Int>& bvh,
                const lattice::Coords& at, unsigned d) {
    const Int p[2] = {lattice::from_integer<Int>(at[0]), lattice::from_integer<Int>(at[1])};
    const shoot::OctagonalShot<Int> shot = bvh.shoot(p, d);
    const engine::ReferenceEvent want = engine::reference_step(s, l.point(at), l.direction(d));
    REQUIRE(shot.escape == want.escape);
    if (want.escape) return false;
    lattice::Coords hit;
    for (int j = 0; j < 2; ++j) hit[j] = at[j] + lattice::to_integer(shot.t) * l.w[d][j];
    CHECK(l.point(hit) == want.point);
    const std::uint8_t next = outcomes.next(d, shot.mirrors, shot.absorbers);
    CHECK((next == lattice::absorbed) == want.absorbed);
    if (!want.absorbed) CHECK(l.direction(next) == want.direction);
    return true;
}

} // namespace

TEST_CASE("octagonal BVH: next hits equal a scan of every element, on every integer type",
          "[octagonal][lattice][shoot]") {
    // From random multiples of N on both axes (scene points whose
    // coordinates are integers after scaling by D: their cross values are
    // integers, as on every ray line), in every direction.
    std::mt19937_64 rng(1404);
    test::RandomOctagonalShape shape;
    shape.one_sided_percent = 30;
    int shots = 0, hits = 0;
    for (int i = 0; i < test::case_count(150); ++i) {
        const Scene s = test::random_octagonal_scene(rng, shape);
        INFO("case " << i << "\n" << write_scene(s));
        const lattice::OctagonalLattice l = lattice::make_octagonal_lattice(s);
        const lattice::OctagonalOutcomes outcomes(l);
        const shoot::OctagonalBvh<std::int64_t> narrow(l);
        const shoot::OctagonalBvh<lattice::int128_t> wide(l);
        const shoot::OctagonalBvh<Integer> gmp(l);
        const Integer N = l.modulus, D = l.scale / N;
        for (int k = 0; k < 20; ++k) {
            // Half-steps over the box and a little beyond, on the D grid.
            const lattice::Coords at{Integer(test::pick(rng, -2, 2 * shape.box + 2)) * D / 2 * N,
                                     Integer(test::pick(rng, -2, 2 * shape.box + 2)) * D / 2 * N,
                                     0};
            const unsigned d = l.canonical[test::pick(rng, 0, 7)];
            ++shots;
            hits += check_shot(s, l, outcomes, narrow, at, d);
            check_shot(s, l, outcomes, wide, at, d);
            check_shot(s, l, outcomes, gmp, at, d);
        }
    }
    // Most points checked are hits, not escapes: 1,636 of 3,000 on 2026-12-01.
    CHECK(hits > shots / 3);
}
