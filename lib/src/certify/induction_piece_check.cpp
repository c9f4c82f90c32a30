// The piece checks (docs/induction-certificates.md, "What verify checks",
// 3). The states of a piece inside one transversal are lattice points
// Q(j) = Q0 + j * step on one line, j in [0, n), all with one direction, so
// the parameter at which the ray from Q(j) meets an element is affine in j,
// and so is the point where it meets the element's line: the states meeting
// an element form an interval of j, found by exact floor and ceiling
// divisions, and comparisons of two affine functions over an interval only
// need its two ends. That makes the check O(elements) per piece, whatever
// the piece's length.
#include "certify/induction_piece_check.hpp"

#include "certify/induction_check_failure.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace orthoray::certify::induction_check {
namespace {

class PieceCheck {
public:
    PieceCheck(const LatticeExchange& exchange, const std::vector<PieceSpec>& pieces)
        : exchange_(exchange), pieces_(pieces) {}

    void check_pieces() {
        check_tiling(pieces_, exchange_.state_count);
        for (std::size_t j = 0; j < pieces_.size(); ++j) check_piece(j);
    }

private:
    // The runs (one a transversal) covering the rotated coordinates
    // [rotated, rotated + length).
    std::vector<Run> runs(const Integer& rotated, const Integer& length) const {
        std::vector<Run> result;
        Integer raw = floor_mod(rotated + exchange_.first_raw, exchange_.state_count);
        Integer rot = rotated;
        Integer left = length;
        while (sgn(left) > 0) {
            // The transversal holding `raw`: the last one with offset <= raw.
            auto it = std::upper_bound(
                exchange_.transversals.begin(), exchange_.transversals.end(), raw,
                [](const Integer& r, const Transversal& t) { return r < t.offset; });
            const Transversal& t = *(it - 1);
            Run run;
            run.transversal = t.number;
            run.first_index = raw - t.offset;
            run.n = std::min(left, Integer(t.count - run.first_index));
            run.rotated = rot;
            run.dx = t.spec.dx;
            run.dy = t.spec.dy;
            const Integer u0 = state_position(t, run.first_index, exchange_.modulus);
            const Integer step = t.increasing ? exchange_.modulus : Integer(-exchange_.modulus);
            const Affine along{u0, run.n > 1 ? step : Integer(0)};
            const Affine fixed{t.spec.c, 0};
            run.qx = t.spec.a == 0 ? fixed : along;
            run.qy = t.spec.a == 0 ? along : fixed;
            left -= run.n;
            rot += run.n;
            raw += run.n;
            if (raw == exchange_.state_count) raw = 0;
            result.push_back(std::move(run));
        }
        return result;
    }

    std::string state_text(const Run& run, const Integer& j) const {
        return "its state at rotated coordinate " + str(run.rotated + j) + " (lattice point " +
               pair_text(run.qx.at(j), run.qy.at(j)) + ", direction " + pair_text(run.dx, run.dy) +
               ")";
    }

    void check_piece(std::size_t number) {
        const PieceSpec& piece = pieces_[number];
        const std::string where = "piece " + std::to_string(number);
        const std::vector<Run> domain = runs(piece.start, piece.length);
        Integer hits = 0;
        std::optional<std::string> hit_state, miss_state;
        for (const Run& run : domain) {
            std::vector<Meeting>& meetings = meetings_;
            meetings.resize(exchange_.elements.size());
            for (std::size_t e = 0; e < exchange_.elements.size(); ++e)
                meet(exchange_.elements[e], run, meetings[e], scratch_);
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
                for (std::size_t e = 0; e < exchange_.elements.size(); ++e)
                    if (!meetings[e].states.empty())
                        fail(where, state_text(run, meetings[e].states.lo) + " meets " +
                                        describe(exchange_.elements[e]) +
                                        ", yet the piece is escape");
                break;
            case Kind::absorbed:
                check_absorbed(where, run, meetings);
                break;
            case Kind::cut:
                fail(where, "a cut piece belongs to octagonal walk certificates only");
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
        const bool vertical = exchange_.transversals[run.transversal].spec.a == 0;
        const Affine& fixed = vertical ? run.qx : run.qy;
        const Affine& along = vertical ? run.qy : run.qx;
        const Integer tau = vertical ? run.dx * (exchange_.target_x - fixed.a)
                                     : run.dy * (exchange_.target_y - fixed.a);
        if (sgn(tau) < 0) return std::nullopt;
        const Integer u =
            vertical ? exchange_.target_y - tau * run.dy : exchange_.target_x - tau * run.dx;
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
        for (std::size_t e = 0; e < exchange_.elements.size(); ++e) {
            const Meeting& m = meetings[e];
            if (m.states.empty()) continue;
            const Affine diff = t - m.t; // > 0: the element comes first
            const Integer at_lo = diff.at(m.states.lo);
            const Integer at_hi = diff.at(m.states.hi);
            if (sgn(at_lo) > 0 || sgn(at_hi) > 0) {
                const Integer& j = sgn(at_lo) > 0 ? m.states.lo : m.states.hi;
                fail(where, state_text(run, j) + " meets " + describe(exchange_.elements[e]) +
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
            const LatticeElement& le = exchange_.elements[e];
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
            for (std::size_t e = 0; e < exchange_.elements.size() && !absorber; ++e)
                if (exchange_.elements[e].absorber && meetings[e].states.contains(cur) &&
                    meetings[e].t.at(cur) == *first)
                    absorber = e;
            if (!absorber)
                fail(where, state_text(run, cur) +
                                " first meets a mirror and no absorber, yet the piece is absorbed");
            const Meeting& a = meetings[*absorber];
            Integer end = a.states.hi;
            for (std::size_t e = 0; e < exchange_.elements.size(); ++e) {
                if (exchange_.elements[e].absorber) continue;
                Range r = meetings[e].states;
                r.lo = std::max(r.lo, cur);
                r.hi = std::min(r.hi, end);
                at_least(r, a.t - meetings[e].t, 1); // the mirror comes first
                if (!r.empty()) end = r.lo - 1;
            }
            cur = end + 1;
        }
    }

    const LatticeExchange& exchange_;
    const std::vector<PieceSpec>& pieces_;
    std::vector<Meeting> meetings_; // reused for every run of every piece
    Scratch scratch_;
};

} // namespace

void check_tiling(const std::vector<PieceSpec>& pieces, const Integer& n) {
    const std::size_t k = pieces.size();
    const PieceSpec& first = pieces[0];
    if (sgn(first.start) != 0 || first.length != 1)
        fail("piece 0", "it is [" + str(first.start) + ", " + str(first.start + first.length) +
                            "), not [0, 1) (x alone)");
    Integer end = 0;
    for (std::size_t j = 0; j < k; ++j) {
        const PieceSpec& piece = pieces[j];
        const std::string where = "piece " + std::to_string(j);
        if (sgn(piece.length) == 0) fail(where, "its length is 0");
        if (piece.start != end)
            fail(where, "it starts at " + str(piece.start) + ", but the pieces before it end at " +
                            str(end) + " (domains must tile [0, N) in order)");
        end += piece.length;
        if (end > n) fail(where, "it ends at " + str(end) + ", beyond N = " + str(n));
    }
    if (end != n) fail("pieces", "the domains end at " + str(end) + ", not at N = " + str(n));
    std::vector<std::size_t> by_image(k);
    for (std::size_t j = 0; j < k; ++j) by_image[j] = j;
    std::sort(by_image.begin(), by_image.end(),
              [&](std::size_t a, std::size_t b) { return pieces[a].image < pieces[b].image; });
    end = 0;
    for (std::size_t j : by_image) {
        const PieceSpec& piece = pieces[j];
        if (piece.image != end)
            fail("piece " + std::to_string(j),
                 "its image starts at " + str(piece.image) + ", but " +
                     (piece.image < end
                          ? "an image before it ends at " + str(end)
                          : "no image covers [" + str(end) + ", " + str(piece.image) + ")") +
                     " (images must tile [0, N))");
        end += piece.length;
    }
    if (end != n) fail("pieces", "the images end at " + str(end) + ", not at N = " + str(n));
}

void check_pieces(const LatticeExchange& exchange, const std::vector<PieceSpec>& pieces) {
    PieceCheck(exchange, pieces).check_pieces();
}

} // namespace orthoray::certify::induction_check
