// Every state a 2D scene's piece tables answer for: each lattice point of
// each mirror (an absorber has no pieces) in each of the four directions.
// Shared by the tests that hold the tables to a trusted shooter there.
#pragma once

#include "shoot/piece_table.hpp"
#include "support/brute_force_shot.hpp"

#include <catch2/catch.hpp>

namespace orthoray::test {

// Requires the tables of `ls` to answer every state as want(p, d) does:
// the same escape, absorber and t, and the same flip on a mirror that
// holds the hit. Pieces keep no axes met, and past an absorber nothing is
// reflected, so the flip is not theirs to say there.
template <class Int, class Want>
void require_tables_answer(const lattice::LatticeScene& ls, const shoot::PieceTable<Int>& table,
                           Want&& want_at) {
    for (std::uint32_t m = 0; m < ls.elements.size(); ++m) {
        const lattice::LatticeElement& e = ls.elements[m];
        if (e.absorber) continue;
        const int t = 1 - e.axis;
        for (Integer u = e.lo[t]; u <= e.hi[t]; ++u)
            for (unsigned d = 0; d < 4; ++d) {
                Int p[2] = {lattice::from_integer<Int>(e.lo[0]),
                            lattice::from_integer<Int>(e.lo[1])};
                p[t] = lattice::from_integer<Int>(u);
                const shoot::Shot<Int> want = want_at(p, d), got = table.shoot(p, d, m);
                INFO("mirror " << m << ", u = " << u << ", direction " << d);
                REQUIRE(got.escape == want.escape);
                if (want.escape) continue;
                REQUIRE(got.absorber == want.absorber);
                REQUIRE(got.t == want.t);
                if (want.absorber) continue;
                REQUIRE(got.flip == want.flip);
                REQUIRE(mirror_holds_hit<Int, 2>(ls, got, p, d));
            }
    }
}

} // namespace orthoray::test
