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

#include <boost/sort/spreadsort/integer_sort.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace orthoray::shoot::piece_sweep {

// Sorts [first, last) by key(item), items with equal keys in no particular
// order: a radix sort (Boost's spreadsort) on a 64-bit key, a comparison
// sort otherwise. On the build's elements and events at 10^5 mirrors it
// takes 0.6 of std::sort's time (measured on pairs and events of those
// sizes). Spreadsort leaves a bin of equal keys as it is, so a finer order
// among them needs a pass of its own.
template <class It, class Key>
void sort_by_key(It first, It last, Key key) {
    using K = std::decay_t<decltype(key(*first))>;
    const auto less = [&key](const auto& x, const auto& y) { return key(x) < key(y); };
    if constexpr (std::is_same_v<K, std::int64_t> || std::is_same_v<K, std::uint64_t>)
        boost::sort::spreadsort::integer_sort(
            first, last, [&key](const auto& x, unsigned offset) { return key(x) >> offset; }, less);
    else
        std::sort(first, last, less);
}

// One piece of slot number * 4 + d, where number is the element's number
// as the caller names it (sweep): from position `from` on (up to the
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
    bool falling = false; // set on an emitted piece: its slot's pieces come falling (falls)
    // The same map: the same elements met, at the same t. An escape leaves
    // every other field zero, so plain equality is the test; & rather than
    // && keeps it free of jumps (the sweep asks it once a map recomputed,
    // unpredictably).
    bool same_map(const Swept& o) const {
        const bool same_base = base == o.base; // a call on GMP integers
        return (kind == o.kind) & (flip == o.flip) & (next == o.next) & (slope == o.slope) &
               same_base;
    }
};

// The first of items[0, size) for which pred is false, when it is true on a
// prefix and false after it (std::partition_point). The sweep searches its
// line a few times an event, and which way each compare goes is a coin
// toss: this search halves the range with a conditional move instead of a
// jump, so it pays no mispredicted branches (given a pred without jumps).
template <class T, class Pred>
std::size_t first_false(const T* items, std::size_t size, Pred&& pred) {
    if (size == 0) return 0;
    const T* base = items;
    // The answer lies in [base, base + size].
    while (size > 1) {
        const std::size_t half = size / 2;
        base = pred(base[half - 1]) ? base + half : base;
        size -= half;
    }
    return static_cast<std::size_t>(base - items) + (pred(*base) ? 1 : 0);
}

// Whether sweep d finds the pieces of a slot of a vertical or a horizontal
// element with falling positions. It closes a slot's runs in the order of
// their lines a, and the position on line a, in the scene's axes, is
// flip_y(a + level) on a vertical element and flip_x(level - a) on a
// horizontal one (sweep's `position`): y rises with a unless the sweep
// flips y (d & 2; never for d = 0 or 1), and x falls with a unless it flips
// x (d & 1). So each slot's pieces come out sorted, one way or the other.
constexpr bool falls(unsigned d, bool vertical) {
    return vertical ? (d & 2u) != 0 : (d & 1u) == 0;
}

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
    std::uint32_t name; // the number its slots are emitted under
    std::uint8_t flags;
    // acting << k: acts on the sweep's direction k (0: deeper, 1: shallower)
    static constexpr std::uint8_t vertical = 1, absorber = 2, acting = 4;
    bool is(std::uint8_t flag) const { return (flags & flag) != 0; }
    // Without a jump where Int allows: the searches over the line compare
    // depths of verticals and horizontals in no predictable order.
    Int depth(const Int& a) const {
        if constexpr (std::is_trivially_copyable_v<Int>)
            return Int(level - (a & Int(Int(flags & vertical) - 1)));
        else
            return is(vertical) ? level : Int(level - a);
    }
};

// Sweeps the lines of direction d (0 or 1) and of its opposite d ^ 3 over
// the n elements box(0 .. n-1): the ray in d meets the next deeper element
// on its line, in d ^ 3 the next shallower one. Calls emit(piece) for every
// piece of every non-absorbing element's slots for both, the slots of
// element e numbered name(e) * 4 + direction; a slot's pieces come in order
// of position, rising or falling (falls), other slots' in between. Returns
// false as soon as emit does (the caller has enough pieces), or once it has
// looked at more than work_limit elements: many mirrors on one line at one
// depth (collinear and overlapping) make it revisit them all at each of
// their ends, so its work can grow as the square of theirs while the pieces
// stay few.
template <class Int, class BoxOf, class Name, class Emit>
bool sweep(std::uint32_t n, BoxOf&& box, Name&& name, unsigned d,
           const std::vector<Crossing>& crossings, std::size_t work_limit,
           const lattice::SetupPoll& poll, Emit&& emit) {
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
            x.name = name(e);
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
        // (Elements with one first line may take their ranks in any order:
        // the sweep reads the order on a line from `after`, not from ranks.)
        sort_by_key(by_first.begin(), by_first.end(), [](const auto& x) { return x.first; });
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
    // The order just after line a (evaluated whole, with & and |, for
    // first_false).
    auto after = [](const Int& a) {
        return [a](const Entry& x, const Entry& y) {
            const Int dx = x.depth(a), dy = y.depth(a);
            const bool vx = x.is(Entry::vertical), vy = y.is(Entry::vertical);
            const bool shallower = dx < dy, level = dx == dy;
            return shallower | (level & ((vx < vy) | ((vx == vy) & (x.e < y.e))));
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
    // The insertions come sorted already (ranks follow first lines). The
    // rest are sorted by line and put in kind order on each line, and the
    // insertions merged in from the back: the rest fill the array's front,
    // and its back, n places, stays ahead of the merge's read by the
    // insertions left to write, so no second array is held.
    std::vector<Event> events;
    events.reserve(std::size_t{n} + std::size_t{n} + 2 * crossings.size());
    for (std::uint32_t r = 0; r < n; ++r) events.push_back(Event{Int(hi[r] + 1), 0, r, r});
    for (const Crossing& c : crossings) {
        const Int a = Int(flip_y(box(c.horizontal).lo[1]) - flip_x(box(c.vertical).lo[0]));
        events.push_back(Event{a, 2, rank[c.vertical], rank[c.horizontal]});
        events.push_back(Event{Int(a + 1), 3, rank[c.vertical], rank[c.horizontal]});
    }
    rank = {};
    sort_by_key(events.begin(), events.end(), [](const Event& x) { return x.a; });
    for (auto run = events.begin(); run != events.end();) {
        const auto end =
            std::find_if(run, events.end(), [&](const Event& x) { return x.a != run->a; });
        if (end - run > 1) std::sort(run, end);
        run = end;
    }
    {
        std::size_t read = events.size();
        events.resize(events.size() + n);
        std::size_t write = events.size();
        for (std::uint32_t r = n; r > 0;) {
            const Event insertion{lo[r - 1], 1, r - 1, r - 1};
            if (read > 0 && insertion < events[read - 1]) {
                events[--write] = events[--read];
            } else {
                events[--write] = insertion;
                --r;
            }
        }
    }

    // The open run of each mirror and direction: its first line and its map.
    std::vector<Int> run_from[2] = {std::vector<Int>(n), std::vector<Int>(n)};
    std::vector<Swept<Int>> run[2] = {std::vector<Swept<Int>>(n), std::vector<Swept<Int>>(n)};
    auto close = [&](int k, const Entry& m, const Int& last) {
        Swept<Int> piece = run[k][m.rank];
        piece.slot = m.name * 4 + directions[k];
        piece.falling = falls(d, m.is(Entry::vertical));
        piece.from = std::min(position(m, run_from[k][m.rank]), position(m, last));
        return emit(piece);
    };

    std::vector<Entry> line;  // the elements meeting the current line, in order
    std::vector<Int> seeds;   // depths at which something changed on it
    std::vector<Int> crossed; // depths of its crossings
    std::vector<std::pair<std::size_t, std::size_t>> dirty[2];
    // The group of elements at depth g on line a: [first, last).
    auto group = [&](const Int& a, const Int& g) {
        const std::size_t first =
            first_false(line.data(), line.size(), [&](const Entry& x) { return x.depth(a) < g; });
        const std::size_t last =
            first + first_false(line.data() + first, line.size() - first,
                                [&](const Entry& x) { return !(g < x.depth(a)); });
        return std::pair<std::size_t, std::size_t>(first, last);
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
        const std::ptrdiff_t step = k == 0 ? 1 : -1,
                             size = static_cast<std::ptrdiff_t>(line.size());
        // Past the elements at line[i]'s depth (t = 0: not met): a step or
        // two, or a search past a long group.
        const Int from = line[i].depth(a);
        std::ptrdiff_t j = static_cast<std::ptrdiff_t>(i) + step;
        for (int tries = 0; j >= 0 && j < size && line[j].depth(a) == from; j += step)
            if (++tries == 8) {
                const auto [first, last] = group(a, from);
                j = k == 0 ? static_cast<std::ptrdiff_t>(last)
                           : static_cast<std::ptrdiff_t>(first) - 1;
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
            const auto before = after(previous);
            const auto at =
                line.begin() +
                first_false(line.data(), line.size(), [&](const Entry& y) { return before(y, x); });
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
            const auto order = after(a);
            line.insert(line.begin() + first_false(line.data(), line.size(),
                                                   [&](const Entry& y) { return !order(x, y); }),
                        x);
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
