// Points and states for M = 3, by inclusion-exclusion over the three axes:
// each plane's rectangles are cut into disjoint cells, the points on a face
// of one axis and a face of another (lines) are subtracted once, the points
// on faces of all three axes (corners) added back once.
#include "bounds/state_count.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace orthoray::bounds {
namespace {

using lattice::Coords;
using lattice::LatticeElement;
using lattice::LatticeScene;

struct Interval {
    Integer lo, hi;
};

// The union of the elements in one plane x_axis = offset, as disjoint
// rectangles [lo, hi] on the free axes free[0] < free[1].
struct Plane {
    int axis = 0;
    Integer offset;
    int free[2] = {0, 0};
    std::vector<std::array<Interval, 2>> cells;

    bool covers(const Integer& u, const Integer& v) const {
        for (const auto& c : cells)
            if (c[0].lo <= u && u <= c[0].hi && c[1].lo <= v && v <= c[1].hi) return true;
        return false;
    }

    // The positions along free axis `along` of the points whose other free
    // coordinate is `at`, as sorted disjoint intervals.
    std::vector<Interval> line(int along, const Integer& at) const {
        const int i = free[0] == along ? 0 : 1;
        std::vector<Interval> out;
        for (const auto& c : cells)
            if (c[1 - i].lo <= at && at <= c[1 - i].hi) out.push_back(c[i]);
        std::sort(out.begin(), out.end(),
                  [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
        std::vector<Interval> merged;
        for (const Interval& x : out) {
            if (!merged.empty() && x.lo <= merged.back().hi + 1)
                merged.back().hi = std::max(merged.back().hi, x.hi);
            else
                merged.push_back(x);
        }
        return merged;
    }
};

// Cuts the rectangles of one plane along every edge (coordinate compression)
// and keeps the cells some rectangle covers: disjoint, same union.
std::vector<std::array<Interval, 2>> disjoint_cells(const std::vector<const LatticeElement*>& rects,
                                                    const int (&free)[2]) {
    std::vector<Integer> cuts[2];
    for (const LatticeElement* e : rects)
        for (int i = 0; i < 2; ++i) {
            cuts[i].push_back(e->lo[free[i]]);
            cuts[i].push_back(e->hi[free[i]] + 1);
        }
    for (auto& c : cuts) {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
    }
    std::vector<std::array<Interval, 2>> cells;
    for (std::size_t a = 0; a + 1 < cuts[0].size(); ++a)
        for (std::size_t b = 0; b + 1 < cuts[1].size(); ++b) {
            const std::array<Interval, 2> cell = {Interval{cuts[0][a], cuts[0][a + 1] - 1},
                                                  Interval{cuts[1][b], cuts[1][b + 1] - 1}};
            for (const LatticeElement* e : rects)
                if (e->lo[free[0]] <= cell[0].lo && cell[0].hi <= e->hi[free[0]] &&
                    e->lo[free[1]] <= cell[1].lo && cell[1].hi <= e->hi[free[1]]) {
                    cells.push_back(cell);
                    break;
                }
        }
    return cells;
}

std::vector<Plane> planes(const LatticeScene& ls) {
    std::map<std::pair<int, Integer>, std::vector<const LatticeElement*>> groups;
    for (const LatticeElement& e : ls.elements) groups[{e.axis, e.lo[e.axis]}].push_back(&e);
    std::vector<Plane> out;
    for (const auto& [key, rects] : groups) {
        Plane p;
        p.axis = key.first;
        p.offset = key.second;
        p.free[0] = key.first == 0 ? 1 : 0;
        p.free[1] = key.first == 2 ? 1 : 2;
        p.cells = disjoint_cells(rects, p.free);
        out.push_back(std::move(p));
    }
    return out;
}

std::vector<Interval> intersect(const std::vector<Interval>& a, const std::vector<Interval>& b) {
    std::vector<Interval> out;
    for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
        const Integer lo = std::max(a[i].lo, b[j].lo), hi = std::min(a[i].hi, b[j].hi);
        if (lo <= hi) out.push_back({lo, hi});
        if (a[i].hi < b[j].hi)
            ++i;
        else
            ++j;
    }
    return out;
}

} // namespace

// Refined states: on a cell of a plane normal to k, the states keeping the
// two invariants D_kj that involve k (the third is dropped: this over-counts
// only states that break it); on a line where planes normal to k and l meet,
// and at a corner, the states keeping all three, exactly. By
// inclusion-exclusion a state keeping every invariant is counted once, and
// any other state at most once: an upper bound on the states that keep them.
StateCount count_space_states(const LatticeScene& ls, const LineInvariant& inv) {
    StateCount n;
    const std::vector<Plane> all = planes(ls);
    for (const Plane& p : all)
        for (const auto& c : p.cells) {
            n.points += (c[0].hi - c[0].lo + 1) * (c[1].hi - c[1].lo + 1);
            for (unsigned s = 0; s < 8; ++s)
                n.refined += inv.count(p.offset, p.axis, p.free[0], c[0].lo, c[0].hi, s) *
                             inv.count(p.offset, p.axis, p.free[1], c[1].lo, c[1].hi, s);
        }
    for (const Plane& p : all)
        for (const Plane& q : all) {
            if (q.axis <= p.axis) continue;
            const int k = p.axis, l = q.axis, m = 3 - k - l;
            // The line x_k = p.offset, x_l = q.offset, along m.
            const std::vector<Interval> line = intersect(p.line(m, q.offset), q.line(m, p.offset));
            Coords x;
            x[k] = p.offset;
            x[l] = q.offset;
            for (const Interval& piece : line) {
                n.points -= piece.hi - piece.lo + 1;
                for (unsigned s = 0; s < 8; ++s)
                    if (inv.holds(x, s, k, l))
                        n.refined -= count_congruent_both(
                            piece.lo, piece.hi, inv.residue(p.offset, k, m, s), inv.modulus[k][m],
                            inv.residue(q.offset, l, m, s), inv.modulus[l][m]);
                if (k != 0 || l != 1) continue;
                // Corners: planes normal to z crossing this x-y line.
                for (const Plane& r : all) {
                    if (r.axis != 2 || r.offset < piece.lo || piece.hi < r.offset ||
                        !r.covers(p.offset, q.offset))
                        continue;
                    x[2] = r.offset;
                    n.points += 1;
                    for (unsigned s = 0; s < 8; ++s)
                        if (inv.holds(x, s)) n.refined += 1;
                }
            }
        }
    return n;
}

} // namespace orthoray::bounds
