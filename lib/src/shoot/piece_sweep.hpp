// The piece tables' maps found by sweeping the ray's lines, without shots.
//
// Fix a direction d and flip the axes it moves negatively on, so that the ray
// moves along (+1, +1); write x', y' for the flipped coordinates. The ray's
// lines are then a = y' - x' (constant along the ray), and along one line the
// points are ordered by the depth x'. An element meets line a in at most one
// point: a vertical element x' = c over y' in [y1, y2] meets the lines
// a in [y1 - c, y2 - c] at depth c; a horizontal one y' = r over x' in
// [x1, x2] meets a in [r - x2, r - x1] at depth r - a. The first element the
// ray meets from a point of mirror m on line a is the nearest deeper one on
// that line (t > 0) among the elements acting on d, together with every
// element at the same point; in the opposite direction d ^ 3 the lines are
// the same and it is the nearest shallower one, so one sweep serves both.
//
// The sweep visits the integer lines in order, keeping the elements that
// meet the current line sorted by depth. Between two lines where something
// happens the order does not change: two verticals keep their depths, two
// horizontals move together, and a vertical and a horizontal swap only where
// they cross, which is a point of both. So the order changes only at three
// kinds of events: an element's first line (it is inserted), the line after
// its last (removed), and the line of a crossing, where the two meet at one
// depth (and, on the next line, come out swapped). On an event's line the
// map of a mirror can change only if the change lies between the mirror and
// the first element it meets: so the maps recomputed there (and on the line
// after a crossing) are those of the elements at the event's point and of
// the elements before it back to, and with, the nearest group acting on d
// (after it, for d ^ 3). Every other mirror keeps its map, so each
// mirror's pieces come out one run of lines at a time, each a maximal run
// with one map: the piece table's pieces, with no shot taken.
//
// The order kept is the one just after the current line (at a + 1/2): by
// depth, a horizontal before a vertical at the same depth (its depth falls
// as a grows), and by element index among parallel elements at one depth
// (collinear elements, whose depths stay equal). Ties at the line itself are
// contiguous in it, since integer depths that differ at a differ by at least
// one and move by at most a half to a +- 1/2.
#pragma once

#include "lattice/setup_poll.hpp"
#include "shoot/element_box.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace orthoray::shoot::piece_sweep {

// One piece of slot element * 4 + d: from position `from` on (up to the
// slot's next piece), the ray meets elements at t = base + slope * u, and
// reflects (kind 0) on a mirror `next` with the normal axes `flip`, escapes
// (1) or is absorbed (2), as PieceTable::Kind numbers them.
template <class Int>
struct Swept {
    std::uint32_t slot = 0;
    std::uint32_t next = 0;
    Int from{}, base{};
    std::int8_t slope = 0;
    std::uint8_t flip = 0;
    std::uint8_t kind = 1;
    // The same map: the same elements met, at the same t (any t for an escape).
    bool same_map(const Swept& o) const {
        return kind == o.kind && flip == o.flip && next == o.next && slope == o.slope &&
               (kind == 1 || base == o.base);
    }
};

// A vertical and a horizontal element sharing a point.
struct Crossing {
    std::uint32_t vertical, horizontal;
    bool operator<(const Crossing& o) const {
        return vertical != o.vertical ? vertical < o.vertical : horizontal < o.horizontal;
    }
    bool operator==(const Crossing& o) const = default;
};

// An element on the sweep's line, with what the order and the maps read
// of it inline (the line is short and read often; the elements are many).
template <class Int>
struct OnLine {
    Int level;          // the depth (vertical) or the depth plus a (horizontal)
    std::uint32_t e;    // the element
    std::uint32_t rank; // its number in the sweep (its first line's rank)
    std::uint8_t flags;
    // acting << k: acts on the sweep's direction k (0: deeper, 1: shallower)
    static constexpr std::uint8_t vertical = 1, absorber = 2, acting = 4;
    bool is(std::uint8_t flag) const { return (flags & flag) != 0; }
    Int depth(const Int& a) const { return is(vertical) ? level : Int(level - a); }
};

// Sweeps the lines of direction d (0 or 1) and of its opposite d ^ 3 over
// the n elements box(0 .. n-1): the ray in d meets the next deeper element
// on its line, in d ^ 3 the next shallower one. Calls emit(piece) for every
// piece of every non-absorbing element's slots for both, in no particular
// order. Returns false as soon as emit does (the caller has enough pieces),
// or once it has looked at more than work_limit elements: many mirrors on
// one line at one depth (collinear and overlapping) make it revisit them all
// at each of their ends, so its work can grow as the square of theirs while
// the pieces stay few.
template <class Int, class BoxOf, class Emit>
bool sweep(std::uint32_t n, BoxOf&& box, unsigned d, const std::vector<Crossing>& crossings,
           std::size_t work_limit, const lattice::SetupPoll& poll, Emit&& emit) {
    using Entry = OnLine<Int>;
    const unsigned directions[2] = {d, d ^ 3u};
    const bool fx = d & 1u, fy = d & 2u;
    auto flip_x = [fx](const Int& x) { return fx ? Int(-x) : x; };
    auto flip_y = [fy](const Int& y) { return fy ? Int(-y) : y; };

    // Each element's lines [lo, hi], numbered by lo: an element's state is
    // then read near those of the elements on the line with it (inserted
    // about when it was), not all over arrays in the scene's order.
    std::vector<Int> lo(n), hi(n);
    std::vector<Entry> entry(n);
    std::vector<std::uint32_t> rank(n);
    {
        std::vector<std::pair<Int, std::uint32_t>> by_first(n);
        for (std::uint32_t e = 0; e < n; ++e) {
            poll();
            const ElementBox<Int, 2>& b = box(e);
            Entry& x = entry[e];
            x.e = e;
            x.flags = static_cast<std::uint8_t>(
                (b.axis == 0 ? Entry::vertical : 0) | (b.absorber ? Entry::absorber : 0) |
                (b.acts_on(directions[0]) ? Entry::acting : 0) |
                (b.acts_on(directions[1]) ? Entry::acting << 1 : 0));
            if (b.axis == 0) {
                const Int c = flip_x(b.lo[0]), y1 = flip_y(b.lo[1]), y2 = flip_y(b.hi[1]);
                lo[e] = Int(std::min(y1, y2) - c);
                hi[e] = Int(std::max(y1, y2) - c);
                x.level = c;
            } else {
                const Int r = flip_y(b.lo[1]), x1 = flip_x(b.lo[0]), x2 = flip_x(b.hi[0]);
                lo[e] = Int(r - std::max(x1, x2));
                hi[e] = Int(r - std::min(x1, x2));
                x.level = r;
            }
            by_first[e] = {lo[e], e};
        }
        std::sort(by_first.begin(), by_first.end());
        std::vector<Int> lo_by_rank(n), hi_by_rank(n);
        std::vector<Entry> entry_by_rank(n);
        for (std::uint32_t r = 0; r < n; ++r) {
            const std::uint32_t e = by_first[r].second;
            rank[e] = r;
            lo_by_rank[r] = lo[e];
            hi_by_rank[r] = hi[e];
            entry_by_rank[r] = entry[e];
            entry_by_rank[r].rank = r;
        }
        lo = std::move(lo_by_rank);
        hi = std::move(hi_by_rank);
        entry = std::move(entry_by_rank);
    }
    // The order just after line a.
    auto after = [](const Int& a) {
        return [a](const Entry& x, const Entry& y) {
            const Int dx = x.depth(a), dy = y.depth(a);
            if (dx != dy) return dx < dy;
            if (x.is(Entry::vertical) != y.is(Entry::vertical)) return y.is(Entry::vertical);
            return x.e < y.e;
        };
    };
    // A mirror's position on line a: y on a vertical one, x on a horizontal.
    auto position = [&](const Entry& m, const Int& a) {
        return m.is(Entry::vertical) ? flip_y(Int(a + m.level)) : flip_x(Int(m.level - a));
    };

    // Events: 0 removal (on the line after an element's last), 1 insertion,
    // 2 crossing, 3 the line after a crossing.
    struct Event {
        Int a;
        std::uint32_t kind;
        std::uint32_t e, f;
        bool operator<(const Event& o) const { return a != o.a ? a < o.a : kind < o.kind; }
    };
    std::vector<Event> events;
    events.reserve(2 * std::size_t{n} + 2 * crossings.size());
    for (std::uint32_t r = 0; r < n; ++r) {
        events.push_back(Event{lo[r], 1, r, r});
        events.push_back(Event{Int(hi[r] + 1), 0, r, r});
    }
    for (const Crossing& c : crossings) {
        const Int a = Int(flip_y(box(c.horizontal).lo[1]) - flip_x(box(c.vertical).lo[0]));
        events.push_back(Event{a, 2, rank[c.vertical], rank[c.horizontal]});
        events.push_back(Event{Int(a + 1), 3, rank[c.vertical], rank[c.horizontal]});
    }
    rank = {};
    std::sort(events.begin(), events.end());

    // The open run of each mirror and direction: its first line and its map.
    std::vector<Int> run_from[2] = {std::vector<Int>(n), std::vector<Int>(n)};
    std::vector<Swept<Int>> run[2] = {std::vector<Swept<Int>>(n), std::vector<Swept<Int>>(n)};
    auto close = [&](int k, const Entry& m, const Int& last) {
        Swept<Int> piece = run[k][m.rank];
        piece.slot = m.e * 4 + directions[k];
        piece.from = std::min(position(m, run_from[k][m.rank]), position(m, last));
        return emit(piece);
    };

    std::vector<Entry> line;  // the elements meeting the current line, in order
    std::vector<Int> seeds;   // depths at which something changed on it
    std::vector<Int> crossed; // depths of its crossings
    std::vector<std::pair<std::size_t, std::size_t>> dirty[2];
    // The group of elements at depth g on line a: [first, last).
    auto group = [&](const Int& a, const Int& g) {
        const auto first =
            std::lower_bound(line.begin(), line.end(), g,
                             [&a](const Entry& x, const Int& v) { return x.depth(a) < v; });
        const auto last = std::upper_bound(
            first, line.end(), g, [&a](const Int& v, const Entry& x) { return v < x.depth(a); });
        return std::pair<std::size_t, std::size_t>(first - line.begin(), last - line.begin());
    };
    // What the ray meets from depth `from` on line a in direction k: the
    // first group of elements beyond it (deeper for k = 0, shallower for 1)
    // holding an element acting on that direction. Every element at one
    // depth shares it, so the sweep computes it once a group.
    struct Met {
        Int depth{};
        unsigned axes = 0; // normal axes of the elements met, absorbers included
        bool absorbed = false;
        std::uint8_t flip = 0;
        std::uint32_t next = 0;
    };
    std::size_t work = 0; // elements looked at, against work_limit
    auto met_from = [&](int k, std::size_t i, const Int& a) {
        const std::uint8_t acting = static_cast<std::uint8_t>(Entry::acting << k);
        const auto below = [&a](const Entry& x, const Int& v) { return x.depth(a) < v; };
        const auto above = [&a](const Int& v, const Entry& x) { return v < x.depth(a); };
        const std::ptrdiff_t step = k == 0 ? 1 : -1,
                             size = static_cast<std::ptrdiff_t>(line.size());
        // Past the elements at line[i]'s depth (t = 0: not met): a step or
        // two, or a search past a long group.
        const Int from = line[i].depth(a);
        std::ptrdiff_t j = static_cast<std::ptrdiff_t>(i) + step;
        for (int tries = 0; j >= 0 && j < size && line[j].depth(a) == from; j += step)
            if (++tries == 8) {
                j = k == 0 ? std::upper_bound(line.begin(), line.end(), from, above) - line.begin()
                           : std::lower_bound(line.begin(), line.end(), from, below) -
                                 line.begin() - 1;
                break;
            }
        Met met;
        while (j >= 0 && j < size) {
            met.depth = line[j].depth(a);
            for (; j >= 0 && j < size && line[j].depth(a) == met.depth; j += step) {
                ++work;
                const Entry& x = line[j];
                if (!x.is(acting)) continue;
                const unsigned axis = x.is(Entry::vertical) ? 0 : 1;
                met.axes |= 1u << axis;
                if (x.is(Entry::absorber)) {
                    met.absorbed = true;
                } else {
                    met.flip |= static_cast<std::uint8_t>(1u << axis);
                    // Of several mirrors met at once, the last in the scene:
                    // the one the grid's shot names (its cells list elements
                    // in scene order), so both build the same tables.
                    met.next = std::max(met.next, x.e);
                }
            }
            if (met.axes != 0) break;
        }
        return met;
    };
    // The map of mirror m on line a in direction k, meeting `met`.
    auto map_of = [&](int k, const Entry& m, const Met& met, const Int& a) {
        Swept<Int> piece;
        if (met.axes == 0) return piece; // an escape
        piece.kind = met.absorbed ? 2 : 0;
        piece.flip = met.flip;
        piece.next = met.next;
        const unsigned tangent = m.is(Entry::vertical) ? 1 : 0;
        if (met.axes == (1u << tangent)) piece.slope = ((directions[k] >> tangent) & 1u) ? 1 : -1;
        const Int from = m.depth(a);
        const Int t = k == 0 ? Int(met.depth - from) : Int(from - met.depth);
        piece.base = Int(t - Int(piece.slope) * position(m, a));
        return piece;
    };

    for (std::size_t k = 0; k < events.size();) {
        poll();
        const Int a = events[k].a;
        std::size_t end = k;
        while (end < events.size() && events[end].a == a) ++end;
        seeds.clear();
        // Removals: the order before this line is the one after the last.
        const Int previous = a - 1;
        for (; k < end && events[k].kind == 0; ++k) {
            const Entry& x = entry[events[k].e];
            const auto at = std::lower_bound(line.begin(), line.end(), x, after(previous));
            if (at == line.end() || at->rank != x.rank)
                throw std::logic_error("piece sweep: an element left the line out of order");
            line.erase(at);
            seeds.push_back(x.depth(a));
            if (!x.is(Entry::absorber) && !(close(0, x, previous) && close(1, x, previous)))
                return false;
        }
        // Insertions in the order after this line. That order differs from
        // the list's only inside the groups of this line's crossings, which
        // are sorted next: outside them the search is exact, and its element
        // goes into the right group.
        for (std::size_t i = k; i < end && events[i].kind == 1; ++i) {
            const Entry& x = entry[events[i].e];
            line.insert(std::upper_bound(line.begin(), line.end(), x, after(a)), x);
            seeds.push_back(x.depth(a));
        }
        crossed.clear();
        for (std::size_t i = k; i < end; ++i)
            if (events[i].kind == 2) {
                seeds.push_back(entry[events[i].e].level);
                crossed.push_back(entry[events[i].e].level);
            } else if (events[i].kind == 3) {
                seeds.push_back(entry[events[i].e].level);
                seeds.push_back(entry[events[i].f].depth(a));
            }
        // Each crossing's group, put in the order after this line.
        std::sort(crossed.begin(), crossed.end());
        crossed.erase(std::unique(crossed.begin(), crossed.end()), crossed.end());
        for (const Int& g : crossed) {
            const auto [first, last] = group(a, g);
            std::sort(line.begin() + first, line.begin() + last, after(a));
        }
        // Each group where something happened may change the maps of its own
        // elements and of those before it (for d; after it for d ^ 3), up to
        // and with the nearest group holding an element acting on that
        // direction.
        std::sort(seeds.begin(), seeds.end());
        seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
        dirty[0].clear();
        dirty[1].clear();
        for (const Int& g : seeds) {
            const auto [first, last] = group(a, g);
            std::size_t start = first;
            while (start > 0) {
                --start;
                if (!line[start].is(Entry::acting)) continue;
                const Int at = line[start].depth(a);
                while (start > 0 && line[start - 1].depth(a) == at) --start;
                break;
            }
            std::size_t stop = last;
            while (stop < line.size()) {
                if (!line[stop++].is(Entry::acting << 1)) continue;
                const Int at = line[stop - 1].depth(a);
                while (stop < line.size() && line[stop].depth(a) == at) ++stop;
                break;
            }
            work += (first - start) + (stop - last);
            if (start < last) dirty[0].emplace_back(start, last);
            if (first < stop) dirty[1].emplace_back(first, stop);
        }
        // The ranges come in order (the seeds did) and may overlap: each
        // mirror is computed once.
        for (int side = 0; side < 2; ++side) {
            std::size_t done = 0;
            // What the group at depth met_for meets: shared by its elements.
            bool known = false;
            Int met_for{};
            Met met;
            for (const auto& [first, last] : dirty[side]) {
                for (std::size_t i = std::max(first, done); i < last; ++i) {
                    const Entry& m = line[i];
                    if (++work > work_limit) return false;
                    if (m.is(Entry::absorber)) continue;
                    poll.on_gmp<Int>();
                    const Int from = m.depth(a);
                    if (!known || !(met_for == from)) {
                        met = met_from(side, i, a);
                        met_for = from;
                        known = true;
                    }
                    const Swept<Int> now = map_of(side, m, met, a);
                    const bool fresh = lo[m.rank] == a; // inserted on this line: no run yet
                    if (!fresh && now.same_map(run[side][m.rank])) continue;
                    if (!fresh && !close(side, m, previous)) return false;
                    run[side][m.rank] = now;
                    run_from[side][m.rank] = a;
                }
                done = std::max(done, last);
            }
        }
        k = end;
    }
    return true;
}

} // namespace orthoray::shoot::piece_sweep
