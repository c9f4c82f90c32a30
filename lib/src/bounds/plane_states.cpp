// Points and states for M = 1 and 2: collinear elements merged into runs,
// crossings of a vertical and a horizontal run counted once.
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

// One maximal run of integer points on mirrors of one axis and offset.
struct Run {
    int axis = 0;
    Integer offset, lo, hi; // along the other axis (2D) or unused (1D)
};

// For M <= 2: the elements' points as disjoint runs (overlapping collinear
// elements merged), so that every point is counted once except crossings.
std::vector<Run> merged_runs(const LatticeScene& ls) {
    std::map<std::pair<int, Integer>, std::vector<std::pair<Integer, Integer>>> lines;
    for (const LatticeElement& e : ls.elements) {
        const int t = ls.dim == 2 ? 1 - e.axis : e.axis;
        lines[{e.axis, e.lo[e.axis]}].emplace_back(e.lo[t], e.hi[t]);
    }
    std::vector<Run> runs;
    for (auto& [line, intervals] : lines) {
        std::sort(intervals.begin(), intervals.end());
        for (const auto& [lo, hi] : intervals) {
            if (!runs.empty() && runs.back().axis == line.first &&
                runs.back().offset == line.second && lo <= runs.back().hi + 1) {
                runs.back().hi = std::max(runs.back().hi, hi);
                continue;
            }
            runs.push_back({line.first, line.second, lo, hi});
        }
    }
    return runs;
}

} // namespace

StateCount count_line_and_plane_states(const LatticeScene& ls, const LineInvariant& inv) {
    StateCount b;
    const std::vector<Run> runs = merged_runs(ls);
    const unsigned directions = 1u << ls.dim;
    std::vector<const Run*> horizontal;
    for (const Run& r : runs) {
        b.points += ls.dim == 2 ? Integer(r.hi - r.lo + 1) : Integer(1);
        for (unsigned s = 0; s < directions; ++s)
            b.refined +=
                ls.dim == 2 ? inv.count(r.offset, r.axis, 1 - r.axis, r.lo, r.hi, s) : Integer(1);
        if (ls.dim == 2 && r.axis == 1) horizontal.push_back(&r);
    }
    if (ls.dim < 2) return b;
    // A point where a vertical and a horizontal run cross was counted twice.
    std::sort(horizontal.begin(), horizontal.end(),
              [](const Run* a, const Run* c) { return a->offset < c->offset; });
    for (const Run& v : runs) {
        if (v.axis != 0) continue;
        auto first = std::lower_bound(horizontal.begin(), horizontal.end(), v.lo,
                                      [](const Run* h, const Integer& y) { return h->offset < y; });
        for (auto it = first; it != horizontal.end() && (*it)->offset <= v.hi; ++it) {
            const Run& h = **it;
            if (v.offset < h.lo || h.hi < v.offset) continue;
            b.points -= 1;
            const Coords x = {v.offset, h.offset, 0};
            for (unsigned s = 0; s < directions; ++s)
                if (inv.holds(x, s)) b.refined -= 1;
        }
    }
    return b;
}

} // namespace orthoray::bounds
