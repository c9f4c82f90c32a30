// The lattice bound and the line-invariant bound on a trajectory's states;
// the formulas and their derivation are in docs/bounds.md.
#include "orthoray/bounds.hpp"

#include "lattice/lattice_scene.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace orthoray {
namespace {

using lattice::Coords;
using lattice::LatticeElement;
using lattice::LatticeScene;

std::size_t bits(const Integer& x) {
    return x == 0 ? 0 : mpz_sizeinbase(x.get_mpz_t(), 2);
}

std::size_t input_bits(const Scene& scene) {
    std::size_t total = 0;
    auto take = [&](const Rational& x) { total += bits(x.get_num()) + bits(x.get_den()); };
    for (const Element& e : scene.elements)
        for (int j = 0; j < scene.dim; ++j) {
            take(e.lo[j]);
            if (j != e.axis) take(e.hi[j]);
        }
    for (int j = 0; j < scene.dim; ++j) {
        take(scene.start[j]);
        take(scene.direction[j]);
        take(scene.target[j]);
    }
    return total;
}

Integer gcd(const Integer& a, const Integer& b) {
    Integer g;
    mpz_gcd(g.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return g;
}

Integer floor_div(const Integer& a, const Integer& b) {
    Integer q;
    mpz_fdiv_q(q.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
    return q;
}

// Integers x in [lo, hi] with x = r (mod G); G = 0 means x = r.
Integer count_congruent(const Integer& lo, const Integer& hi, const Integer& r, const Integer& G) {
    if (hi < lo) return 0;
    if (G == 0) return lo <= r && r <= hi ? 1 : 0;
    return floor_div(hi - r, G) - floor_div(lo - 1 - r, G);
}

// The line invariant (docs/bounds.md): with s the direction (+-1 per axis)
// and o_k the offset of some mirror normal to axis k,
//     D_kj(x, s) = s_k (x_k - o_k) - s_j (x_j - o_j)
// is constant along a segment and changes by a multiple of G_kj =
// 2 gcd(g_k, g_j) at a reflection, g_k the gcd of the differences of the
// offsets of the mirrors normal to axis k.
struct LineInvariant {
    int dim = 0;
    Coords origin;                                 // o_k
    std::array<std::array<Integer, 3>, 3> modulus; // G_kj
    std::array<std::array<Integer, 3>, 3> start;   // D_kj of the start state

    static int sign(unsigned mask, int axis) { return (mask >> axis) & 1u ? -1 : 1; }

    Integer value(const Coords& x, unsigned s, int k, int j) const {
        return sign(s, k) * (x[k] - origin[k]) - sign(s, j) * (x[j] - origin[j]);
    }

    // Whether the state (x, s) keeps every invariant of the start.
    bool holds(const Coords& x, unsigned s) const {
        for (int k = 0; k < dim; ++k)
            for (int j = k + 1; j < dim; ++j) {
                const Integer d = value(x, s, k, j) - start[k][j];
                if (modulus[k][j] == 0 ? d != 0 : Integer(d % modulus[k][j]) != 0) return false;
            }
        return true;
    }

    // Positions x_j in [lo, hi] on a mirror x_k = c that keep D_kj in
    // direction s: s_j (x_j - o_j) = s_k (c - o_k) - D_kj(start) (mod G_kj).
    Integer count(const Integer& c, int k, int j, const Integer& lo, const Integer& hi,
                  unsigned s) const {
        const Integer r = origin[j] + sign(s, j) * (sign(s, k) * (c - origin[k]) - start[k][j]);
        return count_congruent(lo, hi, r, modulus[k][j]);
    }
};

LineInvariant line_invariant(const LatticeScene& ls) {
    LineInvariant inv;
    inv.dim = ls.dim;
    std::array<bool, 3> seen{};
    std::array<Integer, 3> g;
    for (const LatticeElement& e : ls.elements) {
        if (e.absorber) continue; // absorbers do not reflect: they change no invariant
        const Integer& c = e.lo[e.axis];
        if (!seen[e.axis]) {
            seen[e.axis] = true;
            inv.origin[e.axis] = c;
        }
        g[e.axis] = gcd(g[e.axis], c - inv.origin[e.axis]);
    }
    for (int k = 0; k < ls.dim; ++k)
        for (int j = 0; j < ls.dim; ++j)
            if (j != k) {
                inv.modulus[k][j] = 2 * gcd(g[k], g[j]);
                inv.start[k][j] = inv.value(ls.start, ls.start_direction, k, j);
            }
    return inv;
}

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

void count_plane(const LatticeScene& ls, const LineInvariant& inv, StateBounds& b) {
    const std::vector<Run> runs = merged_runs(ls);
    const unsigned directions = 1u << ls.dim;
    std::vector<const Run*> horizontal;
    for (const Run& r : runs) {
        b.points += ls.dim == 2 ? Integer(r.hi - r.lo + 1) : Integer(1);
        for (unsigned s = 0; s < directions; ++s)
            b.refined_states +=
                ls.dim == 2 ? inv.count(r.offset, r.axis, 1 - r.axis, r.lo, r.hi, s) : Integer(1);
        if (ls.dim == 2 && r.axis == 1) horizontal.push_back(&r);
    }
    if (ls.dim < 2) return;
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
                if (inv.holds(x, s)) b.refined_states -= 1;
        }
    }
}

// 3D: every element's points and invariant-keeping states, summed (points
// shared by elements are counted once per element: an upper bound). On a
// mirror normal to k only the two invariants D_kj involving k are used; the
// third couples the two free coordinates and is dropped (an upper bound).
void count_space(const LatticeScene& ls, const LineInvariant& inv, StateBounds& b) {
    b.points_exact = false;
    for (const LatticeElement& e : ls.elements) {
        Integer points = 1;
        for (int j = 0; j < 3; ++j)
            if (j != e.axis) points *= e.hi[j] - e.lo[j] + 1;
        b.points += points;
        for (unsigned s = 0; s < 8; ++s) {
            Integer states = 1;
            for (int j = 0; j < 3; ++j)
                if (j != e.axis) states *= inv.count(e.lo[e.axis], e.axis, j, e.lo[j], e.hi[j], s);
            b.refined_states += states;
        }
    }
}

} // namespace

StateBounds compute_bounds(const Scene& scene, bool with_pieces) {
    const LatticeScene ls = lattice::make_lattice(scene);
    StateBounds b;
    b.dim = ls.dim;
    b.active = ls.active;
    b.scale = ls.scale;
    b.elements = ls.elements.size();
    b.input_bits = input_bits(scene);
    b.magnitude_bits = bits(ls.magnitude);
    b.state_bits = static_cast<std::size_t>(ls.dim) * (b.magnitude_bits + 2);
    const LineInvariant inv = line_invariant(ls);
    for (int k = 0, p = 0; k < ls.dim; ++k)
        for (int j = k + 1; j < ls.dim; ++j)
            b.line_modulus[static_cast<std::size_t>(p++)] = inv.modulus[k][j];
    if (ls.dim == 3)
        count_space(ls, inv, b);
    else
        count_plane(ls, inv, b);
    b.lattice_states = b.points * (1u << ls.dim);
    if (with_pieces && scene.dim == 2 && ls.dim == 2) {
        const lattice::UniformGrid<Integer, 2> grid(ls);
        const auto table = lattice::PieceTable<Integer>::build(ls, grid, ~std::size_t{0});
        b.pieces = table ? table->size() : 0;
    }
    return b;
}

std::optional<Integer> states_visited(const Answer& answer) {
    switch (answer.reason) {
    case Reason::cycle:
    case Reason::hit:
    case Reason::escape:
        return answer.reflections;
    case Reason::absorbed:
        return Integer(answer.reflections + 1);
    case Reason::limit:
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace orthoray
