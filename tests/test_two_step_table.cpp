// The two-step tables against the piece tables they compose: a glide on
// either takes the same reflections and stops at the same state, with the
// same cursor, for every limit, first state and target, with one-sided
// elements or without; and without them the two-step table has at most
// twice the pieces (each of T's first positions has at most one preimage,
// two_step_table.hpp).
#include "shoot/two_step_table.hpp"
#include "support/case_count.hpp"
#include "support/lattice_segments.hpp"
#include "support/portable_random.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

template <class Int>
struct Glider {
    Int p[2];
    unsigned negative;
    typename PieceTable<Int>::Cursor where;
};

template <class Int>
void require_same(const Glider<Int>& a, const Glider<Int>& b) {
    REQUIRE(a.p[0] == b.p[0]);
    REQUIRE(a.p[1] == b.p[1]);
    REQUIRE(a.negative == b.negative);
    REQUIRE(a.where.begin == b.where.begin);
    REQUIRE(a.where.count == b.where.count);
    REQUIRE(a.where.tangent == b.where.tangent);
}

} // namespace

TEMPLATE_TEST_CASE("two-step glides take the piece tables' reflections and stop where they do",
                   "[pieces][two-step]", std::int64_t, int128_t, Integer) {
    std::mt19937_64 rng(2611);
    const int scenes = test::case_count(std::is_same_v<TestType, Integer> ? 100 : 400);
    int glides = 0, long_glides = 0, stopped_at_first = 0;
    for (int s = 0; s < scenes; ++s) {
        int range = 0;
        LatticeScene ls = test::random_lattice_scene<2>(rng, 40, range);
        // One-sided elements in a third of the scenes: the engine glides
        // only without them, but the glide's contract does not need that.
        if (test::pick(rng, 0, 2) == 0) test::make_one_sided<2>(rng, ls, 30);
        const UniformGrid<TestType, 2> grid(ls);
        auto table = PieceTable<TestType>::build(grid, 1'000'000);
        REQUIRE(table);
        // A target in half the scenes: its pieces stop both glides.
        if (test::pick(rng, 0, 1)) {
            const TestType target[2] = {TestType(test::pick(rng, -range, range)),
                                        TestType(test::pick(rng, -range, range))};
            table->mark_target(grid, target);
        }
        const auto two = TwoStepTable<TestType>::build(*table, grid, 1'000'000);
        REQUIRE(two);
        // T is injective without one-sided elements (two_step_table.hpp).
        if (!ls.one_sided) CHECK(two->size() <= 2 * table->size());
        for (int q = 0; q < 20; ++q) {
            const auto m = static_cast<std::uint32_t>(
                test::pick(rng, 0, static_cast<int>(ls.elements.size()) - 1));
            const LatticeElement& e = ls.elements[m];
            if (e.absorber) continue;
            const int t = 1 - e.axis;
            Glider<TestType> start;
            start.negative = static_cast<unsigned>(test::pick(rng, 0, 3));
            start.p[0] = from_integer<TestType>(e.lo[0]);
            start.p[1] = from_integer<TestType>(e.lo[1]);
            start.p[t] = TestType(test::pick(rng, static_cast<int>(e.lo[t].get_si()),
                                             static_cast<int>(e.hi[t].get_si())));
            start.where = table->at(m, start.negative);
            // The first state: one the ray reaches after a few reflections
            // (so the glides must stop just before it), or none.
            Glider<TestType> first = start;
            const int ahead = test::pick(rng, 0, 12);
            const TestType nowhere[2] = {TestType(0), TestType(0)};
            table->glide(first.p, first.negative, first.where, static_cast<std::uint64_t>(ahead),
                         nowhere, 4u);
            const unsigned first_negative = test::pick(rng, 0, 2) ? first.negative : 4u;
            const std::uint64_t limit = static_cast<std::uint64_t>(test::pick(rng, 0, 60));
            Glider<TestType> single = start, paired = start;
            const std::uint64_t want = table->glide(single.p, single.negative, single.where, limit,
                                                    first.p, first_negative);
            const std::uint64_t got =
                two->glide(paired.p, paired.negative, paired.where, limit, first.p, first_negative);
            INFO("scene " << s << ", mirror " << m << ", limit " << limit);
            REQUIRE(got == want);
            require_same(paired, single);
            ++glides;
            long_glides += want >= 4;
            stopped_at_first += first_negative < 4 && want < limit && ahead > 0;
        }
    }
    // The samples reach what they are for: long glides, and glides cut
    // short by the first state.
    CHECK(glides > 10 * scenes);
    CHECK(long_glides > glides / 10);
    CHECK(stopped_at_first > glides / 20);
}

// A 4 x 6 mirror box: from the foot of the left wall towards +x+y the ray
// meets the right wall at (4, 4), then the top at (2, 6). One two-step
// lookup takes both; the table's pieces there say so.
TEST_CASE("a two-step glide in a box takes two reflections a lookup", "[pieces][two-step]") {
    const LatticeScene ls = test::lattice_box(4, 6);
    const UniformGrid<std::int64_t, 2> grid(ls);
    const auto table = PieceTable<std::int64_t>::build(grid, 1000);
    REQUIRE(table);
    const auto two = TwoStepTable<std::int64_t>::build(*table, grid, 1000);
    REQUIRE(two);
    std::int64_t p[2] = {0, 0};
    unsigned negative = 0;
    auto where = table->at(0, 0);
    const std::int64_t nowhere[2] = {-1, -1};
    CHECK(two->glide(p, negative, where, 2, nowhere, 0) == 2);
    CHECK(p[0] == 2);
    CHECK(p[1] == 6);
    CHECK(negative == 3u); // x flipped at the right wall, y at the top
    // An odd limit ends on a single step: 2 + 7 reflections in two glides
    // land where 9 single steps do.
    std::int64_t q[2] = {0, 0};
    unsigned q_negative = 0;
    auto q_where = table->at(0, 0);
    CHECK(table->glide(q, q_negative, q_where, 9, nowhere, 0) == 9);
    CHECK(two->glide(p, negative, where, 7, nowhere, 0) == 7);
    CHECK(p[0] == q[0]);
    CHECK(p[1] == q[1]);
    CHECK(negative == q_negative);
}
