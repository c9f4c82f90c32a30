// Building the piece tables (piece_table.hpp): breakpoints from the events,
// one forward shot a piece, then the links from each piece to the next
// mirror's pieces.
#pragma once

#include "shoot/piece_table.hpp"

namespace orthoray::shoot {
namespace piece_build {

// Puts items[0, size) in order of key(item) in [0, keys), in place, and
// returns where each key's items start (keys + 1 entries, the last = size).
// Each swap moves one item into its key's range for good: the ranges before
// the one being filled are full, so it goes to a later one. One pass over
// all 4n slots of 10^5 mirrors chases a dependent cache miss a swap (0.5 s
// for 1.8 M breakpoints); keys at most 1024 keep the positions written
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

// The open run next to a position on mirror A whose ray in direction d
// (bit i: towards -infinity on axis i) first meets the point e, where B is
// the one element acting on d: the side of the position (+1 above, -1
// below, 0 neither) on which the run maps as the position does. Moving the
// start by delta along A moves the hit on B's line by delta along B when B
// is parallel to A, and by -delta s0 s1 (s_i = -1 where bit i of d is set)
// when perpendicular; t stays affine in delta either way. So when e is an
// end of B, the side that moves the hit into B meets B, at the same map,
// provided nothing else comes near: the position must not itself be an
// event (an element crossing A there would be met at t ~ delta), and B
// must be the only element acting on d at e (the caller's two checks);
// nothing lies between, or the reverse shot would have stopped there.
template <class Int>
int run_side(const ElementBox<Int, 2>& a, const ElementBox<Int, 2>& b, const Int (&e)[2],
             unsigned d) {
    const int along = 1 - b.axis;
    if (b.lo[along] == b.hi[along]) return 0; // a point: no side of it is B
    const int extends = e[along] == b.lo[along] ? 1 : e[along] == b.hi[along] ? -1 : 0;
    if (a.axis == b.axis) return extends;
    const bool same_signs = ((d ^ (d >> 1)) & 1u) == 0;
    return same_signs ? -extends : extends;
}

} // namespace piece_build

template <class Int>
std::optional<PieceTable<Int>>
PieceTable<Int>::build(const LatticeScene& scene, const UniformGrid<Int, 2>& grid,
                       std::size_t max_pieces, const lattice::SetupPoll& poll) {
    // The grid holds every element's box in Int (element e of the scene is
    // the grid's element e): read there, not copied.
    const std::uint32_t n = static_cast<std::uint32_t>(grid.size());
    auto box = [&grid](std::uint32_t e) -> const ElementBox<Int, 2>& { return grid.element(e); };

    // Events: every element's two ends (so each slot of a mirror gets its
    // first and last positions as breakpoints, from add_breaks_at below),
    // and every crossing of a vertical and a horizontal element (T-junctions
    // and corners included).
    using Point = std::array<Int, 2>;
    std::vector<Point> events;
    for (std::uint32_t e = 0; e < n; ++e) {
        poll();
        const ElementBox<Int, 2>& b = box(e);
        const int t = 1 - b.axis;
        Point p{b.lo[0], b.lo[1]};
        events.push_back(p);
        p[t] = b.hi[t];
        events.push_back(p);
    }
    for (std::uint32_t e = 0; e < n; ++e) {
        poll();
        if (box(e).axis != 0) continue;
        grid.for_each_neighbour(e, [&](std::uint32_t f) {
            const ElementBox<Int, 2>& v = box(e);
            const ElementBox<Int, 2>& h = box(f);
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
        table.tangent_[e] = static_cast<std::uint8_t>(1 - box(e).axis);
        table.acting_[e] = box(e).acting;
    }

    // Breakpoints as (mirror * 4 + direction, position) pairs in one array,
    // sorted once: far cheaper than a small vector per mirror and direction.
    // A breakpoint found by shooting back from an event remembers it: the
    // forward shot from there ends at that event, with nothing in between, so
    // it needs no second walk through the grid.
    // A breakpoint at an event on its own mirror carries no event, or
    // lone_end when that mirror is the only element there (its end, then).
    static constexpr std::uint32_t no_event = ~std::uint32_t{0}, lone_end = no_event - 1;
    struct Break {
        std::uint32_t slot;
        std::uint32_t event; // the event the ray meets first from here, or as above
        Int u;
        bool operator<(const Break& o) const { return slot != o.slot ? slot < o.slot : u < o.u; }
        bool operator==(const Break& o) const { return slot == o.slot && u == o.u; }
    };
    std::vector<Break> breaks;
    breaks.reserve(std::size_t{n} * 8 + events.size() * 12);
    auto add_breaks_at = [&](const Int(&p)[2], unsigned first_d, unsigned last_d,
                             std::uint32_t event) {
        grid.for_each_element_at(p, [&](std::uint32_t m) {
            if (box(m).absorber) return;
            for (unsigned d = first_d; d <= last_d; ++d)
                breaks.push_back(Break{m * 4 + d, event, p[table.tangent_[m]]});
        });
    };
    // Whether some element at p acts on direction d (always, without
    // one-sided elements).
    auto acted_on_at = [&](const Int(&p)[2], unsigned d) {
        if (!scene.one_sided) return true;
        bool acted = false;
        grid.for_each_element_at(p, [&](std::uint32_t f) {
            if (box(f).acts_on(d)) acted = true;
        });
        return acted;
    };
    for (std::uint32_t e = 0; e < events.size(); ++e) {
        poll();
        const Int p[2] = {events[e][0], events[e][1]};
        unsigned here = 0;
        grid.for_each_element_at(p, [&](std::uint32_t) { ++here; });
        add_breaks_at(p, 0, 3, here == 1 ? lone_end : no_event);
        for (unsigned d = 0; d < 4; ++d) {
            if (!acted_on_at(p, d)) continue; // rays in direction d pass it unseen
            walk_back(grid, p, d, [&](const Int(&q)[2]) {
                add_breaks_at(q, d, d, e);
                return acted_on_at(q, d);
            });
        }
        if (2 * breaks.size() > max_pieces) return std::nullopt;
    }
    // Bucket by slot (a counting sort over the 4n slots, in place: a
    // bucketed copy would double the build's largest array, 28 MB at 10^5
    // mirrors), then sort each slot's few positions: cheaper than one
    // comparison sort of everything.
    const std::vector<std::uint32_t> start = piece_build::by_slot(breaks, n * 4);
    for (std::uint32_t slot = 0; slot < n * 4; ++slot)
        std::sort(breaks.begin() + start[slot], breaks.begin() + start[slot + 1]);

    // Mirrors are resolved, and their pieces laid out, in Z-order of their
    // low corners: the forward shots then walk nearby cells, and the ray,
    // whose next mirror is a spatial neighbour, finds its next pieces nearby.
    {
        std::vector<std::pair<std::uint64_t, std::uint32_t>> order(n);
        for (std::uint32_t m = 0; m < n; ++m) order[m] = {grid.locality_key(box(m).lo), m};
        std::sort(order.begin(), order.end());
        table.laid_out_.resize(n);
        for (std::uint32_t r = 0; r < n; ++r) table.laid_out_[r] = order[r].second;
    }

    // Resolve each piece, merging runs with one map: a position found from
    // an event reads its map there, an open run next to one that vouches
    // for it (piece_build::run_side) takes its map, and the rest take one
    // forward shot each.
    table.slots_.resize(std::size_t{n} * 4);
    // Room for about one piece a breakpoint, reserved, not touched: growing
    // by doubling would hold the old and the new arrays at once, at the
    // build's peak (10^5 mirrors: 50 MB of the 130 the tables added), while
    // untouched reserved pages cost no memory (more pieces just grow).
    table.from_.reserve(breaks.size());
    table.hops_.reserve(breaks.size());
    // The current slot's positions, reused: each with the event the ray
    // from there meets first (no_event if no reverse shot found it) and
    // whether the position is itself an event (an event on the mirror).
    struct Position {
        const Int* u;
        std::uint32_t event; // an event's index, or no_event
        bool on_event, lone;
    };
    std::vector<Position> b;
    // A piece resolved, and the side of it (+1 above, -1 below, 0 neither
    // known) on which the open run next to it has the same map.
    struct Resolved {
        Hop hop;
        int run_side = 0;
    };
    for (const std::uint32_t m : table.laid_out_) {
        for (unsigned d = 0; d < 4; ++d) {
            poll();
            const std::uint32_t slot = m * 4 + d;
            Cursor& range = table.slots_[slot];
            range.begin = static_cast<std::uint32_t>(table.hops_.size());
            range.tangent = table.tangent_[m];
            b.clear();
            // Equal positions: one entry, which keeps the event if any
            // (its piece then needs no shot).
            for (std::uint32_t k = start[slot]; k < start[slot + 1]; ++k) {
                const Break& x = breaks[k];
                const bool on_event = x.event >= lone_end;
                if (b.empty() || !(*b.back().u == x.u))
                    b.push_back(Position{&x.u, on_event ? no_event : x.event, on_event,
                                         x.event == lone_end});
                else if (!on_event)
                    b.back().event = x.event;
                else {
                    b.back().on_event = true;
                    b.back().lone = x.event == lone_end;
                }
            }
            if (box(m).absorber) continue;
            const int tangent = table.tangent_[m];
            const std::size_t first = table.hops_.size();
            auto resolve = [&](const Int& u, std::uint32_t event, bool on_event) {
                poll.on_gmp<Int>(); // a slot may have thousands of pieces
                Shot<Int> s;
                Resolved r;
                if (event == no_event) {
                    Int p[2] = {box(m).lo[0], box(m).lo[1]};
                    p[tangent] = u;
                    s = grid.shoot(p, d);
                } else {
                    const Int p[2] = {events[event][0], events[event][1]};
                    const int normal = box(m).axis;
                    const Int t = p[normal] < box(m).lo[normal]
                                      ? Int(box(m).lo[normal] - p[normal])
                                      : Int(p[normal] - box(m).lo[normal]);
                    unsigned met = 0;
                    std::uint32_t seen = 0;
                    grid.for_each_element_at(p, [&](std::uint32_t f) {
                        const ElementBox<Int, 2>& at = box(f);
                        if (!at.acts_on(d)) return;
                        s.record(t, at.axis, at.absorber, f);
                        ++met;
                        seen = f;
                    });
                    if (met == 1 && !on_event)
                        r.run_side = piece_build::run_side(box(m), box(seen), p, d);
                }
                const Kind kind = s.escape     ? Kind::escape
                                  : s.absorber ? Kind::absorb
                                               : Kind::reflect;
                Hop& hop = r.hop;
                hop.bits = static_cast<std::uint8_t>((s.flip & flip_mask) |
                                                     (static_cast<unsigned>(kind) << kind_shift) |
                                                     (kind == Kind::reflect ? 0u : stop_bit));
                // Moving u along A moves the hit along B; t changes only when
                // B is perpendicular to A (B's normal is A's tangent axis).
                if (!s.escape && s.met == (1u << tangent))
                    hop.slope = ((d >> tangent) & 1u) ? 1 : -1;
                hop.base = s.t - Int(hop.slope) * u;
                // The mirror met, until the links below replace it by its pieces.
                hop.next_begin = s.mirror;
                return r;
            };
            auto add = [&](const Int& from, const Hop& hop) {
                if (table.hops_.size() > first) {
                    const Hop& last = table.hops_.back();
                    const bool same_map = last.bits == hop.bits &&
                                          last.next_begin == hop.next_begin &&
                                          last.slope == hop.slope &&
                                          (hop.kind() == Kind::escape || last.base == hop.base);
                    if (same_map) return;
                }
                table.from_.push_back(from);
                table.hops_.push_back(hop);
            };
            // Each position, then the open run after it: that run takes the
            // map of a neighbour that vouches for it (run_side), else a shot.
            // A mirror's end that no other element touches and whose ray
            // meets no event (the lone ends below) maps as the run beside
            // it: shifting the start into the mirror moves the ray off no
            // event and onto no element near the start, which is the
            // mirror's alone. So it takes that run's map, with no shot.
            const std::size_t last = b.size() - 1;
            auto gap = [&](std::size_t i) { return Int(*b[i].u + 1) < *b[i + 1].u; };
            auto lone_end_at = [&](std::size_t i, const Int& end) {
                return b[i].lone && b[i].event == no_event && *b[i].u == end;
            };
            const bool lo_from_run = last > 0 && gap(0) && lone_end_at(0, box(m).lo[tangent]),
                       hi_from_run =
                           last > 0 && gap(last - 1) && lone_end_at(last, box(m).hi[tangent]);
            auto at = [&](std::size_t i) { return resolve(*b[i].u, b[i].event, b[i].on_event); };
            Resolved next = lo_from_run ? Resolved{} : at(0);
            for (std::size_t i = 0; i < b.size(); ++i) {
                const Resolved here = next;
                if (i == last) {
                    if (!hi_from_run) add(*b[i].u, here.hop);
                    break;
                }
                next = i + 1 == last && hi_from_run ? Resolved{} : at(i + 1);
                if (!gap(i)) {
                    add(*b[i].u, here.hop);
                    continue;
                }
                const Int after = *b[i].u + 1;
                const Hop run = here.run_side > 0   ? here.hop
                                : next.run_side < 0 ? next.hop
                                                    : resolve(after, no_event, false).hop;
                add(*b[i].u, i == 0 && lo_from_run ? run : here.hop);
                add(after, run);
            }
            const std::size_t count = table.hops_.size() - range.begin;
            table.count_ += count;
            if (table.count_ > max_pieces || count > UINT16_MAX) return std::nullopt;
            range.count = static_cast<std::uint16_t>(count);
            // A long slot's index (locate_piece), with hops kept as long.
            table.hops_.resize(table.hops_.size() +
                               add_block_index(table.from_, range.begin, count));
        }
    }

    breaks = {}; // before the links: the build's largest temporary
    b = {};

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
