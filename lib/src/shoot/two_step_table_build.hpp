// Building the two-step tables (two_step_table.hpp): each piece of the
// piece table, imaged onto the mirror it reaches and cut there by that
// mirror's pieces, then each piece linked to the pieces the ray goes on from.
#pragma once

#include "shoot/two_step_table.hpp"

namespace orthoray::shoot {

template <class Int>
std::optional<TwoStepTable<Int>>
TwoStepTable<Int>::build(const PieceTable<Int>& table, const UniformGrid<Int, 2>& grid,
                         std::size_t max_pieces, const lattice::SetupPoll& poll) {
    using Single = PieceTable<Int>;
    TwoStepTable two(table);
    two.cursor_of_.assign(table.hops_.size() + 1, Cursor{});
    two.from_.reserve(2 * table.hops_.size());
    two.hops_.reserve(2 * table.hops_.size());
    // Slots in the piece table's order, so that the ray's next pieces lie
    // near as they do there (Z-order of the mirrors).
    for (const std::uint32_t m : table.laid_out_) {
        const ElementBox<Int, 2>& a = grid.element(m);
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            const Cursor single = table.at(m, d);
            Cursor slot{static_cast<std::uint32_t>(two.hops_.size()), 0, single.tangent};
            const std::size_t first = two.hops_.size();
            auto add = [&](const Int& from, const PairHop& hop) {
                // Stops need no more than one piece in a row: the glide
                // leaves them to the piece table, which knows why.
                if (two.hops_.size() > first && (hop.bits & stop_bit) &&
                    (two.hops_.back().bits & stop_bit))
                    return;
                two.from_.push_back(from);
                two.hops_.push_back(hop);
            };
            const std::uint32_t end = single.begin + single.count;
            for (std::uint32_t k = single.begin; k < end; ++k) {
                const typename Single::Hop& h = table.hops_[k];
                const Int lo = table.from_[k];
                if (h.bits & Single::stop_bit) {
                    PairHop stop;
                    stop.bits = stop_bit;
                    add(lo, stop);
                    continue;
                }
                const Int hi = k + 1 < end ? Int(table.from_[k + 1] - 1) : a.hi[single.tangent];
                // The position on B of the state at u on A: p' = p + t d on
                // B's tangent axis. Parallel mirrors keep t fixed (slope 0)
                // and move u' with u; a perpendicular B takes u' from t
                // alone, with slope ±1: either way u' = image(lo) + alpha (u - lo).
                const Cursor next = h.next();
                const auto image = [&](const Int& u) {
                    Int p[2] = {a.lo[0], a.lo[1]};
                    p[single.tangent] = u;
                    const Int t = h.base + Int(h.slope) * u;
                    const Int& q = p[next.tangent];
                    return ((d >> next.tangent) & 1u) ? Int(q - t) : Int(q + t);
                };
                const Int at_lo = image(lo), at_hi = image(hi);
                const bool rising = !(at_hi < at_lo);
                const Int& v_lo = rising ? at_lo : at_hi;
                const Int& v_hi = rising ? at_hi : at_lo;
                // B's pieces over [v_lo, v_hi]; each gives the part of [lo, hi]
                // imaged into it, in the order of u.
                const std::uint32_t j_lo = next.begin + table.locate(next, v_lo),
                                    j_hi = next.begin + table.locate(next, v_hi);
                for (std::uint32_t i = 0; i <= j_hi - j_lo; ++i) {
                    const std::uint32_t j = rising ? j_lo + i : j_hi - i;
                    // The first u of this part: the image of its lowest
                    // v when rising, of its highest when falling.
                    Int from = lo;
                    if (rising && j != j_lo) from = Int(lo + (table.from_[j] - at_lo));
                    if (!rising && j != j_hi) from = Int(lo + (at_lo - (table.from_[j + 1] - 1)));
                    const typename Single::Hop& g = table.hops_[j];
                    PairHop hop;
                    if (g.bits & Single::stop_bit) {
                        hop.bits = stop_bit;
                    } else {
                        hop.base1 = h.base;
                        hop.slope1 = h.slope;
                        hop.base2 = g.base;
                        hop.slope2 = g.slope;
                        hop.bits = static_cast<std::uint8_t>(
                            (h.bits & flip_mask) | (g.bits & flip_mask) << 2 |
                            (next.tangent ? mid_tangent_bit : 0) |
                            ((g.bits & Single::next_tangent_bit) ? next_tangent_bit : 0));
                        hop.single_begin = g.next_begin;
                        hop.single_count = g.next_count;
                    }
                    add(from, hop);
                }
            }
            const std::size_t count = two.hops_.size() - first;
            two.count_ += count;
            if (two.count_ > max_pieces || count > UINT16_MAX) return std::nullopt;
            slot.count = static_cast<std::uint16_t>(count);
            if (single.count) two.cursor_of_[single.begin] = slot;
            two.hops_.resize(two.hops_.size() + add_block_index(two.from_, first, count));
        }
    }
    // Link each plain piece to the two-step pieces of the mirror it reaches.
    for (PairHop& hop : two.hops_)
        if (!(hop.bits & stop_bit) && hop.single_count) {
            const Cursor next = two.cursor_of_[hop.single_begin];
            hop.next_begin = next.begin;
            hop.next_count = next.count;
        }
    two.from_.resize(two.hops_.size() + piece_search_padding, Int{});
    return two;
}

} // namespace orthoray::shoot
