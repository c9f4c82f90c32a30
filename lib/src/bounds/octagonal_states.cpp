// Points and states of a scene with diagonals (docs/bounds.md, "Diagonal
// elements"): collinear elements merged into runs along their lines, points
// shared by runs of different orientations found pairwise and counted once,
// and the states that keep the lattice's line invariant cross(w, P) = 0
// (mod N).
#include "bounds/state_count.hpp"
#include "lattice/lattice_int.hpp" // floor_mod

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace orthoray::bounds {
namespace {

using lattice::Orientation;

// The integer points P(s) = base + s * step, s in [lo, hi], of one maximal
// run on a line of one orientation.
struct Run {
    Orientation orientation;
    Integer offset, lo, hi;
    Integer x_lo, x_hi; // the run's extent in x, for the sweep
};

// A line of each orientation, parametrised: x = k by y, the others by x.
lattice::Coords point_at(Orientation o, const Integer& k, const Integer& s) {
    switch (o) {
    case lattice::normal_x:
        return {k, s, 0};
    case lattice::normal_y:
        return {s, k, 0};
    case lattice::rising: // x - y = k
        return {s, s - k, 0};
    case lattice::falling: // x + y = k
        return {s, k - s, 0};
    }
    return {};
}

Integer parameter_of(Orientation o, const lattice::Coords& p) {
    return o == lattice::normal_x ? p[1] : p[0];
}

std::vector<Run> merged_runs(const lattice::OctagonalLattice& l) {
    std::map<std::pair<int, Integer>, std::vector<std::pair<Integer, Integer>>> lines;
    for (const lattice::OctagonalElement& e : l.elements) {
        const int s = e.orientation == lattice::normal_x ? 1 : 0;
        lines[{e.orientation, e.offset}].emplace_back(e.lo[s], e.hi[s]);
    }
    std::vector<Run> runs;
    for (auto& [line, intervals] : lines) {
        std::sort(intervals.begin(), intervals.end());
        const auto o = static_cast<Orientation>(line.first);
        const std::size_t first = runs.size();
        for (const auto& [lo, hi] : intervals) {
            if (runs.size() > first && lo <= runs.back().hi + 1) {
                runs.back().hi = std::max(runs.back().hi, hi);
                continue;
            }
            runs.push_back({o, line.second, lo, hi, 0, 0});
        }
    }
    for (Run& r : runs) {
        r.x_lo = point_at(r.orientation, r.offset, r.lo)[0];
        r.x_hi = point_at(r.orientation, r.offset, r.hi)[0];
    }
    return runs;
}

// The point two lines of different orientations share, if it is integral.
bool meet(const Run& a, const Run& b, lattice::Coords& p) {
    auto on = [](const Run& r, const lattice::Coords& q) {
        const Integer s = parameter_of(r.orientation, q);
        return point_at(r.orientation, r.offset, s) == q && r.lo <= s && s <= r.hi;
    };
    const Run& first = a.orientation < b.orientation ? a : b;
    const Run& second = a.orientation < b.orientation ? b : a;
    if (first.orientation == lattice::normal_x) {
        p = second.orientation == lattice::normal_y
                ? lattice::Coords{first.offset, second.offset, 0}
                : point_at(second.orientation, second.offset, first.offset);
    } else if (first.orientation == lattice::normal_y) {
        // y = k on x - y = m: x = m + k; on x + y = m: x = m - k.
        p = second.orientation == lattice::rising
                ? lattice::Coords{second.offset + first.offset, first.offset, 0}
                : lattice::Coords{second.offset - first.offset, first.offset, 0};
    } else { // x - y = k and x + y = m: x = (k + m) / 2
        const Integer twice_x = first.offset + second.offset;
        if (lattice::floor_mod(twice_x, 2) != 0) return false;
        p = point_at(lattice::rising, first.offset, twice_x / 2);
    }
    return on(first, p) && on(second, p);
}

// Whether the state (p, w) keeps the line invariant: cross(w, p) = 0 (mod N).
bool keeps(const lattice::Coords& p, const std::array<Integer, 2>& w, const Integer& N) {
    return lattice::floor_mod(w[0] * p[1] - w[1] * p[0], N) == 0;
}

// Parameters s in [lo, hi] of a run with cross(w, P(s)) = 0 (mod N): the
// linear congruence A + s B = 0, A = cross(w, P(0)), B = cross(w, step).
Integer keeping(const Run& r, const std::array<Integer, 2>& w, const Integer& N) {
    const lattice::Coords base = point_at(r.orientation, r.offset, 0);
    const lattice::Coords next = point_at(r.orientation, r.offset, 1);
    const Integer A = w[0] * base[1] - w[1] * base[0];
    const Integer B = w[0] * (next[1] - base[1]) - w[1] * (next[0] - base[0]);
    const Integer g = gcd(B, N);
    if (lattice::floor_mod(A, g) != 0) return 0;
    const Integer modulus = N / g;
    Integer s0 = 0;
    if (modulus != 1) {
        Integer inverse;
        const Integer b = lattice::floor_mod(Integer(B / g), modulus);
        mpz_invert(inverse.get_mpz_t(), b.get_mpz_t(), modulus.get_mpz_t());
        s0 = lattice::floor_mod(Integer(-(A / g) * inverse), modulus);
    }
    return count_congruent(r.lo, r.hi, s0, modulus);
}

} // namespace

StateCount count_octagonal_states(const lattice::OctagonalLattice& l) {
    const Integer& N = l.modulus;
    StateCount count;
    std::vector<Run> runs = merged_runs(l);
    for (const Run& r : runs) {
        count.points += r.hi - r.lo + 1;
        for (unsigned d = 0; d < lattice::direction_count; ++d)
            if (l.canonical[d] == d) count.refined += keeping(r, l.w[d], N);
    }
    // Points on m runs (of m different orientations) were counted m times:
    // find them pairwise (a sweep over x: only runs whose x extents overlap
    // can share a point), m from the m (m - 1) / 2 pairs.
    std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.x_lo < b.x_lo; });
    std::map<std::pair<Integer, Integer>, int> pairs;
    for (std::size_t i = 0; i < runs.size(); ++i)
        for (std::size_t j = i + 1; j < runs.size() && runs[j].x_lo <= runs[i].x_hi; ++j) {
            lattice::Coords p;
            if (runs[i].orientation != runs[j].orientation && meet(runs[i], runs[j], p))
                ++pairs[{p[0], p[1]}];
        }
    for (const auto& [point, n] : pairs) {
        const int extra = n == 1 ? 1 : n == 3 ? 2 : 3; // m - 1 for n = 1, 3, 6
        count.points -= extra;
        const lattice::Coords p{point.first, point.second, 0};
        for (unsigned d = 0; d < lattice::direction_count; ++d)
            if (l.canonical[d] == d && keeps(p, l.w[d], N)) count.refined -= extra;
    }
    return count;
}

} // namespace orthoray::bounds
