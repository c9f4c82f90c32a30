// 2D piece tables: the first-return map of the ray on the mirrors, as an
// interval exchange.
//
// In lattice coordinates (lattice_scene.hpp) the ray is diagonal. Fix one of
// the four directions d = (sx, sy) in {±1}^2 and a mirror A; a state on A is
// its position u (y on a vertical mirror, x on a horizontal one). As u runs
// along A, the line the ray follows shifts, and the next element met only
// changes where that line passes an *event*: an element's endpoint or the
// crossing of two elements. Between two such u the next hit is one element B
// at a parameter t that is affine in u, t(u) = t0 + slope * (u - u0) with
// slope in {-1, 0, 1}, and the point reached moves along B by a translation
// (with a flip when A and B are perpendicular). So the map "position on A ->
// (next mirror, position there)" is piecewise a translation: over all
// (A, d) it is an interval exchange with flips, and with holes where the ray
// escapes or is absorbed. A reflection is then a fixed-width count among A's
// few pieces plus a few additions (docs/piece-tables.md, "How a reflection
// reads them").
//
// Building (piece_sweep.hpp). For each pair of opposite directions one
// sweep visits the ray's lines in order, keeping the elements that meet the
// current line sorted along it. A mirror's next element is its neighbour
// there (the next one acting on the direction), and the order only changes
// on the lines through an event: an element's first or last line, or the
// line of a crossing. So a mirror's map is recomputed only on those lines,
// and only for the mirrors between the event and the nearest acting element
// before it; each run of lines with one map is one piece. No shot is taken.
//
// One-sided elements. The map of direction d only knows the elements that
// act on d: the sweep keeps every element on the line (each mirror has its
// slots), but a mirror's next element is the first one beyond it that acts
// on d, and the rays pass the others unseen.
#pragma once

#include "shoot/piece_search.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <optional>
#include <type_traits>
#include <vector>

namespace orthoray::shoot {

template <class Int>
class TwoStepTable;

template <class Int>
class PieceTable {
public:
    enum class Kind : std::uint8_t { reflect, escape, absorb };

    // Where the ray is: the pieces of one (mirror, direction), and the axis
    // positions on that mirror run along.
    struct Cursor {
        std::uint32_t begin = 0;
        std::uint16_t count = 0; // a slot with more pieces makes the build give up
        std::uint8_t tangent = 0;
    };

    // A piece as the exchange builder and the dump read it: from position
    // `from` on, the next hit is at t = t0 + slope * (u - from).
    struct Piece {
        Int from, t0;
        unsigned flip = 0; // normal axes of the mirrors met there
        Kind kind_ = Kind::escape;
        int slope_ = 0;
        Kind kind() const { return kind_; }
        int slope() const { return slope_; }
    };

    // The pieces of one (mirror, direction), read one at a time.
    class Range {
    public:
        Range(const PieceTable& table, Cursor c) : table_(&table), c_(c) {}
        std::size_t size() const { return c_.count; }
        Piece operator[](std::size_t i) const { return table_->piece(c_.begin + i); }

    private:
        const PieceTable* table_;
        Cursor c_;
    };

    // std::nullopt when the tables would need more than max_pieces pieces
    // (many crossings can make them quadratic in the number of mirrors).
    // `poll` is called once an element, an event and a slot, and on GMP
    // integers once a piece (it may throw lattice::SetupStopped).
    // Defined in piece_table_build.hpp.
    static std::optional<PieceTable> build(const UniformGrid<Int, 2>& grid, std::size_t max_pieces,
                                           const lattice::SetupPoll& poll = {});

    // The pieces of mirror `element` for leaving it in direction `negative`
    // (bit i set: moving towards -infinity on axis i), sorted by `from`.
    Range pieces(std::uint32_t element, unsigned negative) const {
        return {*this, slots_[element * 4 + negative]};
    }

    // The pieces for leaving mirror `element` in direction `negative`.
    Cursor at(std::uint32_t element, unsigned negative) const {
        return slots_[element * 4 + negative];
    }

    // The next hit from point p, as the grid would give it; `where` must
    // describe p's mirror and the direction, and moves on to the mirror hit
    // (for the direction after reflecting there).
    Shot<Int> shoot(const Int (&p)[2], Cursor& where) const {
        const Int& u = p[where.tangent];
        const Hop& hop = hops_[where.begin + locate(where, u)];
        const Kind kind = hop.kind();
        Shot<Int> shot;
        shot.escape = kind == Kind::escape;
        shot.absorber = kind == Kind::absorb;
        shot.flip = hop.bits & flip_mask;
        shot.near_target = (hop.bits & near_bit) != 0;
        shot.t = hop.base + Int(hop.slope) * u;
        where = hop.next();
        return shot;
    }

    // The same, entering at mirror `element`, and naming a mirror met when
    // the ray reflects (for tests and the dump; the engine keeps a cursor).
    Shot<Int> shoot(const Int (&p)[2], unsigned negative, std::uint32_t element) const {
        Cursor where = at(element, negative);
        const Hop& hop = hops_[where.begin + locate(where, p[where.tangent])];
        Shot<Int> shot = shoot(p, where);
        if (hop.kind() == Kind::reflect) shot.mirror = next_mirror(hop);
        return shot;
    }

    // The stepper's fast path: reflects the state (p, negative), on the
    // mirror `where` describes, for as long as the pieces met reflect and no
    // target is near (Shot::near_target), at most `limit` times, and stops
    // before a reflection that would lead back to the state (first,
    // first_negative), which the cycle detector must see. Returns the
    // reflections taken; p, negative and where have moved on with them. The
    // state lives in locals (registers) and a piece is used as stored, with
    // no fields to decode, so a reflection is one search, a multiply-add
    // and two conditional negations.
    std::uint64_t glide(Int (&p)[2], unsigned& negative, Cursor& where, std::uint64_t limit,
                        const Int (&first)[2], unsigned first_negative) const {
        Int x = p[0], y = p[1];
        unsigned neg = negative;
        Cursor at = where;
        // The position the search needs is chosen when the hop is at hand,
        // not from the cursor at the next step: the compiler kept the
        // cursor's axis in memory, a store and a load more on the chain.
        Int u = at.tangent ? y : x;
        std::uint64_t taken = 0;
        for (; taken < limit; ++taken) {
            const Hop& hop = hops_[at.begin + locate(at, u)];
            if (hop.bits & stop_bit) break;
            const Int t = hop.base + Int(hop.slope) * u;
            const Int nx = (neg & 1u) ? Int(x - t) : Int(x + t);
            const Int ny = (neg & 2u) ? Int(y - t) : Int(y + t);
            const unsigned nneg = neg ^ (hop.bits & flip_mask);
            if (nx == first[0] && ny == first[1] && nneg == first_negative) break;
            x = nx;
            y = ny;
            neg = nneg;
            at = hop.next();
            u = (hop.bits & next_tangent_bit) ? y : x;
            // The next hop is in this line or the next (a short slot is at
            // most 128 bytes of hops): fetched while its positions are
            // searched, not after.
            __builtin_prefetch(hops_.data() + at.begin);
            __builtin_prefetch(hops_.data() + at.begin + 4);
        }
        p[0] = x;
        p[1] = y;
        negative = neg;
        where = at;
        return taken;
    }

    std::size_t size() const { return count_; }

    // Marks the pieces holding the states after which the ray passes
    // `target`: for each direction d, the segment through the target in
    // direction d starts where a shot from the target in direction -d first
    // meets the mirrors, so at most four points on a few mirrors. Every
    // other piece's segments miss the target, and Shot::near_target says so.
    void mark_target(const UniformGrid<Int, 2>& grid, const Int (&target)[2],
                     const lattice::SetupPoll& poll = {});

    // A piece as the dump shows it: on mirror `element` leaving in direction
    // `negative`, the positions from `from` on (to the next row's) go to
    // mirror `next` (reflect; 0 otherwise), or nowhere (escape), or stop
    // (absorb), with
    // the hit at t = t0 + slope * (u - from), reflecting on the axes `flip`.
    struct Row {
        std::uint32_t element = 0;
        unsigned negative = 0;
        Integer from, t0;
        Kind kind = Kind::escape;
        std::uint32_t next = 0;
        int slope = 0;
        unsigned flip = 0;
    };
    // Calls visit(row) for every piece, by mirror, direction and position.
    template <class Visit>
    void for_each_row(Visit&& visit) const {
        for (std::uint32_t m = 0; m < tangent_.size(); ++m)
            for (unsigned d = 0; d < 4; ++d) {
                const Cursor c = at(m, d);
                for (std::uint32_t k = c.begin; k < c.begin + c.count; ++k) {
                    const Piece p = piece(k);
                    const std::uint32_t next =
                        p.kind() == Kind::reflect ? next_mirror(hops_[k]) : 0;
                    visit(Row{m, d, to_integer(p.from), to_integer(p.t0), p.kind(), next, p.slope(),
                              p.flip});
                }
            }
    }

private:
    // Composes this table with itself from its pieces as stored.
    friend class TwoStepTable<Int>;

    // What a reflection reads of a piece, ready to use: 16 bytes on int64.
    // The hit is at t = base + slope * u (base = t0 - slope * from: |base|
    // <= 3B, so t stays within lattice_int.hpp's 8B), and the next mirror's
    // pieces are inline, so a step needs no other lookup.
    struct Hop {
        Int base{};
        std::uint32_t next_begin = 0;
        std::uint16_t next_count = 0;
        std::int8_t slope = 0; // -1, 0 or 1
        std::uint8_t bits = 0; // flip_mask | next_tangent_bit | stop_bit | near_bit | kind
        Cursor next() const {
            return {next_begin, next_count,
                    static_cast<std::uint8_t>((bits & next_tangent_bit) ? 1 : 0)};
        }
        Kind kind() const { return static_cast<Kind>((bits >> kind_shift) & 3u); }
    };
    static constexpr std::uint8_t
        flip_mask = 3,
        next_tangent_bit = 4,
        stop_bit = 8,  // not a plain reflection: escape, absorb or near the target
        near_bit = 16; // a state here starts a segment through the target
    static constexpr unsigned kind_shift = 5; // bits 5-6: a Kind
    static_assert(!std::is_same_v<Int, std::int64_t> || sizeof(Hop) == 16,
                  "a piece is meant to be 16 bytes of hop and 8 of position on int64");

    Piece piece(std::size_t k) const {
        const Hop& h = hops_[k];
        return {from_[k], Int(h.base + Int(h.slope) * from_[k]),
                static_cast<unsigned>(h.bits & flip_mask), h.kind(), h.slope};
    }

    // The mirror a reflecting hop goes on to (cold: tests and the dump read
    // it; the build keeps no array of them, 4 bytes a piece). Its cursor
    // starts that mirror's slot, and slots are laid out by laid_out_ rank and
    // direction, so their starts ascend in that order: the slot is the last
    // one starting at or before the cursor (an absorber's slots are empty
    // and start where the next one does; a mirror's never are).
    std::uint32_t next_mirror(const Hop& hop) const {
        auto start_of = [&](std::size_t k) { return slots_[laid_out_[k / 4] * 4 + k % 4].begin; };
        std::size_t lo = 0, hi = laid_out_.size() * 4; // start_of(lo) <= cursor < start_of(hi)
        while (hi - lo > 1) {
            const std::size_t mid = (lo + hi) / 2;
            (hop.next_begin < start_of(mid) ? hi : lo) = mid;
        }
        return laid_out_[lo / 4];
    }

    // The piece holding position u, counted from the slot's first
    // (piece_search.hpp).
    std::uint32_t locate(const Cursor& where, const Int& u) const {
        return locate_piece(from_.data() + where.begin, where.count, u);
    }

    std::size_t count_ = 0;               // pieces (the arrays also hold long slots' indexes)
    std::vector<Int> from_;               // per piece: its first position (+ padding)
    std::vector<Hop> hops_;               // per piece: what a reflection there does
    std::vector<std::uint32_t> laid_out_; // the elements in the order their slots are laid out
    std::vector<Cursor> slots_;           // (element * 4 + direction) -> its pieces
    std::vector<std::uint8_t> tangent_;   // the axis a position on the element runs along
    std::vector<std::uint8_t> acting_;    // LatticeElement::acting, per element

    // From p backwards along direction d: calls visit(q) at each point q
    // where the reverse ray meets some element (of any side), nearest first,
    // until visit returns true (q holds an element acting on d, which hides
    // what lies behind it from rays in direction d) or the ray leaves.
    template <class Visit>
    static void walk_back(const UniformGrid<Int, 2>& grid, const Int (&p)[2], unsigned d,
                          Visit&& visit);
};

} // namespace orthoray::shoot

#include "shoot/piece_table_build.hpp"
