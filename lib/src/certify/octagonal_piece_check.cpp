// Check 3 for octagonal scenes (docs/induction-certificates.md, "Octagonal
// scenes"). A run is the states j in [0, n) of one transversal inside a
// piece: Q(j) = Q0 + j * step, direction d. For an element with normal n
// not orthogonal to d the ray from Q(j) reaches the element's line at
// t = A(j) / B, A(j) = s (c - n . Q(j)) affine, B = |n . d|, s its sign; the
// state meets the element when A(j) >= 1 (t > 0) and the crossing's
// coordinate along the line, (B m . Q(j) + A(j) m . d) / B, is in [lo, hi].
// An element parallel to d never acts (docs/octagonal.md). So each element
// is met by an interval of j, and every claim below is checked on intervals,
// O(elements log elements) per piece whatever its length.
#include "certify/octagonal_piece_check.hpp"

#include "certify/cross_index.hpp"
#include "certify/induction_check_failure.hpp"
#include "certify/induction_piece_check.hpp"
#include "certify/induction_piece_geometry.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace orthoray::certify::induction_check {
namespace {

struct LineRun {
    std::size_t transversal = 0;
    Integer rotated, n; // rotated coordinate of j = 0, how many states
    Affine qx, qy;
    Integer dx, dy;
};

// Where the ray from the run's states meets an element: the states j in
// `states`, at time t(j) = a(j) / b.
struct Crossing {
    std::size_t element = 0;
    Range states;
    Affine a;
    Integer b;
};

Affine combine(const Integer& u, const Affine& f, const Integer& v, const Affine& g) {
    return {u * f.a + v * g.a, u * f.b + v * g.b};
}

std::string element_text(const OctagonalElement& e) {
    static const char* const names[] = {"x = ", "y = ", "y - x = ", "y + x = "};
    const Element& s = *e.source;
    std::string text = s.kind == ElementKind::absorber ? "the absorber on " : "the mirror on ";
    text += names[e.orientation] + e.c.get_str() + " (lattice)";
    if (s.line > 0) text += " (scene line " + std::to_string(s.line) + ")";
    return text;
}

class OctagonalPieceCheck {
public:
    OctagonalPieceCheck(const OctagonalExchange& exchange, const std::vector<PieceSpec>& pieces)
        : exchange_(exchange), pieces_(pieces) {}

    void run() {
        check_tiling(pieces_, exchange_.state_count);
        for (std::size_t j = 0; j < pieces_.size(); ++j) check_piece(j);
    }

private:
    std::vector<LineRun> runs(const Integer& rotated, const Integer& length) const {
        std::vector<LineRun> result;
        Integer raw = floor_mod(rotated + exchange_.first_raw, exchange_.state_count);
        Integer rot = rotated;
        Integer left = length;
        while (sgn(left) > 0) {
            auto it = std::upper_bound(
                exchange_.transversals.begin(), exchange_.transversals.end(), raw,
                [](const Integer& r, const LiftedSpec& t) { return r < t.offset; });
            const LiftedSpec& t = *(it - 1);
            LineRun run;
            run.transversal = static_cast<std::size_t>(it - 1 - exchange_.transversals.begin());
            const Integer index = raw - t.offset;
            run.n = std::min(left, Integer(t.count - index));
            run.rotated = rot;
            run.qx = {t.x0 + index * t.sx, run.n > 1 ? t.sx : Integer(0)};
            run.qy = {t.y0 + index * t.sy, run.n > 1 ? t.sy : Integer(0)};
            run.dx = t.dx;
            run.dy = t.dy;
            left -= run.n;
            rot += run.n;
            raw += run.n;
            if (raw == exchange_.state_count) raw = 0;
            result.push_back(std::move(run));
        }
        return result;
    }

    static std::string state_text(const LineRun& run, const Integer& j) {
        return "its state at rotated coordinate " + str(run.rotated + j) + " (lattice point " +
               pair_text(run.qx.at(j), run.qy.at(j)) + ", direction " + pair_text(run.dx, run.dy) +
               ")";
    }

    static Crossing cross_element(const OctagonalElement& e, const LineRun& run) {
        Crossing m;
        m.states = {0, run.n - 1};
        const Integer nd = e.nx * run.dx + e.ny * run.dy;
        if (sgn(nd) == 0) {
            m.states.hi = -1; // parallel: never acts
            return m;
        }
        m.b = abs(nd);
        const int s = sgn(nd);
        const Affine normal = combine(e.nx, run.qx, e.ny, run.qy);
        m.a = {s * (e.c - normal.a), -s * normal.b};
        at_least(m.states, m.a, 1); // nothing happens at t = 0
        const Affine along = combine(e.mx, run.qx, e.my, run.qy);
        const Integer md = e.mx * run.dx + e.my * run.dy;
        const Affine crossing = {m.b * along.a + md * m.a.a, m.b * along.b + md * m.a.b};
        Integer q;
        at_least(m.states, crossing.a, crossing.b, m.b * e.lo, q);
        at_most(m.states, crossing.a, crossing.b, m.b * e.hi, q);
        return m;
    }

    void check_piece(std::size_t number) {
        const PieceSpec& piece = pieces_[number];
        const std::string where = "piece " + std::to_string(number);
        const std::vector<LineRun> domain = runs(piece.start, piece.length);
        Integer hits = 0;
        std::optional<std::string> hit_state, miss_state;
        for (const LineRun& run : domain) {
            crossings_.clear();
            const Integer c0 = run.dx * run.qy.a - run.dy * run.qx.a;
            const Integer c1 = c0 + (run.n - 1) * (run.dx * run.qy.b - run.dy * run.qx.b);
            index_for(run.dx, run.dy).query(std::min(c0, c1), std::max(c0, c1), candidates_);
            for (std::size_t e : candidates_) {
                crossings_.push_back(cross_element(exchange_.elements[e], run));
                crossings_.back().element = e;
            }
            switch (piece.kind) {
            case Kind::reflect:
                if (domain.size() != 1)
                    fail(where, "a reflect piece must lie in one transversal, but its domain "
                                "spans transversals " +
                                    std::to_string(domain[0].transversal) + " and " +
                                    std::to_string(domain[1].transversal));
                check_reflect(where, piece, run);
                break;
            case Kind::escape:
                for (const Crossing& m : crossings_)
                    if (!m.states.empty())
                        fail(where, state_text(run, m.states.lo) + " meets " +
                                        element_text(exchange_.elements[m.element]) +
                                        ", yet the piece is escape");
                break;
            case Kind::absorbed:
                check_absorbed(where, run);
                break;
            case Kind::cut: // the ray steps to the join, checked as a reflect piece
                if (piece.length != 1) fail(where, "a cut piece is one state");
                check_reflect(where, {piece.start, 1, piece.join, piece.join, Kind::reflect}, run);
                break;
            }
            if (const std::optional<Integer> j = hit_candidate(run)) {
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

    // The time of the first element met from state j, if any.
    std::optional<Rational> first_time(const Integer& j) const {
        std::optional<Rational> best;
        for (const Crossing& m : crossings_) {
            if (!m.states.contains(j)) continue;
            Rational t(m.a.at(j), m.b);
            t.canonicalize();
            if (!best || t < *best) best = std::move(t);
        }
        return best;
    }

    // The state whose segment (up to the first element met, or to infinity)
    // holds the target: T = Q(j) + tau d with tau >= 0. The transversal is
    // not parallel to d, so at most one j has T on its line.
    std::optional<Integer> hit_candidate(const LineRun& run) const {
        const Integer& tx = exchange_.target_x;
        const Integer& ty = exchange_.target_y;
        // cross(d, T - Q(j)) = c0 + c1 j.
        const Integer c0 = run.dx * (ty - run.qy.a) - run.dy * (tx - run.qx.a);
        const Integer c1 = run.dy * run.qx.b - run.dx * run.qy.b;
        Integer j = 0;
        if (sgn(c1) == 0) {
            if (sgn(c0) != 0) return std::nullopt;
        } else {
            if (sgn(floor_mod(c0, abs(c1))) != 0) return std::nullopt;
            j = -c0 / c1;
            if (sgn(j) < 0 || j >= run.n) return std::nullopt;
        }
        const Integer along = run.dx * (tx - run.qx.at(j)) + run.dy * (ty - run.qy.at(j));
        if (sgn(along) < 0) return std::nullopt;
        if (const std::optional<Rational> next = first_time(j)) {
            Rational tau(along, run.dx * run.dx + run.dy * run.dy);
            tau.canonicalize();
            if (tau > *next) return std::nullopt;
        }
        return j;
    }

    // The direction a reflection in a line of this orientation gives d.
    static std::pair<Integer, Integer> reflected(int orientation, const LineRun& run) {
        switch (orientation) {
        case 0:
            return {-run.dx, run.dy};
        case 1:
            return {run.dx, -run.dy};
        case 2:
            return {run.dy, run.dx};
        default:
            return {-run.dy, -run.dx};
        }
    }

    void check_reflect(const std::string& where, const PieceSpec& piece, const LineRun& run) const {
        const std::vector<LineRun> image = runs(piece.image, piece.length);
        if (image.size() != 1)
            fail(where, "a reflect piece's image must lie in one transversal, but it spans "
                        "transversals " +
                            std::to_string(image[0].transversal) + " and " +
                            std::to_string(image[1].transversal));
        const LineRun& next = image[0];
        const Integer last = run.n - 1;
        // The claimed next point is Q(j) + (C(j) / E) d: the offset to it is
        // parallel to d (cross 0) and ahead (C > 0), checked at both ends
        // of the run, hence everywhere between (both are affine in j).
        const Affine vx = next.qx - run.qx, vy = next.qy - run.qy;
        const Affine ahead = combine(run.dx, vx, run.dy, vy);
        const Affine side = combine(run.dx, vy, -run.dy, vx);
        for (const Integer& j : {Integer(0), last})
            if (sgn(side.at(j)) != 0 || sgn(ahead.at(j)) <= 0)
                fail(where, state_text(run, j) + " is mapped to the lattice point " +
                                pair_text(next.qx.at(j), next.qy.at(j)) +
                                ", which is not ahead of it on its ray");
        const Integer e2 = run.dx * run.dx + run.dy * run.dy;
        // The elements met exactly at the claimed point, by orientation.
        std::vector<std::pair<Range, int>> at_point;
        for (const Crossing& m : crossings_) {
            if (m.states.empty()) continue;
            // diff > 0: the element comes before the claimed point.
            const Affine diff = combine(m.b, ahead, -e2, m.a);
            const Integer at_lo = diff.at(m.states.lo);
            const Integer at_hi = diff.at(m.states.hi);
            const OctagonalElement& oe = exchange_.elements[m.element];
            if (sgn(at_lo) > 0 || sgn(at_hi) > 0) {
                const Integer& j = sgn(at_lo) > 0 ? m.states.lo : m.states.hi;
                fail(where, state_text(run, j) + " meets " + element_text(oe) +
                                " before its claimed next point " +
                                pair_text(next.qx.at(j), next.qy.at(j)));
            }
            Range at;
            if (sgn(at_lo) == 0 && sgn(at_hi) == 0)
                at = m.states;
            else if (sgn(at_lo) == 0)
                at = {m.states.lo, m.states.lo};
            else if (sgn(at_hi) == 0)
                at = {m.states.hi, m.states.hi};
            else
                continue;
            if (oe.absorber)
                fail(where, state_text(run, at.lo) + " is absorbed by " + element_text(oe) +
                                " at its claimed next point");
            at_point.emplace_back(std::move(at), oe.orientation);
        }
        // Between consecutive ends of those ranges the set of orientations
        // acting at the claimed point is constant; the rule of
        // docs/octagonal.md then fixes the direction leaving it.
        std::vector<Integer> cuts{0, run.n};
        for (const auto& [r, o] : at_point) {
            cuts.push_back(r.lo);
            cuts.push_back(r.hi + 1);
        }
        std::sort(cuts.begin(), cuts.end());
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
        for (std::size_t k = 0; k + 1 < cuts.size() && cuts[k] < run.n; ++k) {
            const Integer& j = cuts[k];
            unsigned orientations = 0;
            int one = 0;
            for (const auto& [r, o] : at_point)
                if (r.contains(j)) {
                    orientations |= 1u << o;
                    one = o;
                }
            if (orientations == 0)
                fail(where, state_text(run, j) + " meets no mirror at its claimed next point " +
                                pair_text(next.qx.at(j), next.qy.at(j)));
            const bool single = (orientations & (orientations - 1)) == 0;
            const std::pair<Integer, Integer> leaving =
                single ? reflected(one, run) : std::pair<Integer, Integer>{-run.dx, -run.dy};
            if (leaving.first != next.dx || leaving.second != next.dy)
                fail(where, state_text(run, j) + " leaves its claimed next point along " +
                                pair_text(leaving.first, leaving.second) +
                                (single ? " (one orientation acts there)"
                                        : " (several orientations act there: back)") +
                                ", but its image's direction is " + pair_text(next.dx, next.dy));
        }
    }

    void check_absorbed(const std::string& where, const LineRun& run) const {
        // Stretches with one absorber that no mirror strictly precedes, as
        // for axis-parallel scenes (stretch_walk.hpp's reasoning).
        Integer cur = 0;
        while (cur < run.n) {
            const std::optional<Rational> first = first_time(cur);
            if (!first)
                fail(where, state_text(run, cur) + " meets no element, yet the piece is absorbed");
            std::optional<std::size_t> absorber;
            for (std::size_t e = 0; e < crossings_.size() && !absorber; ++e) {
                const Crossing& m = crossings_[e];
                if (!exchange_.elements[m.element].absorber || !m.states.contains(cur)) continue;
                Rational t(m.a.at(cur), m.b);
                t.canonicalize();
                if (t == *first) absorber = e;
            }
            if (!absorber)
                fail(where, state_text(run, cur) +
                                " first meets a mirror and no absorber, yet the piece is absorbed");
            const Crossing& a = crossings_[*absorber];
            Integer end = a.states.hi;
            for (const Crossing& m : crossings_) {
                if (exchange_.elements[m.element].absorber) continue;
                Range r = m.states;
                r.lo = std::max(r.lo, cur);
                r.hi = std::min(r.hi, end);
                // The mirror strictly first: a / a.b > m.a / m.b.
                at_least(r, combine(m.b, a.a, -a.b, m.a), 1);
                if (!r.empty()) end = r.lo - 1;
            }
            cur = end + 1;
        }
    }

    const OctagonalExchange& exchange_;
    const std::vector<PieceSpec>& pieces_;
    const CrossIndex& index_for(const Integer& dx, const Integer& dy) {
        auto it = indexes_.find({dx, dy});
        if (it == indexes_.end())
            it = indexes_.emplace(std::make_pair(dx, dy), CrossIndex(exchange_.elements, dx, dy))
                     .first;
        return it->second;
    }

    std::map<std::pair<Integer, Integer>, CrossIndex> indexes_; // one a direction
    std::vector<std::size_t> candidates_;
    std::vector<Crossing> crossings_; // of the current run, one a candidate element
};

} // namespace

void check_octagonal_pieces(const OctagonalExchange& exchange,
                            const std::vector<PieceSpec>& pieces) {
    OctagonalPieceCheck(exchange, pieces).run();
}

} // namespace orthoray::certify::induction_check
