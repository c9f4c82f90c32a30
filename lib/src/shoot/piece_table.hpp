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
// escapes or is absorbed. A reflection is then one binary search in A's few
// pieces plus a few additions.
//
// Building. The breakpoints of (A, d) are (1) the positions on A of every
// event lying on A (its ends, crossings on it) and (2) the positions on A
// from which the ray in direction d reaches an event first: found by shooting
// from each event in the reverse direction with the exact grid. Every other u
// has an open neighbourhood with the same next element, flip and affine t,
// since the first element above A along the lines can only change at a vertex
// of that lower envelope, and those vertices are visible events. Each piece
// (a breakpoint itself, or an open run between two) is resolved with one
// forward grid shot; adjacent pieces with the same map are merged.
//
// One-sided elements. The map of direction d only knows the elements that
// act on d (the grid's per-direction lists), so only their ends and
// crossings can change it, and the reverse shot from such an event must find
// every mirror whose rays in direction d reach it: it goes on through the
// elements that do not act on d (a one-way mirror the ray leaves in d is
// one of them; its rays pass the mirrors behind it unseen) and stops at the
// first that does, which hides everything behind it.
#pragma once

#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <vector>

namespace orthoray::shoot {

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

    // 24 bytes with 64-bit integers: every reflection loads one, and at 10^5
    // mirrors the tables are far larger than the cache, so size is speed.
    struct Piece {
        Int from; // first position on the mirror this piece covers
        Int t0;   // the next hit's parameter at u = from
        // After reflecting here: the next mirror's pieces for the new
        // direction, stored inline so that a step needs no other lookup.
        std::uint32_t next_begin = 0;
        std::uint16_t next_count = 0;
        std::uint8_t next_tangent : 1 = 0;
        std::uint8_t near_target : 1 = 0; // a state here starts a segment through the target
        std::uint8_t flip : 2 = 0;        // normal axes of the mirrors met there
        std::uint8_t kind_code : 2 = 0;   // a Kind
        std::uint8_t slope_code : 2 = 1;  // slope + 1: t(u) = t0 + slope * (u - from)

        Kind kind() const { return static_cast<Kind>(kind_code); }
        int slope() const { return static_cast<int>(slope_code) - 1; }
        Cursor next() const { return {next_begin, next_count, next_tangent}; }
    };

    // std::nullopt when the tables would need more than max_pieces pieces
    // (many crossings can make them quadratic in the number of mirrors).
    // `poll` is called once an element, an event and a slot, and on GMP
    // integers once a piece (it may throw lattice::SetupStopped).
    static std::optional<PieceTable> build(const LatticeScene& scene,
                                           const UniformGrid<Int, 2>& grid, std::size_t max_pieces,
                                           const lattice::SetupPoll& poll = {});

    // The pieces of mirror `element` for leaving it in direction `negative`
    // (bit i set: moving towards -infinity on axis i), sorted by `from`.
    std::span<const Piece> pieces(std::uint32_t element, unsigned negative) const {
        const Cursor& c = slots_[element * 4 + negative];
        return {pieces_.data() + c.begin, c.count};
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
        const Piece& piece = *locate(where, u);
        Shot<Int> shot;
        shot.escape = piece.kind() == Kind::escape;
        shot.absorber = piece.kind() == Kind::absorb;
        shot.flip = piece.flip;
        shot.near_target = piece.near_target;
        shot.t = piece.t0 + Int(piece.slope()) * Int(u - piece.from);
        where = piece.next();
        return shot;
    }

    // The same, entering at mirror `element`, and naming a mirror met (for
    // tests and the dump; the engine keeps a cursor instead).
    Shot<Int> shoot(const Int (&p)[2], unsigned negative, std::uint32_t element) const {
        Cursor where = at(element, negative);
        const std::size_t k =
            static_cast<std::size_t>(locate(where, p[where.tangent]) - pieces_.data());
        Shot<Int> shot = shoot(p, where);
        shot.mirror = next_mirror_[k];
        return shot;
    }

    std::size_t size() const { return pieces_.size(); }

    // Marks the pieces holding the states after which the ray passes
    // `target`: for each direction d, the segment through the target in
    // direction d starts where a shot from the target in direction -d first
    // meets the mirrors, so at most four points on a few mirrors. Every
    // other piece's segments miss the target, and Shot::near_target says so.
    void mark_target(const UniformGrid<Int, 2>& grid, const Int (&target)[2],
                     const lattice::SetupPoll& poll = {});

    // A piece as the dump shows it: on mirror `element` leaving in direction
    // `negative`, the positions from `from` on (to the next row's) go to
    // mirror `next` (reflect), or nowhere (escape), or stop (absorb), with
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
            for (unsigned d = 0; d < 4; ++d)
                for (const Piece& p : pieces(m, d))
                    visit(Row{m, d, to_integer(p.from), to_integer(p.t0), p.kind(),
                              next_mirror_[static_cast<std::size_t>(&p - pieces_.data())],
                              p.slope(), p.flip});
    }

private:
    // The piece holding position u: the last one of the range
    // starting at or before u. A mirror has a handful of pieces, so counting
    // them without branches beats a binary search, whose jumps the processor
    // cannot predict.
    const Piece* locate(const Cursor& where, const Int& u) const {
        const Piece* range = pieces_.data() + where.begin;
        std::uint32_t k = 0;
        if (where.count <= 8) {
            for (std::uint32_t i = 1; i < where.count; ++i) k += !(u < range[i].from);
        } else {
            k = static_cast<std::uint32_t>(
                std::upper_bound(range, range + where.count, u,
                                 [](const Int& x, const Piece& piece) { return x < piece.from; }) -
                range - 1);
        }
        return range + k;
    }

    std::vector<Piece> pieces_;
    std::vector<std::uint32_t> next_mirror_; // per piece: a mirror met (cold: tests, dump)
    std::vector<Cursor> slots_;              // (element * 4 + direction) -> its pieces
    std::vector<std::uint8_t> tangent_;      // the axis a position on the element runs along
    std::vector<std::uint8_t> acting_;       // LatticeElement::acting, per element

    // From p backwards along direction d: calls visit(q) at each point q
    // where the reverse ray meets some element (of any side), nearest first,
    // until visit returns true (q holds an element acting on d, which hides
    // what lies behind it from rays in direction d) or the ray leaves.
    template <class Visit>
    static void walk_back(const UniformGrid<Int, 2>& grid, const Int (&p)[2], unsigned d,
                          Visit&& visit);
};

template <class Int>
std::optional<PieceTable<Int>>
PieceTable<Int>::build(const LatticeScene& scene, const UniformGrid<Int, 2>& grid,
                       std::size_t max_pieces, const lattice::SetupPoll& poll) {
    const auto& elements = scene.elements;
    const std::uint32_t n = static_cast<std::uint32_t>(elements.size());
    struct Box {
        Int lo[2], hi[2];
        int axis;
        bool absorber;
        unsigned acting; // LatticeElement::acting
    };
    std::vector<Box> box(n);
    for (std::uint32_t e = 0; e < n; ++e) {
        poll();
        for (int j = 0; j < 2; ++j) {
            box[e].lo[j] = from_integer<Int>(elements[e].lo[j]);
            box[e].hi[j] = from_integer<Int>(elements[e].hi[j]);
        }
        box[e].axis = elements[e].axis;
        box[e].absorber = elements[e].absorber;
        box[e].acting = elements[e].acting;
    }

    // Events: every element's two ends, and every crossing of a vertical and
    // a horizontal element (T-junctions and corners included).
    using Point = std::array<Int, 2>;
    std::vector<Point> events;
    for (const Box& b : box) {
        const int t = 1 - b.axis;
        Point p{b.lo[0], b.lo[1]};
        events.push_back(p);
        p[t] = b.hi[t];
        events.push_back(p);
    }
    for (std::uint32_t e = 0; e < n; ++e) {
        poll();
        if (box[e].axis != 0) continue;
        grid.for_each_neighbour(e, [&](std::uint32_t f) {
            const Box &v = box[e], &h = box[f];
            if (h.axis != 1) return;
            if (h.lo[0] <= v.lo[0] && v.lo[0] <= h.hi[0] && v.lo[1] <= h.lo[1] &&
                h.lo[1] <= v.hi[1])
                events.push_back(Point{v.lo[0], h.lo[1]});
        });
    }
    // Events in Z-order of their grid cells: consecutive reverse shots then
    // walk nearby cells, which matters once the grid outgrows the cache.
    {
        std::vector<std::pair<std::uint64_t, Point>> keyed;
        keyed.reserve(events.size());
        for (const Point& p : events) {
            poll();
            const Int q[2] = {p[0], p[1]};
            keyed.emplace_back(grid.locality_key(q), p);
        }
        std::sort(keyed.begin(), keyed.end());
        keyed.erase(std::unique(keyed.begin(), keyed.end()), keyed.end());
        events.clear();
        for (auto& [key, p] : keyed) events.push_back(p);
    }

    PieceTable table;
    table.tangent_.resize(n);
    table.acting_.resize(n);
    for (std::uint32_t e = 0; e < n; ++e) {
        table.tangent_[e] = static_cast<std::uint8_t>(1 - box[e].axis);
        table.acting_[e] = static_cast<std::uint8_t>(box[e].acting);
    }

    // Breakpoints as (mirror * 4 + direction, position) pairs in one array,
    // sorted once: far cheaper than a small vector per mirror and direction.
    // A breakpoint found by shooting back from an event remembers it: the
    // forward shot from there ends at that event, with nothing in between, so
    // it needs no second walk through the grid.
    static constexpr std::uint32_t no_event = ~std::uint32_t{0};
    struct Break {
        std::uint32_t slot;
        std::uint32_t event; // the event the ray from here meets first, or no_event
        Int u;
        bool operator<(const Break& o) const { return slot != o.slot ? slot < o.slot : u < o.u; }
        bool operator==(const Break& o) const { return slot == o.slot && u == o.u; }
    };
    std::vector<Break> breaks;
    breaks.reserve(std::size_t{n} * 8 + events.size() * 12);
    auto add_breaks_at = [&](const Int(&p)[2], unsigned first_d, unsigned last_d,
                             std::uint32_t event) {
        grid.for_each_element_at(p, [&](std::uint32_t m) {
            if (box[m].absorber) return;
            for (unsigned d = first_d; d <= last_d; ++d)
                breaks.push_back(Break{m * 4 + d, event, p[table.tangent_[m]]});
        });
    };
    for (std::uint32_t m = 0; m < n; ++m) {
        poll();
        for (unsigned d = 0; d < 4; ++d) {
            const int t = table.tangent_[m];
            breaks.push_back(Break{m * 4 + d, no_event, box[m].lo[t]});
            breaks.push_back(Break{m * 4 + d, no_event, box[m].hi[t]});
        }
    }
    // Whether some element at p acts on direction d (always, without
    // one-sided elements).
    auto acted_on_at = [&](const Int(&p)[2], unsigned d) {
        if (!scene.one_sided) return true;
        bool acted = false;
        grid.for_each_element_at(p, [&](std::uint32_t f) {
            if ((box[f].acting >> d) & 1u) acted = true;
        });
        return acted;
    };
    for (std::uint32_t e = 0; e < events.size(); ++e) {
        poll();
        const Int p[2] = {events[e][0], events[e][1]};
        add_breaks_at(p, 0, 3, no_event);
        for (unsigned d = 0; d < 4; ++d) {
            if (!acted_on_at(p, d)) continue; // rays in direction d pass it unseen
            walk_back(grid, p, d, [&](const Int(&q)[2]) {
                add_breaks_at(q, d, d, e);
                return acted_on_at(q, d);
            });
        }
        if (2 * breaks.size() > max_pieces) return std::nullopt;
    }
    // Bucket by slot (a counting sort over the 4n slots), then sort each
    // slot's few positions: cheaper than one comparison sort of everything.
    std::vector<std::uint32_t> start(std::size_t{n} * 4 + 1, 0);
    {
        for (const Break& k : breaks) ++start[k.slot + 1];
        for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
        std::vector<Break> bucketed(breaks.size());
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (Break& k : breaks) bucketed[fill[k.slot]++] = std::move(k);
        for (std::size_t i = 0; i + 1 < start.size(); ++i)
            std::sort(bucketed.begin() + start[i], bucketed.begin() + start[i + 1]);
        breaks = std::move(bucketed);
    }

    // Mirrors are resolved, and their pieces laid out, in Z-order of their
    // low corners: the forward shots then walk nearby cells, and the ray,
    // whose next mirror is a spatial neighbour, finds its next pieces nearby.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(n);
    for (std::uint32_t m = 0; m < n; ++m) order[m] = {grid.locality_key(box[m].lo), m};
    std::sort(order.begin(), order.end());

    // Resolve each piece with one forward shot, merging runs with one map.
    table.slots_.resize(std::size_t{n} * 4);
    std::vector<const Break*> b; // the current slot's breakpoints, reused
    for (const auto& ordered : order) {
        // A plain variable: clang 14 (the fuzz build) cannot capture a
        // structured binding in the lambdas below.
        const auto m = ordered.second;
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            const std::uint32_t slot = m * 4 + d;
            Cursor& range = table.slots_[slot];
            range.begin = static_cast<std::uint32_t>(table.pieces_.size());
            range.tangent = table.tangent_[m];
            b.clear();
            for (std::uint32_t k = start[slot]; k < start[slot + 1]; ++k)
                if (b.empty() || !(*b.back() == breaks[k])) b.push_back(&breaks[k]);
            if (box[m].absorber) continue;
            const int tangent = table.tangent_[m];
            const std::size_t first = table.pieces_.size();
            auto resolve = [&](const Int& u, std::uint32_t event) {
                poll.on_gmp<Int>(); // a slot may have thousands of pieces
                Shot<Int> s;
                if (event == no_event) {
                    Int p[2] = {box[m].lo[0], box[m].lo[1]};
                    p[tangent] = u;
                    s = grid.shoot(p, d);
                } else {
                    const Int p[2] = {events[event][0], events[event][1]};
                    const int normal = box[m].axis;
                    const Int t = p[normal] < box[m].lo[normal]
                                      ? Int(box[m].lo[normal] - p[normal])
                                      : Int(p[normal] - box[m].lo[normal]);
                    grid.for_each_element_at(p, [&](std::uint32_t f) {
                        if ((box[f].acting >> d) & 1u) s.record(t, box[f].axis, box[f].absorber, f);
                    });
                }
                Piece piece;
                piece.from = u;
                piece.t0 = s.t;
                piece.flip = s.flip & 3u;
                piece.kind_code = static_cast<std::uint8_t>(s.escape     ? Kind::escape
                                                            : s.absorber ? Kind::absorb
                                                                         : Kind::reflect);
                // Moving u along A moves the hit along B; t changes only when
                // B is perpendicular to A (B's normal is A's tangent axis).
                if (!s.escape && s.met == (1u << tangent)) {
                    const bool neg = (d >> tangent) & 1u;
                    piece.slope_code = neg ? 2 : 0;
                }
                if (table.pieces_.size() > first) {
                    const Piece& last = table.pieces_.back();
                    const bool same_map =
                        last.kind_code == piece.kind_code && last.flip == piece.flip &&
                        table.next_mirror_.back() == s.mirror &&
                        last.slope_code == piece.slope_code &&
                        (piece.kind() == Kind::escape ||
                         last.t0 + Int(last.slope()) * Int(u - last.from) == piece.t0);
                    if (same_map) return;
                }
                table.pieces_.push_back(piece);
                table.next_mirror_.push_back(s.mirror);
            };
            for (std::size_t i = 0; i < b.size(); ++i) {
                resolve(b[i]->u, b[i]->event);
                if (i + 1 < b.size() && Int(b[i]->u + 1) < b[i + 1]->u)
                    resolve(Int(b[i]->u + 1), no_event);
            }
            const std::size_t count = table.pieces_.size() - range.begin;
            if (table.pieces_.size() > max_pieces || count > UINT16_MAX) return std::nullopt;
            range.count = static_cast<std::uint16_t>(count);
        }
    }

    // Link each reflecting piece to the pieces the ray continues from.
    for (std::uint32_t m = 0; m < n; ++m)
        for (unsigned d = 0; d < 4; ++d)
            for (std::uint32_t k = table.slots_[m * 4 + d].begin,
                               end = k + table.slots_[m * 4 + d].count;
                 k < end; ++k) {
                Piece& piece = table.pieces_[k];
                if (piece.kind() == Kind::reflect) {
                    const Cursor next = table.at(table.next_mirror_[k], d ^ piece.flip);
                    piece.next_begin = next.begin;
                    piece.next_count = next.count;
                    piece.next_tangent = next.tangent & 1u;
                }
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
                pieces_[locate(where, q[where.tangent]) - pieces_.data()].near_target = true;
            });
            return acted;
        });
}

static_assert(sizeof(PieceTable<std::int64_t>::Piece) == 24, "a piece is meant to be 24 bytes");

} // namespace orthoray::shoot
