// Finding the piece that holds a position, in the sorted first positions of
// one slot's pieces: the search both the piece tables (piece_table.hpp) and
// their two-step tables (two_step_table.hpp) make once a lookup.
//
// Layout it reads. A slot's first positions key[0 .. count) are stored in
// order; a slot of more than 8 also stores the first position of each block
// of 8 right after them (add_block_index), and the array holds
// piece_search_padding positions past its last slot, which the fixed-width
// counts read and mask off.
#pragma once

#include "lattice/lattice_int.hpp"

#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace orthoray::shoot {

// Positions past the last slot that the fixed-width searches read: up to 31
// past a long slot's index, 7 past a short slot.
inline constexpr std::size_t piece_search_padding = 32;

namespace piece_search {

// How many of key[1], ..., key[width - 1] are at most u, counting only the
// first `count - 1` of them (key[0], a slot's first position, is at most
// u): a fixed number of subtractions, masks and adds, no compares and no
// jumps. key <= u and i < count are the sign bits of key - (u + 1) and
// i - count; every position is below 8B in size (lattice_int.hpp), so the
// differences cannot overflow. (Plain registers: moving u into a vector
// register and the count back out costs more latency than the compares,
// measured.)
template <unsigned width, class Int>
std::uint32_t count_at_most(const Int* key, std::uint32_t count, const Int& u) {
    using Bits = std::conditional_t<sizeof(Int) == 8, std::uint64_t, lattice::uint128_t>;
    constexpr int sign = 8 * sizeof(Int) - 1;
    const Int above = u + 1, n = count;
    Bits k = 0;
    for (unsigned i = 1; i < width; ++i)
        k += (static_cast<Bits>(key[i] - above) & static_cast<Bits>(Int(i) - n)) >> sign;
    return static_cast<std::uint32_t>(k);
}

} // namespace piece_search

// The piece holding position u among a slot's `count` pieces whose first
// positions start at `key`, counted from the slot's first: the last one
// starting at or before u. A slot of up to 8 pieces is one cache line of
// positions, counted at fixed width (4 lanes when it has at most 4, as most
// have: the lanes cost; 2 was slower, measured). A longer one (a box wall of
// a random scene has 80-100 pieces, 130-165 in the two-step table) is
// searched on two levels: its index (up to 32 blocks at fixed width; a
// binary search past that), then the 8 of the block found. A binary search
// over the pieces would jump on every compare, unpredictably.
template <class Int>
std::uint32_t locate_piece(const Int* key, std::uint32_t count, const Int& u) {
    using piece_search::count_at_most;
    if constexpr (std::is_trivially_copyable_v<Int>) {
        if (count <= 4) return count_at_most<4>(key, count, u);
        if (count <= 8) return count_at_most<8>(key, count, u);
        const std::uint32_t blocks = (count + 7) / 8;
        std::uint32_t block = 0;
        if (blocks <= 16) {
            block = count_at_most<16>(key + count, blocks, u);
        } else if (blocks <= 32) {
            block = count_at_most<32>(key + count, blocks, u);
        } else {
            std::uint32_t lo = 0, hi = blocks; // key[8 lo] <= u < key[8 hi] (hi: past the end)
            while (hi - lo > 1) {
                const std::uint32_t mid = (lo + hi) / 2;
                (u < key[count + mid] ? hi : lo) = mid;
            }
            block = lo;
        }
        return 8 * block + count_at_most<8>(key + 8 * block, count - 8 * block, u);
    } else {
        // GMP integers: a compare costs more than a jump; search plainly.
        return static_cast<std::uint32_t>(std::upper_bound(key, key + count, u) - key - 1);
    }
}

// The positions a slot of `count` pieces adds after its own for its index
// (locate_piece's): one a block of 8, when it has more than 8.
inline std::size_t block_index_size(std::size_t count) {
    return count <= 8 ? 0 : (count + 7) / 8;
}

// Writes that index after a slot's `count` first positions at `key`, which
// has room for it.
template <class Int>
void write_block_index(Int* key, std::size_t count) {
    for (std::size_t b = 0; b < block_index_size(count); ++b) key[count + b] = key[8 * b];
}

// After a slot's `count` first positions, ending `key`: its index. Returns
// how many positions were added; the caller keeps any parallel array as
// long.
template <class Int>
std::size_t add_block_index(std::vector<Int>& key, std::size_t begin, std::size_t count) {
    const std::size_t blocks = block_index_size(count);
    key.resize(key.size() + blocks);
    write_block_index(key.data() + begin, count);
    return blocks;
}

} // namespace orthoray::shoot
