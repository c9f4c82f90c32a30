// The header and transversal checks (docs/induction-certificates.md, "What
// verify checks", 1 and 2). Point 1 and its direction come from the path
// checker's own rational scan (the path prefix); the transversals are state
// sets {u in [LO, HI] : w(u) in the class of point 1}, an arithmetic
// progression of step G on one line, so disjointness and "on a mirror" are
// checked on their ranges, not state by state.
#include "certify/induction_exchange_check.hpp"

#include "certify/induction_check_failure.hpp"
#include "certify/path_geometry.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <tuple>
#include <utility>

namespace orthoray::certify::induction_check {

Integer state_position(const Transversal& t, const Integer& index, const Integer& modulus) {
    if (t.increasing) return t.umin + index * modulus;
    return t.umax - index * modulus;
}

namespace {

class ExchangeCheck {
public:
    ExchangeCheck(const Scene& scene, const PathPrefix& prefix, const Parsed& parsed)
        : scene_(scene), prefix_(prefix), parsed_(parsed) {
        out_.modulus = parsed.modulus;
    }

    LatticeExchange run() {
        check_header();
        check_transversals();
        return std::move(out_);
    }

private:
    // ---------------------------------------------------------- header --

    Integer lattice(const Rational& x, const Rational& s, const std::string& what) const {
        const Rational v = x * s;
        if (v.get_den() != 1)
            fail("scale", "scale " + to_string(parsed_.sx) + " " + to_string(parsed_.sy) +
                              " makes " + what + " " + to_string(v) + ", not an integer");
        return v.get_num();
    }

    void check_header() {
        if (scene_.dim != 2)
            fail("header", "induction certificates are for 2D scenes, the scene has dim " +
                               std::to_string(scene_.dim));
        const int dim = 2;
        // The prefix p0 .. pr was checked point by point like a path, with
        // the target on none of its segments; the induction starts at p1.
        if (prefix_.failure) throw CheckFailure{*prefix_.failure};
        if (prefix_.points < 2)
            fail("header", "the path prefix has only point 0; the induction needs point 1");
        if (prefix_.absorbed)
            fail("header", "the ray is absorbed at point " + std::to_string(prefix_.points - 1) +
                               " of the path prefix");
        const Vector& v = prefix_.v1;
        const Rational& sx = parsed_.sx;
        const Rational& sy = parsed_.sy;
        if (!same(parsed_.v1, v, dim))
            fail("header", "direction " + show(parsed_.v1, dim) + " is not the direction " +
                               show(v, dim) + " the ray leaves point 1 in");

        if (sgn(sx) <= 0 || sgn(sy) <= 0)
            fail("scale", "scale " + to_string(sx) + " " + to_string(sy) + " is not positive");
        if (sgn(v[0]) == 0 || sgn(v[1]) == 0 || abs(v[0]) * sx != abs(v[1]) * sy)
            fail("scale", "the direction " + show(v, dim) + " is not diagonal in lattice terms: " +
                              "|v_x| * SX = " + to_string(Rational(abs(v[0]) * sx)) +
                              ", |v_y| * SY = " + to_string(Rational(abs(v[1]) * sy)));
        out_.first_dx = sgn(v[0]);
        out_.first_dy = sgn(v[1]);
        for (const Element& s : scene_.elements) {
            LatticeElement le;
            le.axis = s.axis;
            le.absorber = s.kind == ElementKind::absorber;
            le.source = &s;
            const int other = 1 - s.axis;
            const Rational& along_scale = s.axis == 0 ? sx : sy;
            const Rational& across_scale = other == 0 ? sx : sy;
            const std::string name = "an element coordinate";
            le.c = lattice(s.offset(), along_scale, name);
            le.lo = lattice(s.lo[other], across_scale, name);
            le.hi = lattice(s.hi[other], across_scale, name);
            out_.elements.push_back(std::move(le));
        }
        lattice(scene_.ray().start[0], sx, "the start's x");
        lattice(scene_.ray().start[1], sy, "the start's y");
        out_.first_x = lattice(prefix_.p1[0], sx, "point 1's x");
        out_.first_y = lattice(prefix_.p1[1], sy, "point 1's y");
        out_.target_x = lattice(scene_.target()[0], sx, "the target's x");
        out_.target_y = lattice(scene_.target()[1], sy, "the target's y");
        out_.first_class = out_.first_dy * out_.first_y - out_.first_dx * out_.first_x;
    }

    // ----------------------------------------------------- transversals --

    bool in_class(const Integer& w) const {
        if (sgn(out_.modulus) == 0) return w == out_.first_class;
        return sgn(floor_mod(w - out_.first_class, out_.modulus)) == 0;
    }

    // The smallest state u >= from (may exceed umax).
    Integer state_at_or_after(const Transversal& t, const Integer& from) const {
        if (sgn(out_.modulus) == 0) return from <= t.residue ? t.residue : Integer(from + 1);
        return from + floor_mod(t.residue - from, out_.modulus);
    }

    void check_transversals() {
        const Integer& g = out_.modulus;
        const Integer& w1 = out_.first_class;
        std::vector<Transversal>& transversals = out_.transversals;
        Integer offset = 0;
        for (std::size_t k = 0; k < parsed_.transversals.size(); ++k) {
            Transversal t;
            t.spec = parsed_.transversals[k];
            t.number = k;
            const TransversalSpec& s = t.spec;
            const std::string where = "transversal " + std::to_string(k);
            if (s.lo > s.hi) fail(where, "LO " + str(s.lo) + " > HI " + str(s.hi));
            // w = DY * Y - DX * X; on X = C it is DY * u - DX * C, on Y = C
            // it is DY * C - DX * u.
            if (s.a == 0) {
                t.residue = s.dy * (w1 + s.dx * s.c);
                t.increasing = s.dy == 1;
            } else {
                t.residue = s.dx * (s.dy * s.c - w1);
                t.increasing = s.dx == -1;
            }
            if (sgn(g) == 0) {
                t.umin = t.umax = t.residue;
                t.count = s.lo <= t.residue && t.residue <= s.hi ? 1 : 0;
            } else {
                t.residue = floor_mod(t.residue, g);
                t.umin = s.lo + floor_mod(t.residue - s.lo, g);
                t.umax = s.hi - floor_mod(s.hi - t.residue, g);
                t.count = t.umin <= t.umax ? Integer((t.umax - t.umin) / g + 1) : Integer(0);
            }
            if (sgn(t.count) == 0)
                fail(where, "no u in [" + str(s.lo) + ", " + str(s.hi) +
                                "] is in the class of the first state, so it has no state");
            t.offset = offset;
            offset += t.count;
            transversals.push_back(std::move(t));
        }
        out_.state_count = offset;

        check_disjoint();
        for (const Transversal& t : transversals) check_on_mirrors(t);

        // `first`: the state (p1, v1).
        const Integer& first_t = parsed_.first_t;
        const Integer& first_i = parsed_.first_i;
        if (first_t >= transversals.size())
            fail("first", "transversal " + str(first_t) + " does not exist (there are " +
                              std::to_string(transversals.size()) + ")");
        const Transversal& t = transversals[first_t.get_ui()];
        if (first_i >= t.count)
            fail("first", "transversal " + str(first_t) + " has " + str(t.count) +
                              " states, no state " + str(first_i));
        const Integer u = state_position(t, first_i, g);
        const Integer x = t.spec.a == 0 ? t.spec.c : u;
        const Integer y = t.spec.a == 0 ? u : t.spec.c;
        if (x != out_.first_x || y != out_.first_y || t.spec.dx != out_.first_dx ||
            t.spec.dy != out_.first_dy)
            fail("first", "state " + str(first_i) + " of transversal " + str(first_t) +
                              " is the lattice point " + pair_text(x, y) + " with direction " +
                              pair_text(t.spec.dx, t.spec.dy) + ", not point 1 " +
                              pair_text(out_.first_x, out_.first_y) + " with direction " +
                              pair_text(out_.first_dx, out_.first_dy));
        out_.first_raw = t.offset + first_i;
    }

    void check_disjoint() const {
        const std::vector<Transversal>& transversals = out_.transversals;
        // On one line with one direction every transversal has the same
        // class, so trimmed to their first and last states, two state sets
        // meet exactly when their ranges do.
        std::vector<const Transversal*> order;
        for (const Transversal& t : transversals) order.push_back(&t);
        auto key = [](const Transversal* t) {
            return std::make_tuple(t->spec.dx, t->spec.dy, t->spec.a);
        };
        std::sort(order.begin(), order.end(), [&](const Transversal* a, const Transversal* b) {
            if (key(a) != key(b)) return key(a) < key(b);
            if (a->spec.c != b->spec.c) return a->spec.c < b->spec.c;
            return a->umin < b->umin;
        });
        for (std::size_t k = 1; k < order.size(); ++k) {
            const Transversal& a = *order[k - 1];
            const Transversal& b = *order[k];
            if (key(&a) == key(&b) && a.spec.c == b.spec.c && b.umin <= a.umax)
                fail("transversal " + std::to_string(std::max(a.number, b.number)),
                     "shares the state u = " + str(b.umin) + " on its line with transversal " +
                         std::to_string(std::min(a.number, b.number)));
        }
        // A line X = C and a line Y = C' with one direction share at most
        // their crossing point (C, C').
        for (const Transversal& v : transversals) {
            if (v.spec.a != 0) continue;
            for (const Transversal& h : transversals) {
                if (h.spec.a != 1 || h.spec.dx != v.spec.dx || h.spec.dy != v.spec.dy) continue;
                const Integer& x = v.spec.c;
                const Integer& y = h.spec.c;
                if (y < v.umin || y > v.umax || x < h.umin || x > h.umax) continue;
                if (!in_class(v.spec.dy * y - v.spec.dx * x)) continue;
                fail("transversal " + std::to_string(std::max(v.number, h.number)),
                     "shares the state at the lattice point " + pair_text(x, y) +
                         " with transversal " + std::to_string(std::min(v.number, h.number)));
            }
        }
    }

    void check_on_mirrors(const Transversal& t) const {
        // The closed u-ranges of the mirrors on the line, and the crossing
        // points of mirrors across it.
        std::vector<Range> cover;
        for (const LatticeElement& e : out_.elements) {
            if (e.absorber) continue;
            if (e.axis == t.spec.a) {
                if (e.c == t.spec.c) cover.push_back({e.lo, e.hi});
            } else if (e.lo <= t.spec.c && t.spec.c <= e.hi) {
                cover.push_back({e.c, e.c});
            }
        }
        std::sort(cover.begin(), cover.end(),
                  [](const Range& a, const Range& b) { return a.lo < b.lo; });
        Integer next = t.umin; // every state below `next` is covered
        for (const Range& r : cover) {
            if (next > t.umax) break;
            if (r.hi < next) continue;
            if (r.lo > next) {
                const Integer u = state_at_or_after(t, next);
                if (u < r.lo && u <= t.umax) uncovered(t, u);
            }
            next = std::max(next, Integer(r.hi + 1));
        }
        if (next <= t.umax) {
            const Integer u = state_at_or_after(t, next);
            if (u <= t.umax) uncovered(t, u);
        }
    }

    [[noreturn]] static void uncovered(const Transversal& t, const Integer& u) {
        const Integer x = t.spec.a == 0 ? t.spec.c : u;
        const Integer y = t.spec.a == 0 ? u : t.spec.c;
        fail("transversal " + std::to_string(t.number),
             "its state at the lattice point " + pair_text(x, y) + " is on no mirror");
    }

    const Scene& scene_;
    const PathPrefix& prefix_;
    const Parsed& parsed_;
    LatticeExchange out_;
};

} // namespace

LatticeExchange check_header_and_transversals(const Scene& scene, const PathPrefix& prefix,
                                              const Parsed& parsed) {
    return ExchangeCheck(scene, prefix, parsed).run();
}

} // namespace orthoray::certify::induction_check
