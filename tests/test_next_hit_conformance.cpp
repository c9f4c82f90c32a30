// One conformance harness for every next-hit structure of lib/src/shoot/:
// the uniform grid, the cross-section grid (at several densities), the
// bounding volume hierarchy and, in 2D, the piece tables, each on each
// integer type of lattice_int.hpp (int64, __int128, GMP), must give the
// brute-force answer (support/brute_force_shot.hpp) on random scenes with
// coincident and overlapping elements and absorbers, from corners, planes,
// walls and outside the scene, at magnitudes near the type's bound and
// along whole trajectories, and with one-sided elements (each structure
// must skip an element seen from its back). What only one structure promises (the BVH's
// node count, the piece tables' budget) stays in that structure's file.
#include "shoot/bvh.hpp"
#include "shoot/cross_section_grid.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"
#include "support/brute_force_shot.hpp"
#include "support/case_count.hpp"
#include "support/piece_table_states.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <tuple>
#include <type_traits>

using namespace orthoray;
using namespace orthoray::lattice;
using namespace orthoray::shoot;

namespace {

// The cross-section grid at a fixed density, so that each density is a
// structure of its own below.
template <class Int, int M, std::int64_t Density>
struct SectionAt : CrossSectionGrid<Int, M> {
    explicit SectionAt(const LatticeScene& ls) : CrossSectionGrid<Int, M>(ls, Density) {}
};

template <class Int, int M>
const char* name_of(const UniformGrid<Int, M>&) {
    return "uniform grid";
}
template <class Int, int M>
const char* name_of(const CrossSectionGrid<Int, M>&) {
    return "cross-section grid";
}
template <class Int, int M>
const char* name_of(const BoundingVolumeHierarchy<Int, M>&) {
    return "bounding volume hierarchy";
}

// `got` must be brute force's answer `want`: the same escape, parameter,
// mirrors flipped, axes met and absorber, and the named mirror must hold
// the hit.
template <class Int, int M>
void require_same(const char* name, const LatticeScene& ls, const Shot<Int>& want,
                  const Shot<Int>& got, const Int (&p)[M], unsigned negative) {
    INFO(name << ", direction " << negative);
    REQUIRE(got.escape == want.escape);
    if (want.escape) return;
    REQUIRE(got.t == want.t);
    REQUIRE(got.flip == want.flip);
    REQUIRE(got.met == want.met);
    REQUIRE(got.absorber == want.absorber);
    if (got.flip != 0) REQUIRE(test::mirror_holds_hit<Int, M>(ls, got, p, negative));
}

// Random scenes of up to `max_elements` elements, coordinates times `scale`,
// `shots` query points each, every structure on the same scene and points;
// about `one_sided` percent of the elements one-sided.
template <class Int, int M, class... Structures>
void check_random_shots(std::uint64_t seed, int scenes, int max_elements, int shots,
                        const Integer& scale, int one_sided) {
    std::mt19937_64 rng(seed);
    for (int scene_index = 0; scene_index < scenes; ++scene_index) {
        int range = 0;
        LatticeScene ls = test::random_lattice_scene<M>(rng, max_elements, range, scale);
        test::make_one_sided<M>(rng, ls, one_sided);
        const std::tuple<Structures...> structures{Structures(ls)...};
        for (int shot = 0; shot < shots; ++shot) {
            Int p[M];
            test::random_query_point<Int, M>(rng, ls, range, scale, p);
            const unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
            const Shot<Int> want = test::brute_force_shot<Int, M>(ls, p, negative);
            std::apply(
                [&](const auto&... s) {
                    (require_same<Int, M>(name_of(s), ls, want, s.shoot(p, negative), p, negative),
                     ...);
                },
                structures);
        }
    }
}

template <class Int, int M>
void check_all_random_shots(std::uint64_t seed, int scenes, int max_elements, int shots,
                            const Integer& scale, int one_sided = 0) {
    check_random_shots<Int, M, UniformGrid<Int, M>, SectionAt<Int, M, 1>, SectionAt<Int, M, 4>,
                       SectionAt<Int, M, 16>, BoundingVolumeHierarchy<Int, M>>(
        seed, scenes, max_elements, shots, scale, one_sided);
}

// Follows the trajectory inside a closed box of mirrors with obstacles
// (reflecting on mirrors, passing through absorbers) by one structure,
// holding every structure to brute force at every step.
template <class Int, int M>
void check_trajectory(std::uint64_t seed, int obstacles, int steps, int one_sided = 0) {
    std::mt19937_64 rng(seed);
    LatticeScene ls = test::random_box_scene<M>(rng, obstacles);
    test::make_one_sided<M>(rng, ls, one_sided);
    const UniformGrid<Int, M> grid(ls);
    const SectionAt<Int, M, 1> section(ls);
    const SectionAt<Int, M, 4> dense_section(ls);
    const BoundingVolumeHierarchy<Int, M> bvh(ls);
    Int p[M];
    for (int j = 0; j < M; ++j) p[j] = test::pick(rng, 1, 999);
    unsigned negative = static_cast<unsigned>(test::pick(rng, 0, (1 << M) - 1));
    for (int step = 0; step < steps; ++step) {
        INFO("step " << step);
        const Shot<Int> want = test::brute_force_shot<Int, M>(ls, p, negative);
        require_same<Int, M>("uniform grid", ls, want, grid.shoot(p, negative), p, negative);
        require_same<Int, M>("cross-section grid", ls, want, section.shoot(p, negative), p,
                             negative);
        require_same<Int, M>("dense cross-section grid", ls, want, dense_section.shoot(p, negative),
                             p, negative);
        const Shot<Int> s = bvh.shoot(p, negative);
        require_same<Int, M>("bounding volume hierarchy", ls, want, s, p, negative);
        if (s.escape) break;
        for (int j = 0; j < M; ++j)
            p[j] = ((negative >> j) & 1u) ? Int(p[j] - s.t) : Int(p[j] + s.t);
        negative ^= s.flip;
    }
}

// How many random scenes a type gets: the wider types cost more a query.
template <class Int>
int scenes_for(int int64_scenes) {
    if constexpr (std::is_same_v<Int, std::int64_t>)
        return test::case_count(int64_scenes);
    else if constexpr (std::is_same_v<Int, int128_t>)
        return test::case_count(int64_scenes / 4);
    else
        return test::case_count(int64_scenes / 7);
}

// A scale that takes coordinates (up to 33 times it) near the type's bound
// in lattice_int.hpp: under 2^59 for int64, 2^123 for __int128 (with room
// for the sums a query forms); GMP has none, so far past both. Odd offsets
// keep the values off powers of two.
template <class Int>
Integer near_bound() {
    if constexpr (std::is_same_v<Int, std::int64_t>)
        return (Integer(1) << 53) + 1;
    else if constexpr (std::is_same_v<Int, int128_t>)
        return (Integer(1) << 110) + 3;
    else
        return Integer(1) << 200;
}

// A mirror's pieces answer for the states on that mirror only, so the
// queries are all of them: every lattice point in every direction.
template <class Int>
void check_piece_tables(std::uint64_t seed, int scenes, int one_sided) {
    std::mt19937_64 rng(seed);
    for (int k = 0; k < scenes; ++k) {
        int range = 0;
        LatticeScene ls = test::random_lattice_scene<2>(rng, 25, range);
        test::make_one_sided<2>(rng, ls, one_sided);
        const UniformGrid<Int, 2> grid(ls);
        const auto table = PieceTable<Int>::build(grid, 1'000'000);
        REQUIRE(table);
        INFO("scene " << k);
        test::require_tables_answer(ls, *table, [&](const Int(&p)[2], unsigned d) {
            return test::brute_force_shot<Int, 2>(ls, p, d);
        });
    }
}

} // namespace

TEMPLATE_TEST_CASE("every next-hit structure matches brute force in 1D, 2D and 3D",
                   "[shoot][conformance][slow]", std::int64_t, int128_t, Integer) {
    using Int = TestType;
    check_all_random_shots<Int, 1>(41, scenes_for<Int>(100), 40, 100, 1);
    check_all_random_shots<Int, 2>(42, scenes_for<Int>(200), 40, 100, 1);
    check_all_random_shots<Int, 3>(43, scenes_for<Int>(200), 40, 100, 1);
    // Crowded: hundreds of elements in a scene.
    check_all_random_shots<Int, 3>(44, scenes_for<Int>(20), 400, 200, 1);
}

TEMPLATE_TEST_CASE("every next-hit structure is exact near its integer type's bound",
                   "[shoot][conformance]", std::int64_t, int128_t, Integer) {
    using Int = TestType;
    check_all_random_shots<Int, 2>(51, scenes_for<Int>(50), 40, 100, near_bound<Int>());
    check_all_random_shots<Int, 3>(52, scenes_for<Int>(50), 100, 100, near_bound<Int>());
}

TEMPLATE_TEST_CASE("every next-hit structure follows trajectories like brute force",
                   "[shoot][conformance][slow]", std::int64_t, int128_t, Integer) {
    using Int = TestType;
    const int steps = scenes_for<Int>(2800);
    check_trajectory<Int, 2>(61, 200, steps);
    check_trajectory<Int, 3>(62, 300, steps);
    check_trajectory<Int, 3>(63, 3000, steps);
}

TEMPLATE_TEST_CASE("piece tables match brute force from every lattice point of every mirror",
                   "[shoot][conformance][pieces][slow]", std::int64_t, int128_t, Integer) {
    check_piece_tables<TestType>(11, scenes_for<TestType>(400), 0);
}

TEMPLATE_TEST_CASE("every next-hit structure skips one-sided elements seen from their back",
                   "[shoot][conformance][optics]", std::int64_t, int128_t, Integer) {
    using Int = TestType;
    check_all_random_shots<Int, 1>(71, scenes_for<Int>(40), 40, 100, 1, 50);
    check_all_random_shots<Int, 2>(72, scenes_for<Int>(80), 40, 100, 1, 50);
    check_all_random_shots<Int, 3>(73, scenes_for<Int>(80), 40, 100, 1, 50);
    check_trajectory<Int, 2>(74, 200, scenes_for<Int>(700), 50);
    check_trajectory<Int, 3>(75, 300, scenes_for<Int>(700), 50);
    // The piece tables, whose sweep looks past elements that do not act on
    // the direction it builds.
    check_piece_tables<Int>(76, scenes_for<Int>(100), 50);
}

TEST_CASE("the cross-section grid past 2^15 elements matches brute force",
          "[shoot][section][slow]") {
    // Past 2^15 elements the grid allows at most 5 registrations an element
    // (cross_section_grid.hpp), a coarser layout no small scene reaches:
    // 40,000 random elements of lengths 1 to 40 in a cube of side 2,000.
    std::mt19937_64 rng(17'215);
    LatticeScene ls;
    ls.dim = 3;
    for (int i = 0; i < 40'000; ++i) {
        LatticeElement e;
        e.axis = test::pick(rng, 0, 2);
        e.absorber = test::pick(rng, 0, 9) == 0;
        for (int j = 0; j < 3; ++j) {
            const int a = test::pick(rng, -1000, 1000);
            e.lo[j] = a;
            e.hi[j] = j == e.axis ? a : a + test::pick(rng, 1, 40);
        }
        ls.elements.push_back(e);
    }
    const SectionAt<std::int64_t, 3, 4> grid(ls); // the engine's density
    const int shots = test::case_count(400);
    for (int shot = 0; shot < shots; ++shot) {
        std::int64_t p[3];
        for (std::int64_t& x : p) x = test::pick(rng, -1100, 1100);
        const unsigned negative = static_cast<unsigned>(test::pick(rng, 0, 7));
        INFO("shot " << shot);
        const Shot<std::int64_t> want = test::brute_force_shot<std::int64_t, 3>(ls, p, negative);
        require_same<std::int64_t, 3>("cross-section grid", ls, want, grid.shoot(p, negative), p,
                                      negative);
    }
}
