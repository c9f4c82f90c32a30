// The octagonal induction certificate checker
// (docs/induction-certificates.md, "Octagonal scenes"), in the order of
// its "What verify checks":
//   1. the header: p0 .. pr and (p1, v1) from the path checker's own scan,
//      the scale making every element end, the target and p1 integral;
//   2. the transversals: non-empty, not running along their direction;
//      `first` (and `twin`) naming (p1, v1), and no other listed state
//      being (p1, v1);
//   3. the pieces (octagonal_piece_check.cpp);
//   4. the steps replayed (replayed_exchange.cpp), then the twin search's
//      steps on the exchange with the twin cut out, and the verdict;
//   5. for short answers, a re-simulation with the path checker's rule.
#include "certify/octagonal_induction_verifier.hpp"

#include "certify/induction_certificate_parse.hpp"
#include "certify/induction_check_failure.hpp"
#include "certify/induction_verdict.hpp"
#include "certify/octagonal_piece_check.hpp"
#include "certify/octagonal_walk_check.hpp"
#include "certify/path_geometry.hpp"
#include "certify/replayed_exchange.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace orthoray::certify {
namespace {

using namespace induction_check;

Integer read_integer(const CertificateReader& in, std::size_t index) {
    const Rational q = in.number(index);
    if (q.get_den() != 1) in.fail(index, "an integer");
    return q.get_num();
}

struct Place {
    Integer transversal, index;
};

struct OctagonalParsed {
    Vector v1;
    Rational scale;
    std::vector<LiftedSpec> transversals;
    Place first;
    std::optional<Place> twin;
    std::vector<PieceSpec> pieces;
};

OctagonalParsed parse(CertificateReader& in) {
    OctagonalParsed p;
    in.expect("method", 1, "'octagonal-induction'");
    in.advance();
    in.expect("direction", 2, "a number");
    p.v1 = in.vector(1, 2);
    in.advance();
    in.expect("scale", 1, "a number");
    p.scale = in.number(1);
    in.advance();
    while (in.keyword() == "lifted") {
        in.expect("lifted", 7, "an integer");
        LiftedSpec t;
        t.x0 = read_integer(in, 1);
        t.y0 = read_integer(in, 2);
        t.sx = read_integer(in, 3);
        t.sy = read_integer(in, 4);
        t.count = in.count(5);
        t.dx = read_integer(in, 6);
        t.dy = read_integer(in, 7);
        p.transversals.push_back(std::move(t));
        in.advance();
    }
    if (p.transversals.empty()) in.fail(0, "'lifted'");
    in.expect("first", 2, "a non-negative integer");
    p.first = {in.count(1), in.count(2)};
    in.advance();
    if (in.keyword() == "twin") {
        in.expect("twin", 2, "a non-negative integer");
        p.twin = Place{in.count(1), in.count(2)};
        in.advance();
    }
    // The pieces have the axis-parallel syntax: reuse its reader by
    // handing it only what follows.
    p.pieces = parse_pieces(in);
    return p;
}

class OctagonalCheck {
public:
    OctagonalCheck(const Scene& scene, const PathPrefix& prefix, OctagonalParsed parsed)
        : scene_(scene), prefix_(prefix), parsed_(std::move(parsed)) {}

    void begin() {
        checks_.guard([&] {
            check_header();
            check_transversals();
            check_octagonal_pieces(exchange_, parsed_.pieces);
            replay_.emplace(parsed_.pieces, exchange_.state_count);
        });
    }

    void step(const StepSpec& s) {
        checks_.guard([&] {
            if (walk_replay_)
                walk_replay_->apply(s);
            else
                (twin_replay_ ? *twin_replay_ : *replay_).apply(s);
        });
    }

    // `walk-search FROM all|only Z` (docs/induction-certificates.md, "The
    // walk"): the certificate is a walk between special states, not one
    // induction from x.
    void walk_search(const Integer& from, const std::optional<Integer>& only) {
        checks_.guard([&] {
            if (!walk_) {
                if (replay_->steps_applied() > 0 || twin_replay_)
                    fail("walk-search", "steps of a single induction came before it");
                walk_.emplace(parsed_.pieces, exchange_.state_count,
                              [this](const Integer& r) { return twin_of(r); });
            }
            if (walk_replay_) walk_->finished(walk_replay_->first_alone());
            walk_replay_.emplace(walk_->search(from, only), exchange_.state_count);
        });
    }

    // `twin-search`: the main induction has ended; the second starts.
    void twin_search() {
        checks_.guard([&] {
            if (twin_replay_) fail("twin-search", "it appears twice");
            if (!twin_rotated_) fail("twin-search", "there is no `twin` line");
            const ReplayedPiece& x = replay_->first_alone();
            if (x.event.kind != FirstEvent::none)
                fail("twin-search", "x's orbit has an event; the search is for cycles only");
            twin_replay_.emplace(twin_alone(), exchange_.state_count);
        });
    }

    Verdict finish(std::size_t steps, const Parsed& stated) {
        std::optional<Verdict> verdict;
        checks_.guard([&] {
            if (stated.reason == Reason::limit) {
                if (stated.answer != "unknown")
                    fail("verdict", "answer " + stated.answer + " does not go with reason limit");
                verdict = Verdict{false, "partial certificate: the exchange and " +
                                             std::to_string(steps) +
                                             " induction steps checked, no answer proven"};
                return;
            }
            if (walk_) {
                verdict = Verdict{true, walk_verdict(stated)};
                return;
            }
            for (const PieceSpec& p : parsed_.pieces)
                if (p.kind == Kind::cut)
                    fail("verdict", "cut pieces, but no walk-search: one induction from x "
                                    "would take a cut state for a dead end");
            ReplayedPiece x = replay_->first_alone();
            if (x.event.kind == FirstEvent::none && twin_rotated_) {
                // The lifted orbit returned to x after p reflections; the
                // physical one returned at the first visit to x or its twin,
                // the only listed states that are (p1, v1).
                if (!twin_replay_)
                    fail("verdict", "x's orbit is a cycle and x has a twin, but no twin-search "
                                    "follows");
                const ReplayedPiece& half = twin_replay_->first_alone();
                if (half.event.kind == FirstEvent::hit) x.return_time = half.event.offset;
            }
            verdict = Verdict{true, check_verdict(stated, x)};
            resimulate(scene_, stated);
        });
        if (checks_.failure()) return {false, *checks_.failure()};
        return *verdict;
    }

private:
    // The walk's answer against the stated one.
    std::string walk_verdict(const Parsed& stated) {
        if (walk_replay_) walk_->finished(walk_replay_->first_alone());
        walk_replay_.reset();
        const WalkAnswer& a = walk_->answer();
        const char* reason = to_string(stated.reason);
        if (stated.answer != (stated.reason == Reason::hit ? "yes" : "no"))
            fail("verdict", "answer " + stated.answer + " does not go with reason " + reason);
        if (stated.reason != a.reason)
            fail("verdict",
                 std::string("reason ") + reason + ", but the walk gives " + to_string(a.reason));
        if (stated.reflections != a.reflections)
            fail("verdict", "reflections " + str(stated.reflections) + ", but the walk gives " +
                                str(a.reflections));
        if (a.reason == Reason::cycle && stated.period != a.reflections - a.tail)
            fail("verdict", "period " + str(stated.period) + ", but the walk gives " +
                                str(a.reflections - a.tail) + " after a tail of " + str(a.tail));
        // The path rule's cross-check knows cycles through point 1 only.
        if (sgn(a.tail) == 0) resimulate(scene_, stated);
        return "valid: " + std::string(reason) + ", " + str(a.reflections) + " reflections";
    }

    // The state of the listing at the same lattice point as rotated state r,
    // leaving in the same direction, if there is one (on a double cover,
    // r's other lift).
    std::optional<Integer> twin_of(const Integer& r) const {
        const Integer& n = exchange_.state_count;
        const Integer raw = floor_mod(r + exchange_.first_raw, n);
        const auto& ts = exchange_.transversals;
        const auto after =
            std::upper_bound(ts.begin(), ts.end(), raw,
                             [](const Integer& v, const LiftedSpec& t) { return v < t.offset; });
        const LiftedSpec& t = *(after - 1);
        const Integer i = raw - t.offset;
        const Integer px = t.x0 + i * t.sx, py = t.y0 + i * t.sy;
        std::optional<Integer> other;
        for (const LiftedSpec& u : ts) {
            if (u.dx * t.dy != u.dy * t.dx || sgn(Integer(u.dx * t.dx + u.dy * t.dy)) <= 0)
                continue;
            const std::optional<Integer> j = index_at(u, px, py);
            if (!j || u.offset + *j == raw) continue;
            if (other)
                fail("walk",
                     "three states are at " + pair_text(px, py) + " leaving in one direction");
            other = floor_mod(u.offset + *j - exchange_.first_raw, n);
        }
        return other;
    }

    Integer lattice(const Rational& x, const std::string& what) const {
        Rational v = x * parsed_.scale;
        v.canonicalize();
        if (v.get_den() != 1)
            fail("scale", "scale " + to_string(parsed_.scale) + " makes " + what + " " +
                              to_string(v) + ", not an integer");
        return v.get_num();
    }

    void check_header() {
        if (scene_.dim != 2)
            fail("header", "induction certificates are for 2D scenes, the scene has dim " +
                               std::to_string(scene_.dim));
        if (prefix_.failure) throw CheckFailure{*prefix_.failure};
        if (prefix_.points < 2)
            fail("header", "the path prefix has only point 0; the induction needs point 1");
        if (prefix_.absorbed)
            fail("header", "the ray is absorbed at point " + std::to_string(prefix_.points - 1) +
                               " of the path prefix");
        if (!same(parsed_.v1, prefix_.v1, 2))
            fail("header", "direction " + show(parsed_.v1, 2) + " is not the direction " +
                               show(prefix_.v1, 2) + " the ray leaves point 1 in");
        if (sgn(parsed_.scale) <= 0)
            fail("scale", "scale " + to_string(parsed_.scale) + " is not positive");
        for (const Element& s : scene_.elements) {
            const std::string what =
                "an end of the element on scene line " + std::to_string(s.line);
            OctagonalElement e;
            e.source = &s;
            e.absorber = s.kind == ElementKind::absorber;
            const Integer x0 = lattice(s.lo[0], what), y0 = lattice(s.lo[1], what);
            const Integer x1 = lattice(s.hi[0], what), y1 = lattice(s.hi[1], what);
            if (s.diagonal == Diagonal::rising) { // y - x = c, along (1, 1)
                e = {2, -1, 1, y0 - x0, 1, 1, x0 + y0, x1 + y1, e.absorber, &s};
            } else if (s.diagonal == Diagonal::falling) { // y + x = c, along (1, -1)
                // Its ends are (x0, y1) and (x1, y0).
                e = {3, 1, 1, x0 + y1, 1, -1, x0 - y1, x1 - y0, e.absorber, &s};
            } else if (s.axis == 0) {
                e = {0, 1, 0, x0, 0, 1, y0, y1, e.absorber, &s};
            } else {
                e = {1, 0, 1, y0, 1, 0, x0, x1, e.absorber, &s};
            }
            exchange_.elements.push_back(std::move(e));
        }
        exchange_.target_x = lattice(scene_.target()[0], "the target's x");
        exchange_.target_y = lattice(scene_.target()[1], "the target's y");
        p1x_ = lattice(prefix_.p1[0], "point 1's x");
        p1y_ = lattice(prefix_.p1[1], "point 1's y");
    }

    // Is (dx, dy) a positive multiple of v1?
    bool along_v1(const Integer& dx, const Integer& dy) const {
        const Rational& a = prefix_.v1[0];
        const Rational& b = prefix_.v1[1];
        return a * dy - b * dx == 0 && sgn(Rational(a * dx + b * dy)) > 0;
    }

    // The index of the state of t that is (p1, v1), if any.
    std::optional<Integer> index_of_first(const LiftedSpec& t) const {
        if (!along_v1(t.dx, t.dy)) return std::nullopt;
        return index_at(t, p1x_, p1y_);
    }

    // Which state of t is the lattice point (px, py), if one is.
    static std::optional<Integer> index_at(const LiftedSpec& t, const Integer& px,
                                           const Integer& py) {
        const Integer ex = px - t.x0, ey = py - t.y0;
        if (t.count == 1) {
            if (sgn(ex) == 0 && sgn(ey) == 0) return Integer(0);
            return std::nullopt;
        }
        // step != 0 (checked): solve ex = i sx, ey = i sy.
        if (ex * t.sy != ey * t.sx) return std::nullopt;
        const Integer& s = sgn(t.sx) != 0 ? t.sx : t.sy;
        const Integer& e = sgn(t.sx) != 0 ? ex : ey;
        if (sgn(floor_mod(e, abs(s))) != 0) return std::nullopt;
        const Integer i = e / s;
        if (sgn(i) < 0 || i >= t.count) return std::nullopt;
        return i;
    }

    Integer raw_of(const Place& p, const char* what) const {
        if (p.transversal >= Integer(static_cast<unsigned long>(exchange_.transversals.size())))
            fail(what, "there is no transversal " + str(p.transversal));
        const LiftedSpec& t = exchange_.transversals[p.transversal.get_ui()];
        if (p.index >= t.count)
            fail(what, "transversal " + str(p.transversal) + " has " + str(t.count) +
                           " states, no state " + str(p.index));
        const std::optional<Integer> i = index_of_first(t);
        if (!i || *i != p.index)
            fail(what, "state " + str(p.index) + " of transversal " + str(p.transversal) +
                           " is not point 1 " + pair_text(p1x_, p1y_) +
                           " (lattice) leaving along " + show(prefix_.v1, 2));
        return t.offset + p.index;
    }

    void check_transversals() {
        Integer offset = 0;
        for (std::size_t k = 0; k < parsed_.transversals.size(); ++k) {
            LiftedSpec t = parsed_.transversals[k];
            const std::string where = "transversal " + std::to_string(k);
            if (sgn(t.count) == 0) fail(where, "it has no state");
            if (sgn(t.dx) == 0 && sgn(t.dy) == 0) fail(where, "its direction is (0, 0)");
            if (t.count > 1 && t.dx * t.sy == t.dy * t.sx)
                fail(where, "its states run along its direction " + pair_text(t.dx, t.dy) +
                                " (or do not move), so they are no transversal");
            t.offset = offset;
            offset += t.count;
            exchange_.transversals.push_back(std::move(t));
        }
        exchange_.state_count = offset;
        exchange_.first_raw = raw_of(parsed_.first, "first");
        std::optional<Integer> twin_raw;
        if (parsed_.twin) {
            twin_raw = raw_of(*parsed_.twin, "twin");
            if (*twin_raw == exchange_.first_raw) fail("twin", "it names x itself");
            twin_rotated_ = floor_mod(*twin_raw - exchange_.first_raw, exchange_.state_count);
        }
        // No other state is (p1, v1): then the physical orbit returns to
        // (p1, v1) exactly when the lifted one returns to x or its twin.
        for (const LiftedSpec& t : exchange_.transversals)
            if (const std::optional<Integer> i = index_of_first(t)) {
                const Integer raw = t.offset + *i;
                if (raw != exchange_.first_raw && (!twin_raw || raw != *twin_raw))
                    fail("transversals", "raw state " + str(raw) + " is point 1 leaving along " +
                                             show(prefix_.v1, 2) +
                                             " too, but neither `first` nor `twin` names it");
            }
    }

    // The pieces with the twin cut out as a piece of its own, the only one
    // flagged hit: its first visit is the event the twin search finds.
    std::vector<PieceSpec> twin_alone() const {
        std::vector<PieceSpec> cut;
        const Integer& t = *twin_rotated_;
        for (PieceSpec p : parsed_.pieces) {
            p.hit = false;
            if (t < p.start || p.start + p.length <= t) {
                cut.push_back(std::move(p));
                continue;
            }
            const Integer head = t - p.start;
            const Integer tail = p.length - head - 1;
            if (sgn(head) > 0) cut.push_back({p.start, head, p.image, p.join, p.kind, false});
            cut.push_back({t, 1, p.image + head, p.join, p.kind, true});
            if (sgn(tail) > 0)
                cut.push_back({t + 1, tail, p.image + head + 1, p.join, p.kind, false});
        }
        return cut;
    }

    const Scene& scene_;
    const PathPrefix& prefix_;
    OctagonalParsed parsed_;
    OctagonalExchange exchange_;
    Integer p1x_, p1y_;
    std::optional<Integer> twin_rotated_;
    std::optional<ReplayedExchange> replay_, twin_replay_, walk_replay_;
    std::optional<WalkCheck> walk_;
    FirstFailure checks_;
};

} // namespace

Verdict verify_octagonal_induction(const Scene& scene, CertificateReader& in,
                                   const PathPrefix& prefix) {
    OctagonalCheck check(scene, prefix, parse(in));
    check.begin();
    std::size_t steps = 0;
    bool searched = false;
    for (;;) {
        if (in.keyword() == "step") {
            const StepSpec s = parse_step(in);
            ++steps;
            check.step(s);
        } else if (in.keyword() == "twin-search" && !searched) {
            in.expect("twin-search", 0, in.end_of_statement());
            searched = true;
            check.twin_search();
        } else if (in.keyword() == "walk-search") {
            if (in.size() < 3)
                in.fail(in.size(), in.size() == 1 ? "a non-negative integer" : "all or only");
            const Integer from = in.count(1);
            std::optional<Integer> only;
            if (in.token(2) == "only") {
                in.expect("walk-search", 3, "a non-negative integer");
                only = in.count(3);
            } else if (in.token(2) == "all") {
                in.expect("walk-search", 2, "all or only");
            } else {
                in.fail(2, "all or only");
            }
            check.walk_search(from, only);
        } else {
            break;
        }
        in.advance();
    }
    Parsed stated;
    parse_verdict(in, stated);
    return check.finish(steps, stated);
}

} // namespace orthoray::certify
