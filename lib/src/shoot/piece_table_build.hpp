// Building the piece tables (piece_table.hpp): the pieces of every slot from
// the sweeps (piece_sweep.hpp), counted by slot, then each written once into
// its place in the tables' layout, linked to the next mirror's pieces.
#pragma once

#include "shoot/piece_sweep.hpp"
#include "shoot/piece_table.hpp"

namespace orthoray::shoot {

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
        piece_sweep::sort_by_key(order.begin(), order.end(), [](const auto& x) { return x.first; });
        table.laid_out_.resize(n);
        for (std::uint32_t r = 0; r < n; ++r) table.laid_out_[r] = order[r].second;
    }
    std::vector<std::uint32_t> layout_rank(n);
    for (std::uint32_t r = 0; r < n; ++r) layout_rank[table.laid_out_[r]] = r;

    // Every slot's pieces, one sweep a pair of opposite directions at a
    // time, each counted in its slot (numbered in layout order: the sweep
    // names each element by its layout rank). A piece waits in 24 bytes on
    // int64, its map packed beside the next mirror (which therefore takes
    // 26 bits).
    if (n >= (std::uint32_t{1} << 26)) return std::nullopt;
    struct Waiting {
        std::uint32_t slot; // layout slot << 1 | its pieces come falling
        std::uint32_t map;  // next << 6 | (slope + 1) << 4 | flip << 2 | kind
        Int from, base;
    };
    // Reserved for 16 a mirror (the benchmark's random scenes have 14), not
    // touched: growing by doubling would hold two copies at the build's peak,
    // while untouched reserved pages cost no memory.
    std::vector<Waiting> swept;
    swept.reserve(std::min<std::size_t>(max_pieces + 1, std::size_t{16} * n));
    std::vector<std::uint32_t> place(std::size_t{n} * 4, 0); // pieces a slot, then its cursor
    // The sweep's work is a few elements looked at a piece on scenes like the
    // benchmark's; far more means mirrors piled on one line (see sweep).
    const std::size_t work_limit = max_pieces < SIZE_MAX / 32 ? 16 * (max_pieces + n) : SIZE_MAX;
    for (unsigned d = 0; d < 2; ++d)
        if (!piece_sweep::sweep<Int>(
                n, box, [&layout_rank](std::uint32_t e) { return layout_rank[e]; }, d, crossings,
                work_limit, poll,
                [&](const piece_sweep::Swept<Int>& piece) {
                    ++place[piece.slot];
                    swept.push_back(Waiting{piece.slot << 1 | std::uint32_t{piece.falling},
                                            piece.next << 6 |
                                                static_cast<std::uint32_t>(piece.slope + 1) << 4 |
                                                std::uint32_t{piece.flip} << 2 | piece.kind,
                                            piece.from, piece.base});
                    return swept.size() <= max_pieces;
                }))
            return std::nullopt;
    crossings = {};
    layout_rank = {};

    // Where each slot goes: slots in layout order, each followed by its
    // index when it is long (locate_piece). So every cursor is known before
    // any piece is placed, and a piece is written once, link and all: at the
    // slot's next place, or its previous one where the sweep found the
    // slot's pieces in falling order (the sweep of d also serves d ^ 3).
    table.slots_.resize(std::size_t{n} * 4);
    std::size_t room = 0;
    for (std::uint32_t r = 0; r < n; ++r)
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            const std::uint32_t count = place[r * 4 + d];
            if (count > UINT16_MAX || room > UINT32_MAX - 2 * std::size_t{count})
                return std::nullopt;
            const std::uint32_t m = table.laid_out_[r];
            table.slots_[m * 4 + d] = Cursor{static_cast<std::uint32_t>(room),
                                             static_cast<std::uint16_t>(count), table.tangent_[m]};
            const bool falling = piece_sweep::falls(d == 0 || d == 3 ? 0 : 1, box(m).axis == 0);
            place[r * 4 + d] = static_cast<std::uint32_t>(falling ? room + count : room);
            room += count + block_index_size(count);
        }
    table.count_ = swept.size();
    // Exactly the room the pieces, their long slots' indexes and the search's
    // padding take, allocated while the waiting pieces are held (the build's
    // peak).
    table.from_.resize(room + piece_search_padding);
    table.hops_.resize(room);

    // Each piece to its place, in the order the sweep found them, and
    // linked to the pieces the ray continues from.
    for (std::size_t i = 0; i < swept.size(); ++i) {
        // The places a piece further on writes and the cursor it reads are
        // scattered over the tables: fetched ahead (hints only, so a place
        // that moves on meanwhile costs nothing but the hint).
        if (i + 16 < swept.size()) {
            const Waiting& ahead = swept[i + 16];
            const std::uint32_t to = place[ahead.slot >> 1];
            __builtin_prefetch(table.hops_.data() + std::min<std::size_t>(to, room - 1), 1);
            __builtin_prefetch(table.from_.data() + to, 1);
            __builtin_prefetch(table.slots_.data() + (ahead.map >> 6) * 4);
        }
        const Waiting& piece = swept[i];
        poll.on_gmp<Int>();
        std::uint32_t& at = place[piece.slot >> 1];
        const std::uint32_t k = (piece.slot & 1u) ? --at : at++;
        const unsigned kind = piece.map & 3u, flip = (piece.map >> 2) & flip_mask;
        Hop& hop = table.hops_[k];
        hop.base = piece.base;
        hop.slope = static_cast<std::int8_t>(static_cast<int>((piece.map >> 4) & 3u) - 1);
        hop.bits =
            static_cast<std::uint8_t>(flip | (kind << kind_shift) | (kind == 0 ? 0u : stop_bit));
        if (kind == 0) { // a reflection: the ray goes on from the next mirror's slot
            const Cursor next = table.at(piece.map >> 6, ((piece.slot >> 1) % 4) ^ flip);
            hop.next_begin = next.begin;
            hop.next_count = next.count;
            if (next.tangent) hop.bits |= next_tangent_bit;
        }
        table.from_[k] = piece.from;
    }
    swept = {};

    // Each slot in order (the sweep's promise, checked: a slot out of order
    // would send rays astray), and the long ones indexed.
    for (std::uint32_t r = 0; r < n * 4; ++r) {
        poll();
        // A mirror's four cursors share a line, scattered over slots_.
        if (r % 4 == 0 && r / 4 + 8 < n)
            __builtin_prefetch(table.slots_.data() + table.laid_out_[r / 4 + 8] * 4);
        const Cursor slot = table.slots_[table.laid_out_[r / 4] * 4 + r % 4];
        Int* from = table.from_.data() + slot.begin;
        for (std::uint32_t k = 1; k < slot.count; ++k)
            if (!(from[k - 1] < from[k]))
                throw std::logic_error("piece tables: a slot's pieces are out of order");
        write_block_index(from, slot.count);
    }
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
