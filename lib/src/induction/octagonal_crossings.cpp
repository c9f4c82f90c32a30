#include "induction/octagonal_crossings.hpp"

#include "lattice/lattice_int.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

namespace orthoray::induction::octagonal {
namespace {

// Where two segments of different orientations meet, if they do.
template <class Int>
std::optional<Point<Int>> crossing(const Segment<Int>& p, const Segment<Int>& q) {
    if (p.orientation == q.orientation) return std::nullopt;
    const Segment<Int>& u = p.orientation < q.orientation ? p : q;
    const Segment<Int>& v = p.orientation < q.orientation ? q : p;
    Point<Int> at;
    if (u.orientation == Orientation::vertical) {
        // x = u.c; y from the other line.
        const Int y = v.orientation == Orientation::horizontal ? v.c
                      : v.orientation == Orientation::rising   ? Int(u.c + v.c)
                                                               : Int(v.c - u.c);
        at = {u.c, y};
    } else if (u.orientation == Orientation::horizontal) {
        at = {v.orientation == Orientation::rising ? Int(u.c - v.c) : Int(v.c - u.c), u.c};
    } else { // y - x = u.c and y + x = v.c; both even after scaling
        at = {Int((v.c - u.c) / 2), Int((v.c + u.c) / 2)};
    }
    for (const Segment<Int>* seg : {&u, &v}) {
        const Int& pos = position(seg->orientation, at);
        if (pos < seg->lo || seg->hi < pos) return std::nullopt;
    }
    return at;
}

} // namespace

// The crossings of the segments of orientation `a` with those of
// orientation `b`, by a sweep in the coordinates (u, v) = (the line
// constant of a, that of b), a linear change of coordinates in which an
// a-segment is a vertical run {u = c} x [v0, v1] and a b-segment a
// horizontal one [u0, u1] x {v = c}: the classic orthogonal sweep, the
// horizontal runs kept ordered by v while u passes their range, each
// vertical run asking for the v in its range. O((n + crossings) log n),
// where comparing every pair was O(n^2) (issue 14).
template <class Int>
void crossings_of(const std::vector<Segment<Int>>& segs, Orientation a, Orientation b,
                  std::vector<Point<Int>>& out, const std::function<void()>& poll) {
    struct Event {
        Int u;
        int kind; // 0: a horizontal run starts, 1: a vertical run asks, 2: one ends
        std::size_t segment;
    };
    std::vector<Event> events;
    for (std::size_t i = 0; i < segs.size(); ++i) {
        const Segment<Int>& s = segs[i];
        if (s.orientation == a) {
            events.push_back({s.c, 1, i});
        } else if (s.orientation == b) {
            Int u0 = line_constant(a, point_on(s.orientation, s.c, s.lo));
            Int u1 = line_constant(a, point_on(s.orientation, s.c, s.hi));
            if (u1 < u0) std::swap(u0, u1);
            events.push_back({u0, 0, i});
            events.push_back({u1, 2, i});
        }
    }
    // At one u the runs starting there come first and those ending there
    // last: segments are closed.
    std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) {
        return std::tie(x.u, x.kind, x.segment) < std::tie(y.u, y.kind, y.segment);
    });
    std::set<std::pair<Int, std::size_t>> open; // (v, segment) of the horizontal runs
    for (const Event& e : events) {
        poll();
        const Segment<Int>& s = segs[e.segment];
        if (e.kind == 0) {
            open.emplace(s.c, e.segment);
        } else if (e.kind == 2) {
            open.erase({s.c, e.segment});
        } else {
            Int v0 = line_constant(b, point_on(s.orientation, s.c, s.lo));
            Int v1 = line_constant(b, point_on(s.orientation, s.c, s.hi));
            if (v1 < v0) std::swap(v0, v1);
            for (auto it = open.lower_bound({v0, 0}); it != open.end() && !(v1 < it->first); ++it)
                if (auto at = crossing(s, segs[it->second])) out.push_back(*at);
        }
    }
}

template void crossings_of(const std::vector<Segment<lattice::int128_t>>&, Orientation, Orientation,
                           std::vector<Point<lattice::int128_t>>&, const std::function<void()>&);
template void crossings_of(const std::vector<Segment<Integer>>&, Orientation, Orientation,
                           std::vector<Point<Integer>>&, const std::function<void()>&);

} // namespace orthoray::induction::octagonal
