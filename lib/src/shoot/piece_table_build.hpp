// Building the piece tables (piece_table.hpp): the pieces of every slot from
// the sweeps (piece_sweep.hpp), bucketed into the tables' layout, then the
// links from each piece to the next mirror's pieces.
#pragma once

#include "shoot/piece_sweep.hpp"
#include "shoot/piece_table.hpp"

namespace orthoray::shoot {
namespace piece_build {

// Puts items[0, size) in order of key(item) in [0, keys), in place, and
// returns where each key's items start (keys + 1 entries, the last = size).
// Each swap moves one item into its key's range for good: the ranges before
// the one being filled are full, so it goes to a later one. One pass over
// all 4n slots of 10^5 mirrors chases a dependent cache miss a swap (0.5 s
// for 1.8 M items); keys at most 1024 keep the positions written
// next in the cache, so the build sorts in two such passes (by_slot).
// The prefetch is only a hint: no position past `size` is read.
template <class T, class Key>
std::vector<std::uint32_t> bucket(T* items, std::uint32_t size, std::uint32_t keys, Key key) {
    std::vector<std::uint32_t> start(std::size_t{keys} + 1, 0);
    for (std::uint32_t i = 0; i < size; ++i) ++start[key(items[i]) + 1];
    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t k = 0; k < keys; ++k)
        while (fill[k] < start[k + 1]) {
            T& item = items[fill[k]];
            const std::uint32_t to = key(item);
            if (to == k) {
                ++fill[k];
            } else {
                std::swap(item, items[fill[to]++]);
                // The next line of that range, read when it is filled further.
                __builtin_prefetch(items + std::min<std::size_t>(size, fill[to] + 64 / sizeof(T)));
            }
        }
    return start;
}

// Puts `items` in order of their `slot` (below `slots`), in place, by its
// high bits and then by its low bits within each range, each pass with at
// most about `max_keys` keys; returns where each slot's items start
// (slots + 1 entries).
template <class T>
std::vector<std::uint32_t> by_slot(std::vector<T>& items, std::uint32_t slots,
                                   std::uint32_t max_keys = 1024) {
    unsigned low = 0;
    while ((slots >> low) > max_keys) ++low;
    const std::uint32_t coarse = (slots >> low) + 1, fine = 1u << low;
    const auto size = static_cast<std::uint32_t>(items.size());
    const std::vector<std::uint32_t> outer =
        bucket(items.data(), size, coarse, [low](const T& x) { return x.slot >> low; });
    std::vector<std::uint32_t> start(std::size_t{slots} + 1, size);
    for (std::uint32_t c = 0; c < coarse; ++c) {
        const std::vector<std::uint32_t> inner =
            bucket(items.data() + outer[c], outer[c + 1] - outer[c], fine,
                   [fine](const T& x) { return x.slot & (fine - 1); });
        for (std::uint32_t f = 0; f < fine && c * fine + f < slots; ++f)
            start[c * fine + f] = outer[c] + inner[f];
    }
    return start;
}

} // namespace piece_build

template <class Int>
std::optional<PieceTable<Int>> PieceTable<Int>::build(const UniformGrid<Int, 2>& grid,
                                                      std::size_t max_pieces,
                                                      const lattice::SetupPoll& poll) {
    // The grid holds every element's box in Int (element e of the scene is
    // the grid's element e): read there, not copied.
    const std::uint32_t n = static_cast<std::uint32_t>(grid.size());
    auto box = [&grid](std::uint32_t e) -> const ElementBox<Int, 2>& { return grid.element(e); };

    // Every crossing of a vertical and a horizontal element (T-junctions and
    // corners included): where the sweep's order changes.
    std::vector<piece_sweep::Crossing> crossings;
    for (std::uint32_t e = 0; e < n; ++e) {
        poll();
        if (box(e).axis != 0) continue;
        grid.for_each_neighbour(e, [&](std::uint32_t f) {
            const ElementBox<Int, 2>& v = box(e);
            const ElementBox<Int, 2>& h = box(f);
            if (h.axis != 1) return;
            if (h.lo[0] <= v.lo[0] && v.lo[0] <= h.hi[0] && v.lo[1] <= h.lo[1] &&
                h.lo[1] <= v.hi[1])
                crossings.push_back(piece_sweep::Crossing{e, f});
        });
    }
    std::sort(crossings.begin(), crossings.end());
    crossings.erase(std::unique(crossings.begin(), crossings.end()), crossings.end());

    PieceTable table;
    table.tangent_.resize(n);
    table.acting_.resize(n);
    for (std::uint32_t e = 0; e < n; ++e) {
        table.tangent_[e] = static_cast<std::uint8_t>(1 - box(e).axis);
        table.acting_[e] = box(e).acting;
    }

    // Mirrors' pieces are laid out in Z-order of their low corners: the ray,
    // whose next mirror is a spatial neighbour, finds its next pieces nearby.
    {
        std::vector<std::pair<std::uint64_t, std::uint32_t>> order(n);
        for (std::uint32_t m = 0; m < n; ++m) order[m] = {grid.locality_key(box(m).lo), m};
        std::sort(order.begin(), order.end());
        table.laid_out_.resize(n);
        for (std::uint32_t r = 0; r < n; ++r) table.laid_out_[r] = order[r].second;
    }
    std::vector<std::uint32_t> layout_rank(n);
    for (std::uint32_t r = 0; r < n; ++r) layout_rank[table.laid_out_[r]] = r;

    // Every slot's pieces, one sweep a pair of opposite directions at a
    // time, then bucketed by slot in layout order (a counting sort in place)
    // and put in order of position. A piece waits in 24 bytes on int64, its
    // map packed beside the next mirror (which therefore takes 26 bits).
    if (n >= (std::uint32_t{1} << 26)) return std::nullopt;
    struct Waiting {
        std::uint32_t slot;
        std::uint32_t map; // next << 6 | (slope + 1) << 4 | flip << 2 | kind
        Int from, base;
    };
    // Reserved for 16 a mirror (the benchmark's random scenes have 14), not
    // touched: growing by doubling would hold two copies at the build's peak,
    // while untouched reserved pages cost no memory.
    std::vector<Waiting> swept;
    swept.reserve(std::min<std::size_t>(max_pieces + 1, std::size_t{16} * n));
    // The sweep's work is a few elements looked at a piece on scenes like the
    // benchmark's; far more means mirrors piled on one line (see sweep).
    const std::size_t work_limit = max_pieces < SIZE_MAX / 32 ? 16 * (max_pieces + n) : SIZE_MAX;
    for (unsigned d = 0; d < 2; ++d)
        if (!piece_sweep::sweep<Int>(
                n, box, d, crossings, work_limit, poll, [&](const piece_sweep::Swept<Int>& piece) {
                    swept.push_back(Waiting{layout_rank[piece.slot / 4] * 4 + piece.slot % 4,
                                            piece.next << 6 |
                                                static_cast<std::uint32_t>(piece.slope + 1) << 4 |
                                                std::uint32_t{piece.flip} << 2 | piece.kind,
                                            piece.from, piece.base});
                    return swept.size() <= max_pieces;
                }))
            return std::nullopt;
    crossings = {};
    layout_rank = {};
    const std::vector<std::uint32_t> start = piece_build::by_slot(swept, n * 4);
    for (std::uint32_t slot = 0; slot < n * 4; ++slot)
        std::sort(swept.begin() + start[slot], swept.begin() + start[slot + 1],
                  [](const Waiting& x, const Waiting& y) { return x.from < y.from; });

    // Exactly the room the pieces, their long slots' indexes and the search's
    // padding take: growing past a reservation would copy the array while
    // the waiting pieces are still held, at the build's peak.
    std::size_t room = swept.size() + piece_search_padding;
    for (std::uint32_t slot = 0; slot < n * 4; ++slot)
        if (const std::size_t count = start[slot + 1] - start[slot]; count > 8)
            room += (count + 7) / 8;
    table.slots_.resize(std::size_t{n} * 4);
    table.from_.reserve(room);
    table.hops_.reserve(room);
    for (std::uint32_t r = 0; r < n; ++r)
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            const std::uint32_t m = table.laid_out_[r];
            Cursor& range = table.slots_[m * 4 + d];
            range.begin = static_cast<std::uint32_t>(table.hops_.size());
            range.tangent = table.tangent_[m];
            for (std::uint32_t k = start[r * 4 + d]; k < start[r * 4 + d + 1]; ++k) {
                const Waiting& piece = swept[k];
                const unsigned kind = piece.map & 3u;
                Hop hop;
                hop.base = piece.base;
                hop.slope = static_cast<std::int8_t>(static_cast<int>((piece.map >> 4) & 3u) - 1);
                hop.bits =
                    static_cast<std::uint8_t>(((piece.map >> 2) & flip_mask) |
                                              (kind << kind_shift) | (kind == 0 ? 0u : stop_bit));
                // The mirror met, until the links below replace it by its pieces.
                hop.next_begin = piece.map >> 6;
                table.from_.push_back(piece.from);
                table.hops_.push_back(hop);
            }
            const std::size_t count = table.hops_.size() - range.begin;
            table.count_ += count;
            if (count > UINT16_MAX) return std::nullopt;
            range.count = static_cast<std::uint16_t>(count);
            // A long slot's index (locate_piece), with hops kept as long.
            table.hops_.resize(table.hops_.size() +
                               add_block_index(table.from_, range.begin, count));
        }
    swept = {}; // before the links: the build's largest temporary

    // Link each reflecting piece to the pieces the ray continues from.
    for (std::uint32_t m = 0; m < n; ++m)
        for (unsigned d = 0; d < 4; ++d)
            for (std::uint32_t k = table.slots_[m * 4 + d].begin,
                               end = k + table.slots_[m * 4 + d].count;
                 k < end; ++k) {
                Hop& hop = table.hops_[k];
                if (hop.kind() != Kind::reflect) {
                    hop.next_begin = 0; // no ray goes on from an escape or an absorber
                } else {
                    const Cursor next = table.at(hop.next_begin, d ^ (hop.bits & flip_mask));
                    hop.next_begin = next.begin;
                    hop.next_count = next.count;
                    if (next.tangent) hop.bits |= next_tangent_bit;
                }
            }
    // Room for the fixed-width searches to read past the last slot.
    table.from_.resize(table.hops_.size() + piece_search_padding, Int{});
    return table;
}

template <class Int>
template <class Visit>
void PieceTable<Int>::walk_back(const UniformGrid<Int, 2>& grid, const Int (&p)[2], unsigned d,
                                Visit&& visit) {
    Int q[2] = {p[0], p[1]};
    while (true) {
        const Shot<Int> back = grid.shoot_any(q, d ^ 3u);
        if (back.escape) return;
        q[0] = (d & 1u) ? Int(q[0] + back.t) : Int(q[0] - back.t);
        q[1] = (d & 2u) ? Int(q[1] + back.t) : Int(q[1] - back.t);
        if (visit(q)) return;
    }
}

template <class Int>
void PieceTable<Int>::mark_target(const UniformGrid<Int, 2>& grid, const Int (&target)[2],
                                  const lattice::SetupPoll& poll) {
    for (unsigned d = 0; d < 4; ++d)
        walk_back(grid, target, d, [&](const Int(&q)[2]) {
            poll();
            bool acted = false;
            grid.for_each_element_at(q, [&](std::uint32_t m) {
                if ((acting_[m] >> d) & 1u) acted = true;
                const Cursor where = at(m, d);
                if (where.count == 0) return; // an absorber: no ray leaves it
                Hop& hop = hops_[where.begin + locate(where, q[where.tangent])];
                hop.bits |= near_bit | stop_bit;
            });
            return acted;
        });
}

static_assert(sizeof(PieceTable<std::int64_t>::Cursor) == 8, "a cursor is meant to be 8 bytes");

} // namespace orthoray::shoot
