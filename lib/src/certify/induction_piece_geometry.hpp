// The lattice geometry the induction checker needs to check a piece of the
// exchange for all its states at once: the states of a piece are lattice
// points Q(j) = Q0 + j * step on one line, so where the ray from Q(j) meets
// an element is affine in j, and the j meeting it form an interval found by
// exact floor and ceiling divisions. Checker code only.
#pragma once

#include "orthoray/number.hpp"

#include <cstddef>
#include <string>

namespace orthoray::certify::induction_check {

// a + b * j.
struct Affine {
    Integer a, b;
    Integer at(const Integer& j) const { return a + b * j; }
};

inline Affine operator-(const Affine& f, const Affine& g) {
    return {f.a - g.a, f.b - g.b};
}
inline Affine scaled(int s, const Affine& f) {
    return {s * f.a, s * f.b};
}

// A closed interval of state numbers j; empty when lo > hi.
struct Range {
    Integer lo, hi;
    bool empty() const { return lo > hi; }
    bool contains(const Integer& j) const { return lo <= j && j <= hi; }
};

// Narrows `r` to the j with a + b * j >= k; `q` is scratch space (this runs
// for every piece and element, so it allocates nothing once warm).
inline void at_least(Range& r, const Integer& a, const Integer& b, const Integer& k, Integer& q) {
    if (r.empty()) return;
    const int s = sgn(b);
    if (s == 0) {
        if (a < k) mpz_sub_ui(r.hi.get_mpz_t(), r.lo.get_mpz_t(), 1);
        return;
    }
    mpz_sub(q.get_mpz_t(), k.get_mpz_t(), a.get_mpz_t());
    if (s > 0) {
        mpz_cdiv_q(q.get_mpz_t(), q.get_mpz_t(), b.get_mpz_t());
        if (q > r.lo) r.lo = q;
    } else {
        mpz_fdiv_q(q.get_mpz_t(), q.get_mpz_t(), b.get_mpz_t());
        if (q < r.hi) r.hi = q;
    }
}

// Narrows `r` to the j with a + b * j <= k.
inline void at_most(Range& r, const Integer& a, const Integer& b, const Integer& k, Integer& q) {
    if (r.empty()) return;
    const int s = sgn(b);
    if (s == 0) {
        if (a > k) mpz_sub_ui(r.hi.get_mpz_t(), r.lo.get_mpz_t(), 1);
        return;
    }
    mpz_sub(q.get_mpz_t(), k.get_mpz_t(), a.get_mpz_t());
    if (s > 0) {
        mpz_fdiv_q(q.get_mpz_t(), q.get_mpz_t(), b.get_mpz_t());
        if (q < r.hi) r.hi = q;
    } else {
        mpz_cdiv_q(q.get_mpz_t(), q.get_mpz_t(), b.get_mpz_t());
        if (q > r.lo) r.lo = q;
    }
}

inline void at_least(Range& r, const Affine& f, const Integer& k) {
    Integer q;
    at_least(r, f.a, f.b, k, q);
}

// An element in lattice coordinates: the line {axis coordinate = c}, the
// closed range [lo, hi] of the other coordinate.
struct LatticeElement {
    int axis = 0;
    Integer c, lo, hi;
    bool absorber = false;
    const Element* source = nullptr;
};

inline std::string describe(const LatticeElement& e) {
    const Element& s = *e.source;
    const int other = 1 - s.axis;
    std::string text =
        std::string(s.kind == ElementKind::absorber ? "the absorber " : "the mirror ") +
        axis_name(s.axis) + " = " + to_string(s.offset()) + ", " + axis_name(other) + " in [" +
        to_string(s.lo[other]) + ", " + to_string(s.hi[other]) + "]";
    if (s.line > 0) text += " (scene line " + std::to_string(s.line) + ")";
    return text;
}

// A run of consecutive states of one transversal: state j (0 <= j < n) is
// the lattice point (qx(j), qy(j)) with direction (dx, dy).
struct Run {
    std::size_t transversal = 0;
    Integer first_index; // of state j = 0 within its transversal
    Integer n;
    Integer rotated; // rotated coordinate of state j = 0
    int dx = 1, dy = 1;
    Affine qx, qy;
};

// Where the ray from the states of a run meets an element: the states j in
// `states`, at parameter t(j) (the ray moves by t in each lattice axis).
struct Meeting {
    Range states;
    Affine t;
};

struct Scratch {
    Integer q, along_a, along_b;
    const Integer one = 1;
};

// Fills `m` in place (see Scratch).
inline void meet(const LatticeElement& e, const Run& run, Meeting& m, Scratch& s) {
    // The coordinate normal to the element, t = d * (c - q(j)); then the
    // coordinate along it where the ray crosses its line, q'(j) + d' * t.
    const Affine& normal = e.axis == 0 ? run.qx : run.qy;
    const Affine& other = e.axis == 0 ? run.qy : run.qx;
    const int d_normal = e.axis == 0 ? run.dx : run.dy;
    const int d_other = e.axis == 0 ? run.dy : run.dx;
    mpz_sub(m.t.a.get_mpz_t(), e.c.get_mpz_t(), normal.a.get_mpz_t());
    mpz_set(m.t.b.get_mpz_t(), normal.b.get_mpz_t());
    if (d_normal < 0)
        mpz_neg(m.t.a.get_mpz_t(), m.t.a.get_mpz_t());
    else
        mpz_neg(m.t.b.get_mpz_t(), m.t.b.get_mpz_t());
    m.states.lo = 0;
    mpz_sub_ui(m.states.hi.get_mpz_t(), run.n.get_mpz_t(), 1);
    at_least(m.states, m.t.a, m.t.b, s.one, s.q); // nothing happens at t = 0
    if (m.states.empty()) return;
    if (d_other > 0) {
        mpz_add(s.along_a.get_mpz_t(), other.a.get_mpz_t(), m.t.a.get_mpz_t());
        mpz_add(s.along_b.get_mpz_t(), other.b.get_mpz_t(), m.t.b.get_mpz_t());
    } else {
        mpz_sub(s.along_a.get_mpz_t(), other.a.get_mpz_t(), m.t.a.get_mpz_t());
        mpz_sub(s.along_b.get_mpz_t(), other.b.get_mpz_t(), m.t.b.get_mpz_t());
    }
    at_least(m.states, s.along_a, s.along_b, e.lo, s.q);
    at_most(m.states, s.along_a, s.along_b, e.hi, s.q);
}

struct Transversal {
    TransversalSpec spec;
    Integer residue;    // the u of the class (G = 0: the only u)
    Integer umin, umax; // the smallest and largest u of a state
    Integer count, offset;
    bool increasing = true; // w grows with u
    std::size_t number = 0;
};

} // namespace orthoray::certify::induction_check
