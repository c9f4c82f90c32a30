// The induction certificate checker (docs/induction-certificates.md).
//
// It reads the whole certificate first (syntax errors win over everything),
// then checks, in the order of the doc's "What verify checks":
//   1. the header: p0, the first reflection (p1, v1) by the path checker's
//      own rational scan, the scale (integral lattice, diagonal direction);
//   2. the transversals: non-empty, pairwise disjoint state sets, every
//      state on a mirror, `first` naming (p1, v1);
//   3. the pieces: domains and images tile [0, N), and each piece's claim
//      (next state, escape, absorption, hit flag) holds for all its states
//      at once. The states of a piece inside one transversal are lattice
//      points Q(j) = Q0 + j * step on one line, j in [0, n), all with one
//      direction, so the parameter at which the ray from Q(j) meets an
//      element is affine in j, and so is the point where it meets the
//      element's line: the states meeting an element form an interval of
//      j, found by exact floor and ceiling divisions, and comparisons of two
//      affine functions over an interval only need its two ends. That makes
//      the check O(elements) per piece, whatever the piece's length;
//   4. the induction steps, replayed on explicit interval positions with
//      their conditions, and the verdict they give for piece 0 (x);
//   5. for short answers, a re-simulation with the path checker's rule.
// The statements are read by induction_certificate_parse.cpp, and the
// per-piece lattice geometry is in induction_piece_geometry.hpp.
// Nothing here comes from a solver: only the public scene and number types,
// the certificate tokenizer and the path checker's geometry
// (path_geometry.hpp) are used.
#include "certify/induction_verifier.hpp"

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"

#include "certify/induction_certificate_parse.hpp"
#include "certify/induction_piece_geometry.hpp"
#include "certify/path_geometry.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace orthoray::certify {
namespace {

using namespace induction_check;

// ---------------------------------------------------------------- integers --

// a mod m in [0, m), m > 0.
Integer floor_mod(const Integer& a, const Integer& m) {
    Integer r;
    mpz_fdiv_r(r.get_mpz_t(), a.get_mpz_t(), m.get_mpz_t());
    return r;
}

std::string str(const Integer& n) {
    return n.get_str();
}

std::string pair_text(const Integer& x, const Integer& y) {
    std::string text = "(";
    text += x.get_str();
    text += ", ";
    text += y.get_str();
    text += ')';
    return text;
}

// The first failure ends the check; thrown inside this file only.
struct Failure {
    std::string message;
};

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw Failure{"invalid: " + where + ": " + what};
}

// ------------------------------------------------------------ the checker --

class InductionCheck {
public:
    InductionCheck(const Scene& scene, const PathPrefix& prefix, Parsed p)
        : scene_(scene), prefix_(prefix), p_(std::move(p)) {}

    // Runs `check` unless a check failed before; keeps the first failure.
    template <class Check>
    void guard(Check check) {
        if (failure_) return;
        try {
            check();
        } catch (const Failure& failure) {
            failure_ = failure.message;
        }
    }

    // Checks 1 to 3, then sets up the replay.
    void begin() {
        guard([&] {
            check_header();
            check_transversals();
            check_pieces();
            start_replay();
        });
    }

    // Check 4, one step at a time as they are read (they are not kept).
    void step(const StepSpec& s, std::size_t number) {
        guard([&] { replay(s, number); });
    }

    // After the verdict has been read into the parsed data.
    Verdict finish(std::size_t steps, const std::string& answer, Reason reason,
                   const Integer& reflections, const Integer& period) {
        p_.steps = steps;
        p_.answer = answer;
        p_.reason = reason;
        p_.reflections = reflections;
        p_.period = period;
        std::optional<Verdict> verdict;
        guard([&] {
            if (p_.reason == Reason::limit) {
                if (p_.answer != "unknown")
                    fail("verdict", "answer " + p_.answer + " does not go with reason limit");
                verdict = Verdict{false, "partial certificate: the exchange and " +
                                             std::to_string(p_.steps) +
                                             " induction steps checked, no answer proven"};
                return;
            }
            end_replay();
            verdict = Verdict{true, check_verdict()};
            resimulate();
        });
        if (failure_) return {false, *failure_};
        return *verdict;
    }

private:
    // ---------------------------------------------------------- header --

    Integer lattice(const Rational& x, const Rational& s, const std::string& what) const {
        const Rational v = x * s;
        if (v.get_den() != 1)
            fail("scale", "scale " + to_string(p_.sx) + " " + to_string(p_.sy) + " makes " + what +
                              " " + to_string(v) + ", not an integer");
        return v.get_num();
    }

    void check_header() {
        if (scene_.dim != 2)
            fail("header", "induction certificates are for 2D scenes, the scene has dim " +
                               std::to_string(scene_.dim));
        const int dim = 2;
        // The prefix p0 .. pr was checked point by point like a path, with
        // the target on none of its segments; the induction starts at p1.
        if (prefix_.failure) throw Failure{*prefix_.failure};
        if (prefix_.points < 2)
            fail("header", "the path prefix has only point 0; the induction needs point 1");
        if (prefix_.absorbed)
            fail("header", "the ray is absorbed at point " + std::to_string(prefix_.points - 1) +
                               " of the path prefix");
        const Vector& v = prefix_.v1;
        if (!same(p_.v1, v, dim))
            fail("header", "direction " + show(p_.v1, dim) + " is not the direction " +
                               show(v, dim) + " the ray leaves point 1 in");

        if (sgn(p_.sx) <= 0 || sgn(p_.sy) <= 0)
            fail("scale",
                 "scale " + to_string(p_.sx) + " " + to_string(p_.sy) + " is not positive");
        if (sgn(v[0]) == 0 || sgn(v[1]) == 0 || abs(v[0]) * p_.sx != abs(v[1]) * p_.sy)
            fail("scale", "the direction " + show(v, dim) + " is not diagonal in lattice terms: " +
                              "|v_x| * SX = " + to_string(Rational(abs(v[0]) * p_.sx)) +
                              ", |v_y| * SY = " + to_string(Rational(abs(v[1]) * p_.sy)));
        dx1_ = sgn(v[0]);
        dy1_ = sgn(v[1]);
        for (const Element& s : scene_.elements) {
            LatticeElement le;
            le.axis = s.axis;
            le.absorber = s.kind == ElementKind::absorber;
            le.source = &s;
            const int other = 1 - s.axis;
            const Rational& so = s.axis == 0 ? p_.sx : p_.sy;
            const Rational& sa = other == 0 ? p_.sx : p_.sy;
            const std::string name = "an element coordinate";
            le.c = lattice(s.offset(), so, name);
            le.lo = lattice(s.lo[other], sa, name);
            le.hi = lattice(s.hi[other], sa, name);
            elements_.push_back(std::move(le));
        }
        lattice(scene_.ray().start[0], p_.sx, "the start's x");
        lattice(scene_.ray().start[1], p_.sy, "the start's y");
        p1x_ = lattice(prefix_.p1[0], p_.sx, "point 1's x");
        p1y_ = lattice(prefix_.p1[1], p_.sy, "point 1's y");
        tx_ = lattice(scene_.target()[0], p_.sx, "the target's x");
        ty_ = lattice(scene_.target()[1], p_.sy, "the target's y");
        wx_ = dy1_ * p1y_ - dx1_ * p1x_;
    }

    // ----------------------------------------------------- transversals --

    bool in_class(const Integer& w) const {
        if (sgn(p_.modulus) == 0) return w == wx_;
        return sgn(floor_mod(w - wx_, p_.modulus)) == 0;
    }

    // The smallest state u >= from (may exceed umax).
    Integer state_at_or_after(const Transversal& t, const Integer& from) const {
        if (sgn(p_.modulus) == 0) return from <= t.residue ? t.residue : Integer(from + 1);
        return from + floor_mod(t.residue - from, p_.modulus);
    }

    Integer position(const Transversal& t, const Integer& index) const {
        if (t.increasing) return t.umin + index * p_.modulus;
        return t.umax - index * p_.modulus;
    }

    void check_transversals() {
        const Integer& g = p_.modulus;
        Integer offset = 0;
        for (std::size_t k = 0; k < p_.transversals.size(); ++k) {
            Transversal t;
            t.spec = p_.transversals[k];
            t.number = k;
            const TransversalSpec& s = t.spec;
            const std::string where = "transversal " + std::to_string(k);
            if (s.lo > s.hi) fail(where, "LO " + str(s.lo) + " > HI " + str(s.hi));
            // w = DY * Y - DX * X; on X = C it is DY * u - DX * C, on Y = C
            // it is DY * C - DX * u.
            if (s.a == 0) {
                t.residue = s.dy * (wx_ + s.dx * s.c);
                t.increasing = s.dy == 1;
            } else {
                t.residue = s.dx * (s.dy * s.c - wx_);
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
            transversals_.push_back(std::move(t));
        }
        n_ = offset;

        check_disjoint();
        for (const Transversal& t : transversals_) check_on_mirrors(t);

        // `first`: the state (p1, v1).
        if (p_.first_t >= transversals_.size())
            fail("first", "transversal " + str(p_.first_t) + " does not exist (there are " +
                              std::to_string(transversals_.size()) + ")");
        const Transversal& t = transversals_[p_.first_t.get_ui()];
        if (p_.first_i >= t.count)
            fail("first", "transversal " + str(p_.first_t) + " has " + str(t.count) +
                              " states, no state " + str(p_.first_i));
        const Integer u = position(t, p_.first_i);
        const Integer x = t.spec.a == 0 ? t.spec.c : u;
        const Integer y = t.spec.a == 0 ? u : t.spec.c;
        if (x != p1x_ || y != p1y_ || t.spec.dx != dx1_ || t.spec.dy != dy1_)
            fail("first", "state " + str(p_.first_i) + " of transversal " + str(p_.first_t) +
                              " is the lattice point " + pair_text(x, y) + " with direction " +
                              pair_text(t.spec.dx, t.spec.dy) + ", not point 1 " +
                              pair_text(p1x_, p1y_) + " with direction " + pair_text(dx1_, dy1_));
        raw_x_ = t.offset + p_.first_i;
    }

    void check_disjoint() const {
        // On one line with one direction every transversal has the same
        // class, so trimmed to their first and last states, two state sets
        // meet exactly when their ranges do.
        std::vector<const Transversal*> order;
        for (const Transversal& t : transversals_) order.push_back(&t);
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
        for (const Transversal& v : transversals_) {
            if (v.spec.a != 0) continue;
            for (const Transversal& h : transversals_) {
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
        for (const LatticeElement& e : elements_) {
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

    [[noreturn]] void uncovered(const Transversal& t, const Integer& u) const {
        const Integer x = t.spec.a == 0 ? t.spec.c : u;
        const Integer y = t.spec.a == 0 ? u : t.spec.c;
        fail("transversal " + std::to_string(t.number),
             "its state at the lattice point " + pair_text(x, y) + " is on no mirror");
    }

    // ----------------------------------------------------------- pieces --

    // The runs (one a transversal) covering the rotated coordinates
    // [rotated, rotated + length).
    std::vector<Run> runs(const Integer& rotated, const Integer& length) const {
        std::vector<Run> result;
        Integer raw = floor_mod(rotated + raw_x_, n_);
        Integer rot = rotated;
        Integer left = length;
        while (sgn(left) > 0) {
            // The transversal holding `raw`: the last one with offset <= raw.
            auto it = std::upper_bound(
                transversals_.begin(), transversals_.end(), raw,
                [](const Integer& r, const Transversal& t) { return r < t.offset; });
            const Transversal& t = *(it - 1);
            Run run;
            run.transversal = t.number;
            run.first_index = raw - t.offset;
            run.n = std::min(left, Integer(t.count - run.first_index));
            run.rotated = rot;
            run.dx = t.spec.dx;
            run.dy = t.spec.dy;
            const Integer u0 = position(t, run.first_index);
            const Integer step = t.increasing ? p_.modulus : Integer(-p_.modulus);
            const Affine along{u0, run.n > 1 ? step : Integer(0)};
            const Affine fixed{t.spec.c, 0};
            run.qx = t.spec.a == 0 ? fixed : along;
            run.qy = t.spec.a == 0 ? along : fixed;
            left -= run.n;
            rot += run.n;
            raw += run.n;
            if (raw == n_) raw = 0;
            result.push_back(std::move(run));
        }
        return result;
    }

    std::string state_text(const Run& run, const Integer& j) const {
        return "its state at rotated coordinate " + str(run.rotated + j) + " (lattice point " +
               pair_text(run.qx.at(j), run.qy.at(j)) + ", direction " + pair_text(run.dx, run.dy) +
               ")";
    }

    void check_pieces() {
        const std::size_t k = p_.pieces.size();
        const PieceSpec& first = p_.pieces[0];
        if (sgn(first.start) != 0 || first.length != 1)
            fail("piece 0", "it is [" + str(first.start) + ", " + str(first.start + first.length) +
                                "), not [0, 1) (x alone)");
        Integer end = 0;
        for (std::size_t j = 0; j < k; ++j) {
            const PieceSpec& piece = p_.pieces[j];
            const std::string where = "piece " + std::to_string(j);
            if (sgn(piece.length) == 0) fail(where, "its length is 0");
            if (piece.start != end)
                fail(where, "it starts at " + str(piece.start) +
                                ", but the pieces before it end at " + str(end) +
                                " (domains must tile [0, N) in order)");
            end += piece.length;
            if (end > n_) fail(where, "it ends at " + str(end) + ", beyond N = " + str(n_));
        }
        if (end != n_) fail("pieces", "the domains end at " + str(end) + ", not at N = " + str(n_));
        std::vector<std::size_t> by_image(k);
        for (std::size_t j = 0; j < k; ++j) by_image[j] = j;
        std::sort(by_image.begin(), by_image.end(), [&](std::size_t a, std::size_t b) {
            return p_.pieces[a].image < p_.pieces[b].image;
        });
        end = 0;
        for (std::size_t j : by_image) {
            const PieceSpec& piece = p_.pieces[j];
            if (piece.image != end)
                fail("piece " + std::to_string(j),
                     "its image starts at " + str(piece.image) + ", but " +
                         (piece.image < end
                              ? "an image before it ends at " + str(end)
                              : "no image covers [" + str(end) + ", " + str(piece.image) + ")") +
                         " (images must tile [0, N))");
            end += piece.length;
        }
        if (end != n_) fail("pieces", "the images end at " + str(end) + ", not at N = " + str(n_));

        for (std::size_t j = 0; j < k; ++j) check_piece(j);
    }

    void check_piece(std::size_t number) {
        const PieceSpec& piece = p_.pieces[number];
        const std::string where = "piece " + std::to_string(number);
        const std::vector<Run> domain = runs(piece.start, piece.length);
        Integer hits = 0;
        std::optional<std::string> hit_state, miss_state;
        for (const Run& run : domain) {
            std::vector<Meeting>& meetings = meetings_;
            meetings.resize(elements_.size());
            for (std::size_t e = 0; e < elements_.size(); ++e)
                meet(elements_[e], run, meetings[e], scratch_);
            switch (piece.kind) {
            case Kind::reflect:
                if (domain.size() != 1)
                    fail(where,
                         "a reflect piece must lie in one transversal, but its domain "
                         "spans transversals " +
                             std::to_string(domain[0].transversal) + " and " +
                             std::to_string(domain[1].transversal) +
                             (domain[1].transversal < domain[0].transversal ? " (it wraps around N)"
                                                                            : ""));
                check_reflect(where, piece, run, meetings);
                break;
            case Kind::escape:
                for (std::size_t e = 0; e < elements_.size(); ++e)
                    if (!meetings[e].states.empty())
                        fail(where, state_text(run, meetings[e].states.lo) + " meets " +
                                        describe(elements_[e]) + ", yet the piece is escape");
                break;
            case Kind::absorbed:
                check_absorbed(where, run, meetings);
                break;
            }
            // The hit flag: the target is on the line of at most one state.
            if (const std::optional<Integer> j = hit_candidate(run, meetings)) {
                hits += 1;
                hit_state = state_text(run, *j);
                if (run.n > 1) miss_state = state_text(run, *j == 0 ? Integer(1) : Integer(0));
            } else {
                miss_state = state_text(run, 0);
            }
        }
        if (piece.hit && hits != piece.length)
            fail(where,
                 "it is flagged hit, but the target is not on the segment from " + *miss_state);
        if (!piece.hit && sgn(hits) != 0)
            fail(where, "the target lies on the segment from " + *hit_state +
                            ", but the piece is not flagged hit");
    }

    // The state of the run whose segment (up to the next element met, or
    // to infinity) contains the target, if any.
    std::optional<Integer> hit_candidate(const Run& run,
                                         const std::vector<Meeting>& meetings) const {
        // target = Q(j) + tau * (dx, dy), with the line's own coordinate fixed.
        const bool vertical = transversals_[run.transversal].spec.a == 0;
        const Affine& fixed = vertical ? run.qx : run.qy;
        const Affine& along = vertical ? run.qy : run.qx;
        const Integer tau = vertical ? run.dx * (tx_ - fixed.a) : run.dy * (ty_ - fixed.a);
        if (sgn(tau) < 0) return std::nullopt;
        const Integer u = vertical ? ty_ - tau * run.dy : tx_ - tau * run.dx;
        Integer j = 0;
        if (run.n == 1) {
            if (u != along.a) return std::nullopt;
        } else {
            const Integer diff = u - along.a;
            if (sgn(floor_mod(diff, abs(along.b))) != 0) return std::nullopt;
            j = diff / along.b;
            if (sgn(j) < 0 || j >= run.n) return std::nullopt;
        }
        const std::optional<Integer> next = first_time(meetings, j);
        if (next && tau > *next) return std::nullopt;
        return j;
    }

    // The parameter of the first element met from state j, if any.
    static std::optional<Integer> first_time(const std::vector<Meeting>& meetings,
                                             const Integer& j) {
        std::optional<Integer> best;
        for (const Meeting& m : meetings) {
            if (!m.states.contains(j)) continue;
            Integer t = m.t.at(j);
            if (!best || t < *best) best = std::move(t);
        }
        return best;
    }

    void check_reflect(const std::string& where, const PieceSpec& piece, const Run& run,
                       const std::vector<Meeting>& meetings) const {
        const std::vector<Run> image = runs(piece.image, piece.length);
        if (image.size() != 1)
            fail(where, "a reflect piece's image must lie in one transversal, but it spans "
                        "transversals " +
                            std::to_string(image[0].transversal) + " and " +
                            std::to_string(image[1].transversal));
        const Run& next = image[0];
        const Integer last = run.n - 1;
        // The parameter at which the ray from state j reaches image state j,
        // computed from each axis; both must agree and be positive.
        const Affine tx = scaled(run.dx, next.qx - run.qx);
        const Affine ty = scaled(run.dy, next.qy - run.qy);
        for (const Integer& j : {Integer(0), last}) {
            if (tx.at(j) != ty.at(j) || sgn(tx.at(j)) <= 0)
                fail(where, state_text(run, j) + " is mapped to the lattice point " +
                                pair_text(next.qx.at(j), next.qy.at(j)) +
                                ", which is not ahead of it on its ray");
        }
        const Affine& t = tx;
        const int flip[2] = {next.dx != run.dx, next.dy != run.dy};
        if (!flip[0] && !flip[1])
            fail(where, "its image has the direction of its domain, but a reflection changes "
                        "it");
        std::vector<Range> met_axis[2];
        for (std::size_t e = 0; e < elements_.size(); ++e) {
            const Meeting& m = meetings[e];
            if (m.states.empty()) continue;
            const Affine diff = t - m.t; // > 0: the element comes first
            const Integer at_lo = diff.at(m.states.lo);
            const Integer at_hi = diff.at(m.states.hi);
            if (sgn(at_lo) > 0 || sgn(at_hi) > 0) {
                const Integer& j = sgn(at_lo) > 0 ? m.states.lo : m.states.hi;
                fail(where, state_text(run, j) + " meets " + describe(elements_[e]) +
                                " at the lattice point " +
                                pair_text(run.qx.at(j) + run.dx * m.t.at(j),
                                          run.qy.at(j) + run.dy * m.t.at(j)) +
                                ", before its claimed next point " +
                                pair_text(next.qx.at(j), next.qy.at(j)));
            }
            // Where diff = 0 the element is met at the claimed point: all
            // of the range, one end, or nowhere (diff is affine and <= 0).
            Range at;
            if (sgn(at_lo) == 0 && sgn(at_hi) == 0)
                at = m.states;
            else if (sgn(at_lo) == 0)
                at = {m.states.lo, m.states.lo};
            else if (sgn(at_hi) == 0)
                at = {m.states.hi, m.states.hi};
            else
                continue;
            const LatticeElement& le = elements_[e];
            if (le.absorber)
                fail(where, state_text(run, at.lo) + " is absorbed by " + describe(le) +
                                " at its claimed next point");
            if (!flip[le.axis])
                fail(where, state_text(run, at.lo) + " meets " + describe(le) +
                                " at its claimed next point, which negates the " +
                                axis_name(le.axis) + " component, but the image keeps it");
            met_axis[le.axis].push_back(at);
        }
        for (int axis = 0; axis < 2; ++axis) {
            if (!flip[axis]) continue;
            std::vector<Range>& cover = met_axis[axis];
            std::sort(cover.begin(), cover.end(),
                      [](const Range& a, const Range& b) { return a.lo < b.lo; });
            Integer next_j = 0;
            for (const Range& r : cover) {
                if (r.lo > next_j) break;
                next_j = std::max(next_j, Integer(r.hi + 1));
            }
            if (next_j <= last)
                fail(where, state_text(run, next_j) + " meets no mirror with normal axis " +
                                axis_name(axis) + " at its claimed next point " +
                                pair_text(next.qx.at(next_j), next.qy.at(next_j)) +
                                ", but the image negates the " + axis_name(axis) + " component");
        }
    }

    void check_absorbed(const std::string& where, const Run& run,
                        const std::vector<Meeting>& meetings) const {
        // Walk the run in stretches, each with one absorber that no mirror
        // precedes: found at the stretch's first state by a plain scan, and
        // kept while it is met and no mirror comes strictly before it.
        Integer cur = 0;
        while (cur < run.n) {
            const std::optional<Integer> first = first_time(meetings, cur);
            if (!first)
                fail(where, state_text(run, cur) + " meets no element, yet the piece is absorbed");
            std::optional<std::size_t> absorber;
            for (std::size_t e = 0; e < elements_.size() && !absorber; ++e)
                if (elements_[e].absorber && meetings[e].states.contains(cur) &&
                    meetings[e].t.at(cur) == *first)
                    absorber = e;
            if (!absorber)
                fail(where, state_text(run, cur) +
                                " first meets a mirror and no absorber, yet the piece is absorbed");
            const Meeting& a = meetings[*absorber];
            Integer end = a.states.hi;
            for (std::size_t e = 0; e < elements_.size(); ++e) {
                if (elements_[e].absorber) continue;
                Range r = meetings[e].states;
                r.lo = std::max(r.lo, cur);
                r.hi = std::min(r.hi, end);
                at_least(r, a.t - meetings[e].t, 1); // the mirror comes first
                if (!r.empty()) end = r.lo - 1;
            }
            cur = end + 1;
        }
    }

    // ------------------------------------------------------------ steps --

    struct EventMark {
        enum Type { none, hit, escape, absorbed } type = none;
        Integer offset;
    };

    struct Live {
        Integer d, i, l, r;
        EventMark event;
        bool alive = true;
    };

    // "first a, then b": a's event, else b's shifted by a's return time.
    static EventMark then(const Live& a, const Live& b) {
        if (a.event.type != EventMark::none) return a.event;
        EventMark e = b.event;
        if (e.type != EventMark::none) e.offset += a.r;
        return e;
    }

    void start_replay() {
        live_.clear();
        for (const PieceSpec& piece : p_.pieces) {
            Live w;
            w.d = piece.start;
            w.i = piece.image;
            w.l = piece.length;
            w.r = 1;
            w.event.offset = 0;
            if (piece.hit)
                w.event.type = EventMark::hit;
            else if (piece.kind == Kind::escape)
                w.event.type = EventMark::escape;
            else if (piece.kind == Kind::absorbed)
                w.event.type = EventMark::absorbed;
            live_.push_back(std::move(w));
        }
        L_ = n_;
    }

    void replay(const StepSpec& s, std::size_t step_number) {
        Integer& L = L_;
        auto where = [&] {
            return "step " + std::to_string(step_number) + " (" + step_text(s) + ")";
        };
        if (L == 1) fail(where(), "the induction has ended (L = 1)");
        auto piece = [&](const Integer& number) -> Live& {
            if (number >= live_.size()) fail(where(), "there is no piece " + str(number));
            Live& w = live_[number.get_ui()];
            if (!w.alive) fail(where(), "piece " + str(number) + " was removed earlier");
            return w;
        };
        auto domain_ends = [&](const Integer& number, const Live& w) {
            if (w.d + w.l != L)
                fail(where(), "piece " + str(number) + "'s domain [" + str(w.d) + ", " +
                                  str(w.d + w.l) + ") does not end at L = " + str(L));
        };
        auto image_ends = [&](const Integer& number, const Live& w) {
            if (w.i + w.l != L)
                fail(where(), "piece " + str(number) + "'s image [" + str(w.i) + ", " +
                                  str(w.i + w.l) + ") does not end at L = " + str(L));
        };
        auto lengths = [&](const Integer& a, const Live& wa, const char* rel, const Integer& b,
                           const Live& wb) {
            return "l(" + str(a) + ") = " + str(wa.l) + rel + "l(" + str(b) + ") = " + str(wb.l);
        };
        switch (s.kind) {
        case StepKind::top: {
            Live& d = piece(s.first);
            Live& r = piece(s.second);
            domain_ends(s.first, d);
            image_ends(s.second, r);
            if (d.l <= r.l)
                fail(where(), "needs l_D > l_R, but " + lengths(s.first, d, " <= ", s.second, r));
            r.event = then(r, d);
            r.r += d.r;
            r.i = d.i + d.l - r.l;
            d.l -= r.l;
            L -= r.l;
            break;
        }
        case StepKind::bottom: {
            Live& r = piece(s.first);
            Live& d = piece(s.second);
            image_ends(s.first, r);
            domain_ends(s.second, d);
            if (r.l <= d.l)
                fail(where(), "needs l_R > l_D, but " + lengths(s.first, r, " <= ", s.second, d));
            d.event = then(r, d);
            d.r += r.r;
            d.d = r.d + r.l - d.l;
            r.l -= d.l;
            L -= d.l;
            break;
        }
        case StepKind::equal: {
            if (s.first == s.second) fail(where(), "names one piece twice (that is invariant)");
            Live& r = piece(s.first);
            Live& d = piece(s.second);
            image_ends(s.first, r);
            domain_ends(s.second, d);
            if (r.l != d.l)
                fail(where(), "needs l_R = l_D, but " + lengths(s.first, r, " != ", s.second, d));
            r.event = then(r, d);
            r.r += d.r;
            r.i = d.i;
            d.alive = false;
            L -= d.l;
            break;
        }
        case StepKind::invariant: {
            Live& d = piece(s.first);
            domain_ends(s.first, d);
            image_ends(s.first, d);
            d.alive = false;
            L -= d.l;
            break;
        }
        case StepKind::top_cycle: {
            Live& d = piece(s.first);
            domain_ends(s.first, d);
            const Integer& m = s.second;
            const Integer above = d.i + d.l;
            const Integer shift = L - above;
            if (sgn(shift) == 0)
                fail(where(),
                     "piece " + str(s.first) + "'s image ends at L, so it is not a top step");
            if (sgn(m) == 0) fail(where(), "M must be at least 1");
            if (m * shift >= d.l)
                fail(where(), "needs M * S < l_D, but M * S = " + str(m) + " * " + str(shift) +
                                  " = " + str(m * shift) + " >= l_D = " + str(d.l));
            const Integer moved = m * shift;
            for (Live& w : live_) {
                if (!w.alive || &w == &d || w.i < above) continue;
                if (w.event.type == EventMark::none && d.event.type != EventMark::none) {
                    w.event.type = d.event.type;
                    w.event.offset = w.r + d.event.offset;
                }
                w.r += m * d.r;
                w.i -= moved;
            }
            d.l -= moved;
            L -= moved;
            break;
        }
        case StepKind::bottom_cycle: {
            Live& r = piece(s.first);
            image_ends(s.first, r);
            const Integer& m = s.second;
            const Integer above = r.d + r.l;
            const Integer shift = L - above;
            if (sgn(shift) == 0)
                fail(where(),
                     "piece " + str(s.first) + "'s domain ends at L, so it is not a bottom step");
            if (sgn(m) == 0) fail(where(), "M must be at least 1");
            if (m * shift >= r.l)
                fail(where(), "needs M * S < l_R, but M * S = " + str(m) + " * " + str(shift) +
                                  " = " + str(m * shift) + " >= l_R = " + str(r.l));
            const Integer moved = m * shift;
            for (Live& w : live_) {
                if (!w.alive || &w == &r || w.d < above) continue;
                if (r.event.type != EventMark::none)
                    w.event = r.event;
                else if (w.event.type != EventMark::none)
                    w.event.offset += m * r.r;
                w.r += m * r.r;
                w.d -= moved;
            }
            r.l -= moved;
            L -= moved;
            break;
        }
        }
    }

    void end_replay() {
        const Integer& L = L_;
        if (L != 1)
            fail("steps",
                 "after the last step L = " + str(L) + ", not 1 (the induction is not done)");
        const Live* x = nullptr;
        for (const Live& w : live_)
            if (w.alive) {
                if (x || sgn(w.d) != 0 || w.l != 1 || sgn(w.i) != 0)
                    fail("steps", "at L = 1 the pieces left are not x alone mapped to itself");
                x = &w;
            }
        if (!x) fail("steps", "no piece is left at L = 1");
        final_ = *x;
    }

    // ---------------------------------------------------------- verdict --

    std::string check_verdict() const {
        const Parsed& p = p_;
        const char* reason = to_string(p.reason);
        const char* word = p.reason == Reason::hit ? "yes" : "no";
        if (p.answer != word)
            fail("verdict", "answer " + p.answer + " does not go with reason " + reason);
        Reason derived = Reason::cycle;
        Integer count = final_.r;
        std::string how =
            "x returns to itself after " + str(final_.r) + " reflections with no event";
        if (final_.event.type != EventMark::none) {
            derived = final_.event.type == EventMark::hit      ? Reason::hit
                      : final_.event.type == EventMark::escape ? Reason::escape
                                                               : Reason::absorbed;
            count = final_.event.offset + 1;
            how = std::string("x's first event is ") + to_string(derived) + " at offset " +
                  str(final_.event.offset);
        }
        if (derived != p.reason)
            fail("verdict", std::string("reason ") + reason + ", but the induction gives " +
                                to_string(derived) + " (" + how + ")");
        if (p.reflections != count)
            fail("verdict", "reflections " + str(p.reflections) + ", but the induction gives " +
                                str(count) + " (" + how + ")");
        if (p.reason == Reason::cycle && p.period != count)
            fail("verdict", "period " + str(p.period) + ", but the induction gives " + str(count) +
                                " (" + how + ")");
        return "valid: " + std::string(reason) + ", " + str(count) + " reflections";
    }

    // When the path is short, walk it with the path checker's own scan
    // and compare: a second, independent check of the same verdict.
    void resimulate() const {
        const Integer budget = p_.reflections * Integer(scene_.elements.size() + 1);
        if (budget > Integer(100000000)) return;
        const int dim = 2;
        Vector p = scene_.ray().start;
        Vector v = scene_.ray().direction;
        Vector p1, v1;
        const Integer claim = p_.reflections;
        Integer k = 0; // reflections so far
        std::string outcome;
        for (;;) {
            const Event e = first_met(scene_, p, v);
            if (on_ray(scene_.target(), p, v, e, dim)) {
                outcome = "hit";
                break;
            }
            if (!e.met) {
                outcome = "escape";
                break;
            }
            p = advance(p, v, e.t, dim);
            if (e.absorbed) {
                outcome = "absorbed";
                break;
            }
            for (int j = 0; j < dim; ++j)
                if (e.flip[j]) v[j] = -v[j];
            k += 1;
            if (k == 1) {
                p1 = p;
                v1 = v;
            } else if (same(p, p1, dim) && same(v, v1, dim)) {
                outcome = "cycle";
                k -= 1;
                break;
            }
            if (k > claim + 1) break;
        }
        const std::string claimed = to_string(p_.reason);
        if (outcome.empty())
            fail("simulation", "the path checker's rule walks " + str(k) +
                                   " reflections without the claimed " + claimed);
        if (outcome != claimed || k != claim)
            fail("simulation", "the path checker's rule gives " + outcome + " after " + str(k) +
                                   " reflections, not " + claimed + " after " + str(claim));
    }

    const Scene& scene_;
    const PathPrefix& prefix_;
    Parsed p_;
    int dx1_ = 1, dy1_ = 1;
    Integer p1x_, p1y_, tx_, ty_, wx_;
    std::vector<LatticeElement> elements_;
    std::vector<Transversal> transversals_;
    Integer n_, raw_x_;
    std::vector<Live> live_;
    Integer L_; // the induced map lives on [0, L)
    Live final_;
    std::optional<std::string> failure_;
    std::vector<Meeting> meetings_; // reused for every run of every piece
    Scratch scratch_;
};

} // namespace

Verdict verify_induction(const Scene& scene, CertificateReader& in, const PathPrefix& prefix) {
    // The exchange is read whole and checked; the steps, which may be
    // millions, are replayed as they are read. After the first failure the
    // rest is still parsed (syntax errors win) but no longer checked.
    InductionCheck check(scene, prefix, parse_exchange(in, scene.dim));
    check.begin();
    std::size_t steps = 0;
    while (in.keyword() == "step") {
        const StepSpec s = parse_step(in);
        check.step(s, ++steps);
        in.advance();
    }
    Parsed verdict;
    parse_verdict(in, verdict);
    return check.finish(steps, verdict.answer, verdict.reason, verdict.reflections, verdict.period);
}

} // namespace orthoray::certify
