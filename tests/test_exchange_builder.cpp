// The interval exchange built from the piece tables is the step map: on
// random small lattice scenes, every state of the exchange is followed
// through the exchange and through a grid shot, and the two must agree
// (next state, escape, absorption, and whether the segment passes the
// target), and the exchange must be a bijection with x alone at 0.
#include "induction/exchange_builder.hpp"

#include "support/case_count.hpp"
#include "support/random_lattice.hpp"

#include "orthoray/exchange.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::induction;

namespace {

// The state at rotated coordinate c: its point and direction.
struct StateAt {
    Integer p[2];
    unsigned negative;
};

StateAt state_at(const IntervalExchange& e, const Integer& c) {
    const Integer raw_first = e.transversals[e.first_transversal].start + e.first_index;
    const Integer raw = floor_mod(c + raw_first, e.size);
    std::size_t i = 0;
    while (!(e.transversals[i].start <= raw &&
             raw < e.transversals[i].start + e.transversals[i].count))
        ++i;
    const Transversal& t = e.transversals[i];
    const Integer number = raw - t.start;
    const Integer j = t.w_slope > 0 ? number : Integer(t.count - 1 - number);
    StateAt s;
    s.p[t.axis] = t.offset;
    s.p[1 - t.axis] = t.first + j * e.modulus;
    s.negative = t.negative;
    return s;
}

const ExchangePiece& piece_at(const IntervalExchange& e, const Integer& c) {
    for (const ExchangePiece& p : e.pieces)
        if (p.start <= c && c < p.start + p.length) return p;
    FAIL("no piece holds " << c.get_str());
    return e.pieces.front();
}

} // namespace

TEST_CASE("the exchange is the step map on every state", "[exchange][slow]") {
    std::mt19937_64 rng(2026);
    int reflecting = 0, dead = 0, hits = 0;
    const int scenes = test::case_count(600); // a quarter under sanitizers
    for (int scene = 0; scene < scenes; ++scene) {
        int range = 0;
        lattice::LatticeScene ls = test::random_lattice_scene<2>(rng, 14, range);
        // Only mirrors give states; x is a random one of them.
        std::vector<std::uint32_t> mirrors;
        for (std::uint32_t m = 0; m < ls.elements.size(); ++m)
            if (!ls.elements[m].absorber) mirrors.push_back(m);
        if (mirrors.empty()) continue;
        const auto& m = ls.elements[mirrors[test::pick(rng, 0, int(mirrors.size()) - 1)]];
        Integer x[2] = {m.lo[0], m.lo[1]};
        x[1 - m.axis] = test::pick(rng, m.lo[1 - m.axis].get_si(), m.hi[1 - m.axis].get_si());
        const unsigned x_negative = static_cast<unsigned>(test::pick(rng, 0, 3));
        ls.target_reachable = true;
        for (int j = 0; j < 2; ++j) ls.target[j] = test::pick(rng, -range, range);

        const shoot::UniformGrid<Integer, 2> grid(ls);
        const auto table = shoot::PieceTable<Integer>::build(grid, 1'000'000);
        REQUIRE(table);
        const IntervalExchange e = build_exchange(ls, grid, *table, x, x_negative);
        INFO("scene " << scene);
        REQUIRE(e.pieces.front().start == 0);
        REQUIRE(e.pieces.front().length == 1);
        const StateAt first = state_at(e, 0);
        REQUIRE((first.p[0] == x[0] && first.p[1] == x[1] && first.negative == x_negative));

        std::vector<bool> imaged(e.size.get_ui(), false);
        for (Integer c = 0; c < e.size; ++c) {
            const ExchangePiece& piece = piece_at(e, c);
            const Integer image = c + piece.image - piece.start;
            REQUIRE(image >= 0);
            REQUIRE(image < e.size);
            REQUIRE_FALSE(imaged[image.get_ui()]);
            imaged[image.get_ui()] = true;

            const StateAt s = state_at(e, c);
            const shoot::Shot<Integer> shot = grid.shoot(s.p, s.negative);
            // The segment from s passes the target: target - p = tau * sigma, 0 <= tau <= t.
            Integer tau = ((s.negative & 1u) ? -1 : 1) * (ls.target[0] - s.p[0]);
            const bool passes = tau >= 0 && (shot.escape || tau <= shot.t) &&
                                ((s.negative & 2u) ? -1 : 1) * (ls.target[1] - s.p[1]) == tau;
            REQUIRE(piece.hit == passes);
            hits += passes;
            if (shot.escape) {
                REQUIRE(piece.kind == PieceKind::escape);
                ++dead;
                continue;
            }
            if (shot.absorber) {
                REQUIRE(piece.kind == PieceKind::absorbed);
                ++dead;
                continue;
            }
            REQUIRE(piece.kind == PieceKind::reflect);
            const StateAt next = state_at(e, image);
            for (int j = 0; j < 2; ++j)
                REQUIRE(next.p[j] ==
                        s.p[j] + (((s.negative >> j) & 1u) ? Integer(-shot.t) : shot.t));
            REQUIRE(next.negative == (s.negative ^ shot.flip));
            ++reflecting;
        }
    }
    CHECK(reflecting * 60 > scenes * 1000);
    CHECK(dead * 60 > scenes * 100);
    CHECK(hits * 60 > scenes * 10);
}

namespace {

// The exchange of a 2D scene built on GMP integers throughout (the tables'
// Integer makes the builder take GMP whatever the bound allows).
IntervalExchange gmp_exchange(const lattice::LatticeScene& ls) {
    const shoot::UniformGrid<Integer, 2> grid(ls);
    auto table = shoot::PieceTable<Integer>::build(grid, 1'000'000);
    REQUIRE(table);
    if (ls.target_reachable) {
        const Integer target[2] = {ls.target[0], ls.target[1]};
        table->mark_target(grid, target);
    }
    return *build_exchange_from_start(ls, grid, *table);
}

void require_same(const IntervalExchange& a, const IntervalExchange& b) {
    REQUIRE(a.size == b.size);
    REQUIRE(a.modulus == b.modulus);
    REQUIRE(a.first_transversal == b.first_transversal);
    REQUIRE(a.first_index == b.first_index);
    REQUIRE(a.transversals.size() == b.transversals.size());
    for (std::size_t i = 0; i < a.transversals.size(); ++i) {
        REQUIRE(a.transversals[i].start == b.transversals[i].start);
        REQUIRE(a.transversals[i].count == b.transversals[i].count);
        REQUIRE(a.transversals[i].first == b.transversals[i].first);
    }
    REQUIRE(a.pieces.size() == b.pieces.size());
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        REQUIRE(a.pieces[i].start == b.pieces[i].start);
        REQUIRE(a.pieces[i].length == b.pieces[i].length);
        REQUIRE(a.pieces[i].image == b.pieces[i].image);
        REQUIRE(a.pieces[i].kind == b.pieces[i].kind);
        REQUIRE(a.pieces[i].hit == b.pieces[i].hit);
    }
}

} // namespace

// exchange_arithmetic's bound, 4 x (lattice points on the mirrors) < 2^59,
// at its edge: an m x (m - 1) box from its corner at 45 degrees (lattice
// scale 1) has 4 (2 (2m - 1) + 4) = 2^59 - 8 such points for m = 2^55 - 1,
// and 2^59 + 8 for m = 2^55. The first builds on int64_t, the second on
// __int128 (its largest coordinate is still far below 2^59); both must give
// GMP's exchange and the closed form.
TEST_CASE("the exchange is built on the narrowest integers its bound allows", "[exchange]") {
    for (const auto& [m, expected] : std::vector<std::pair<Integer, ArithmeticUsed>>{
             {(Integer(1) << 55) - 1, ArithmeticUsed::int64},
             {Integer(1) << 55, ArithmeticUsed::int128}}) {
        INFO("m = " << m.get_str());
        BoxFamily family;
        family.sides = {m, m - 1};
        const GeneratedScene g = generate_box(family);
        const lattice::LatticeScene ls = lattice::make_lattice(g.scene);
        REQUIRE(ls.magnitude < lattice::int64_limit());
        REQUIRE(exchange_arithmetic(ls) == expected);
        const std::optional<IntervalExchange> narrow = exchange_of(g.scene);
        REQUIRE(narrow);
        require_same(*narrow, gmp_exchange(ls));
        SolveOptions o;
        o.engine = Engine::induction;
        const Answer a = solve(g.scene, o);
        REQUIRE(g.expect);
        REQUIRE(a.engine == EngineUsed::induction);
        REQUIRE(a.reason == g.expect->reason);
        REQUIRE(a.reflections == g.expect->reflections);
    }
}
