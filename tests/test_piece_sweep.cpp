// The piece sweep's parts (piece_sweep.hpp): its search, its sort, and its
// promise that each slot's pieces come out in order of position.
#include "shoot/piece_sweep.hpp"
#include "shoot/uniform_grid.hpp"
#include "support/random_lattice.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

using namespace orthoray;
using namespace orthoray::shoot;

TEST_CASE("first_false finds where a partitioned range turns false", "[pieces]") {
    for (std::size_t size = 0; size <= 70; ++size)
        for (std::size_t split = 0; split <= size; ++split) {
            std::vector<int> items(size);
            for (std::size_t i = 0; i < size; ++i) items[i] = static_cast<int>(i);
            const auto pred = [split](int x) { return static_cast<std::size_t>(x) < split; };
            INFO(size << " items, true on the first " << split);
            REQUIRE(piece_sweep::first_false(items.data(), size, pred) ==
                    static_cast<std::size_t>(
                        std::partition_point(items.begin(), items.end(), pred) - items.begin()));
        }
}

TEST_CASE("sort_by_key sorts by key, negative keys and ties included", "[pieces]") {
    std::mt19937_64 rng(29);
    for (const std::size_t size : {0u, 1u, 5u, 1000u, 50000u}) {
        // Keys from a narrow and from a wide range: many ties, and the radix
        // sort's many levels.
        for (const std::int64_t spread : {std::int64_t{7}, std::int64_t{1} << 61}) {
            std::vector<std::pair<std::int64_t, std::uint32_t>> items(size);
            for (std::size_t i = 0; i < size; ++i)
                items[i] = {static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(spread)) -
                                spread / 2,
                            static_cast<std::uint32_t>(i)};
            std::vector<std::pair<std::int64_t, std::uint32_t>> want = items;
            std::sort(want.begin(), want.end());
            piece_sweep::sort_by_key(items.begin(), items.end(),
                                     [](const auto& x) { return x.first; });
            INFO(size << " items, keys spread over " << spread);
            // In order of key, and the same items (ties in any order).
            REQUIRE(std::is_sorted(items.begin(), items.end(),
                                   [](const auto& x, const auto& y) { return x.first < y.first; }));
            std::sort(items.begin(), items.end());
            REQUIRE(items == want);
        }
    }
}

// Every crossing of a vertical and a horizontal element, by brute force.
template <class Int>
std::vector<piece_sweep::Crossing> crossings_of(const UniformGrid<Int, 2>& grid) {
    std::vector<piece_sweep::Crossing> out;
    const auto n = static_cast<std::uint32_t>(grid.size());
    for (std::uint32_t v = 0; v < n; ++v)
        for (std::uint32_t h = 0; h < n; ++h) {
            const ElementBox<Int, 2>&a = grid.element(v), &b = grid.element(h);
            if (a.axis == 0 && b.axis == 1 && b.lo[0] <= a.lo[0] && a.lo[0] <= b.hi[0] &&
                a.lo[1] <= b.lo[1] && b.lo[1] <= a.hi[1])
                out.push_back({v, h});
        }
    return out;
}

// The table builder writes each slot's pieces in the order they come, so it
// relies on this: a slot's positions rise, or fall where `falls` says.
TEST_CASE("a sweep gives each slot's pieces in the order falls names", "[pieces]") {
    std::mt19937_64 rng(31);
    for (int scene = 0; scene < 200; ++scene) {
        const lattice::LatticeScene ls = test::random_box_scene<2>(rng, 1 + scene % 40, 200);
        const UniformGrid<std::int64_t, 2> grid(ls);
        const auto crossings = crossings_of(grid);
        const auto n = static_cast<std::uint32_t>(grid.size());
        for (unsigned d = 0; d < 2; ++d) {
            std::map<std::uint32_t, std::vector<std::int64_t>> slots;
            const bool done = piece_sweep::sweep<std::int64_t>(
                n,
                [&](std::uint32_t e) -> const ElementBox<std::int64_t, 2>& {
                    return grid.element(e);
                },
                [](std::uint32_t e) { return e; }, d, crossings, SIZE_MAX, {},
                [&](const piece_sweep::Swept<std::int64_t>& piece) {
                    slots[piece.slot].push_back(piece.from);
                    return true;
                });
            REQUIRE(done);
            REQUIRE_FALSE(slots.empty());
            for (const auto& [slot, from] : slots) {
                const bool vertical = grid.element(slot / 4).axis == 0;
                INFO("scene " << scene << ", sweep " << d << ", slot " << slot);
                CHECK((slot % 4 == d || slot % 4 == (d ^ 3u)));
                for (std::size_t k = 1; k < from.size(); ++k)
                    REQUIRE((piece_sweep::falls(d, vertical) ? from[k] < from[k - 1]
                                                             : from[k - 1] < from[k]));
            }
        }
    }
}
