// 2D two-step tables: the piece tables' map composed with itself, so that
// one search and one load take the ray two reflections on.
//
// The piece tables (piece_table.hpp) store the first-return map T of each
// (mirror, direction) as pieces, each a translation (possibly flipped) onto
// the next mirror. T∘T is again piecewise a translation: on a piece P of T
// from mirror A onto mirror B, the position on B is u' = ±u + c, so T∘T
// there is cut only where u' passes a first position of B's pieces. Where T
// is injective (two-sided elements, the only scenes the engine glides on:
// one-sided ones take Brent's detector), each first position has at most
// one preimage, so T∘T has at most about twice T's pieces (counted on the
// benchmark's random scenes: 1.64x at 10^2 to 10^4 mirrors); the build's
// cap bounds it elsewhere.
//
// A two-step piece keeps both steps' maps (t1 = base1 + slope1 u on A, and
// t2 = base2 + slope2 u' on B) rather than their composition: the state
// between the two is needed anyway, for the cycle check against the first
// state, and t2 from u' stays within the bounds of lattice_int.hpp, where a
// composed base would not. What a lookup saves is the second search and
// its load, the two dependent memory accesses on a reflection's chain.
//
// A two-step piece is a *stop* when either step is one in T (an escape, an
// absorber, a target near): there the glide takes single steps on T, which
// stop where T's own glide would. The answer is the same reflection by
// reflection; only the number of lookups changes.
#pragma once

#include "shoot/piece_search.hpp"
#include "shoot/piece_table.hpp"

#include <optional>
#include <vector>

namespace orthoray::shoot {

template <class Int>
class TwoStepTable {
public:
    using Cursor = typename PieceTable<Int>::Cursor;

    // The two-step pieces of `table` (after its targets are marked:
    // PieceTable::mark_target), or std::nullopt past max_pieces pieces or
    // 2^16 - 1 in one slot. `poll` is called once a slot (it may throw
    // lattice::SetupStopped).
    static std::optional<TwoStepTable> build(const PieceTable<Int>& table,
                                             const UniformGrid<Int, 2>& grid,
                                             std::size_t max_pieces,
                                             const lattice::SetupPoll& poll = {});

    std::size_t size() const { return count_; }

    // PieceTable::glide's contract, on the same cursor `where` into `table`:
    // the same reflections, stopping at the same state. Two reflections a
    // lookup while they are plain; single steps on the piece table around
    // a stop, before the first state and at an odd limit.
    std::uint64_t glide(Int (&p)[2], unsigned& negative, Cursor& where, std::uint64_t limit,
                        const Int (&first)[2], unsigned first_negative) const {
        Int x = p[0], y = p[1];
        unsigned neg = negative;
        Cursor single = where;
        Cursor pair = cursor_of_[single.begin];
        Int u = single.tangent ? y : x;
        std::uint64_t taken = 0;
        while (taken < limit) {
            if (limit - taken >= 2) {
                const PairHop& hop = hops_[pair.begin + locate(pair, u)];
                if (!(hop.bits & stop_bit)) {
                    const Int t1 = hop.base1 + Int(hop.slope1) * u;
                    const Int mx = (neg & 1u) ? Int(x - t1) : Int(x + t1);
                    const Int my = (neg & 2u) ? Int(y - t1) : Int(y + t1);
                    const unsigned mneg = neg ^ (hop.bits & flip_mask);
                    const Int t2 =
                        hop.base2 + Int(hop.slope2) * ((hop.bits & mid_tangent_bit) ? my : mx);
                    const Int nx = (mneg & 1u) ? Int(mx - t2) : Int(mx + t2);
                    const Int ny = (mneg & 2u) ? Int(my - t2) : Int(my + t2);
                    const unsigned nneg = mneg ^ ((hop.bits >> 2) & flip_mask);
                    const bool back =
                        (mx == first[0] && my == first[1] && mneg == first_negative) ||
                        (nx == first[0] && ny == first[1] && nneg == first_negative);
                    if (!back) {
                        x = nx;
                        y = ny;
                        neg = nneg;
                        taken += 2;
                        pair = hop.next();
                        single = hop.next_single();
                        u = (hop.bits & next_tangent_bit) ? y : x;
                        __builtin_prefetch(hops_.data() + pair.begin);
                        __builtin_prefetch(hops_.data() + pair.begin + 2);
                        continue;
                    }
                }
            }
            // One step on the piece table: it stops where this glide must.
            Int q[2] = {x, y};
            if (table_->glide(q, neg, single, 1, first, first_negative) == 0) break;
            x = q[0];
            y = q[1];
            ++taken;
            pair = cursor_of_[single.begin];
            u = single.tangent ? y : x;
        }
        p[0] = x;
        p[1] = y;
        negative = neg;
        where = single;
        return taken;
    }

private:
    explicit TwoStepTable(const PieceTable<Int>& table) : table_(&table) {}

    // Two reflections from a position on A: t1 = base1 + slope1 u to B,
    // then t2 = base2 + slope2 u' on B (u' the position there), and the
    // pieces of the mirror reached, both here (next) and in the piece table
    // (next_single). 32 bytes on int64.
    struct PairHop {
        Int base1{}, base2{};
        std::uint32_t next_begin = 0;
        std::uint16_t next_count = 0;
        // flip 1 | flip 2 << 2 | mid_tangent_bit | next_tangent_bit | stop_bit
        std::uint8_t bits = 0;
        std::int8_t slope1 = 0;
        std::uint32_t single_begin = 0;
        std::uint16_t single_count = 0;
        std::int8_t slope2 = 0;
        Cursor next() const {
            return {next_begin, next_count,
                    static_cast<std::uint8_t>((bits & next_tangent_bit) ? 1 : 0)};
        }
        Cursor next_single() const {
            return {single_begin, single_count,
                    static_cast<std::uint8_t>((bits & next_tangent_bit) ? 1 : 0)};
        }
    };
    // mid_tangent_bit: the position on B runs along y; next_tangent_bit: so
    // does the position on the mirror reached.
    static constexpr std::uint8_t flip_mask = 3, mid_tangent_bit = 16, next_tangent_bit = 32,
                                  stop_bit = 64;
    static_assert(!std::is_same_v<Int, std::int64_t> || sizeof(PairHop) == 32,
                  "a two-step piece is meant to be 32 bytes of hop on int64");

    std::uint32_t locate(const Cursor& where, const Int& u) const {
        return locate_piece(from_.data() + where.begin, where.count, u);
    }

    const PieceTable<Int>* table_;
    std::size_t count_ = 0;     // pieces (the arrays also hold long slots' indexes)
    std::vector<Int> from_;     // per piece: its first position (+ padding)
    std::vector<PairHop> hops_; // per piece: what two reflections there do
    // The two-step pieces of the slot whose piece-table pieces start at k,
    // for every slot start k of `table` (where a glide enters).
    std::vector<Cursor> cursor_of_;
};

} // namespace orthoray::shoot

#include "shoot/two_step_table_build.hpp"
