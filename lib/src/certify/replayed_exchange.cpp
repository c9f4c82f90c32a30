// The induction steps on explicit positions (docs/induction-certificates.md,
// "What verify checks", 4). With D the piece whose domain ends at L and R
// the one whose image ends at L:
// - top D R (l_D > l_R): R's image lands in D's cut tail, so R becomes "R,
//   then D" and its image moves to where D sends that tail; D loses l_R;
// - bottom R D (l_R > l_D): R's last l_D points land in D, cut off: D takes
//   their place as "R, then D"; R loses l_D;
// - equal R D: R becomes "R, then D" with D's image; D is removed;
// - invariant D: D maps its own tail onto itself and is removed;
// - top-cycle D M / bottom-cycle R M: M whole rounds of top (bottom) steps
//   through every piece whose image (domain) lies above D's (R's), which
//   shifts them by M * S, S the length above.
#include "certify/replayed_exchange.hpp"

#include "certify/induction_check_failure.hpp"

#include <string>
#include <utility>

namespace orthoray::certify::induction_check {
namespace {

// "first a, then b": a's event, else b's, shifted by a's return time.
FirstEvent then(const ReplayedPiece& a, const ReplayedPiece& b) {
    if (a.event.kind != FirstEvent::none) return a.event;
    FirstEvent e = b.event;
    if (e.kind != FirstEvent::none) e.offset += a.return_time;
    return e;
}

} // namespace

ReplayedExchange::ReplayedExchange(const std::vector<PieceSpec>& pieces, const Integer& size)
    : induced_length_(size) {
    for (const PieceSpec& spec : pieces) {
        ReplayedPiece piece;
        piece.domain_start = spec.start;
        piece.image_start = spec.image;
        piece.length = spec.length;
        piece.event.offset = 0;
        if (spec.hit)
            piece.event.kind = FirstEvent::hit;
        else if (spec.kind == Kind::escape)
            piece.event.kind = FirstEvent::escape;
        else if (spec.kind == Kind::absorbed || spec.kind == Kind::cut) // a dead end here
            piece.event.kind = FirstEvent::absorbed;
        pieces_.push_back(std::move(piece));
    }
}

void ReplayedExchange::apply(const StepSpec& s) {
    ++steps_applied_;
    Integer& L = induced_length_;
    // Built only on failure: a certificate may have millions of steps.
    auto where = [&] {
        return "step " + std::to_string(steps_applied_) + " (" + step_text(s) + ")";
    };
    if (L == 1) fail(where(), "the induction has ended (L = 1)");
    auto piece = [&](const Integer& number) -> ReplayedPiece& {
        if (number >= pieces_.size()) fail(where(), "there is no piece " + str(number));
        ReplayedPiece& p = pieces_[number.get_ui()];
        if (p.removed) fail(where(), "piece " + str(number) + " was removed earlier");
        return p;
    };
    auto domain_ends = [&](const Integer& number, const ReplayedPiece& p) {
        if (p.domain_start + p.length != L)
            fail(where(), "piece " + str(number) + "'s domain [" + str(p.domain_start) + ", " +
                              str(p.domain_start + p.length) + ") does not end at L = " + str(L));
    };
    auto image_ends = [&](const Integer& number, const ReplayedPiece& p) {
        if (p.image_start + p.length != L)
            fail(where(), "piece " + str(number) + "'s image [" + str(p.image_start) + ", " +
                              str(p.image_start + p.length) + ") does not end at L = " + str(L));
    };
    auto lengths = [&](const Integer& a, const ReplayedPiece& pa, const char* relation,
                       const Integer& b, const ReplayedPiece& pb) {
        return "l(" + str(a) + ") = " + str(pa.length) + relation + "l(" + str(b) +
               ") = " + str(pb.length);
    };
    switch (s.kind) {
    case StepKind::top: {
        ReplayedPiece& d = piece(s.first);
        ReplayedPiece& r = piece(s.second);
        domain_ends(s.first, d);
        image_ends(s.second, r);
        if (d.length <= r.length)
            fail(where(), "needs l_D > l_R, but " + lengths(s.first, d, " <= ", s.second, r));
        r.event = then(r, d);
        r.return_time += d.return_time;
        r.image_start = d.image_start + d.length - r.length;
        d.length -= r.length;
        L -= r.length;
        break;
    }
    case StepKind::bottom: {
        ReplayedPiece& r = piece(s.first);
        ReplayedPiece& d = piece(s.second);
        image_ends(s.first, r);
        domain_ends(s.second, d);
        if (r.length <= d.length)
            fail(where(), "needs l_R > l_D, but " + lengths(s.first, r, " <= ", s.second, d));
        d.event = then(r, d);
        d.return_time += r.return_time;
        d.domain_start = r.domain_start + r.length - d.length;
        r.length -= d.length;
        L -= d.length;
        break;
    }
    case StepKind::equal: {
        if (s.first == s.second) fail(where(), "names one piece twice (that is invariant)");
        ReplayedPiece& r = piece(s.first);
        ReplayedPiece& d = piece(s.second);
        image_ends(s.first, r);
        domain_ends(s.second, d);
        if (r.length != d.length)
            fail(where(), "needs l_R = l_D, but " + lengths(s.first, r, " != ", s.second, d));
        r.event = then(r, d);
        r.return_time += d.return_time;
        r.image_start = d.image_start;
        d.removed = true;
        L -= d.length;
        break;
    }
    case StepKind::invariant: {
        ReplayedPiece& d = piece(s.first);
        domain_ends(s.first, d);
        image_ends(s.first, d);
        d.removed = true;
        L -= d.length;
        break;
    }
    case StepKind::top_cycle: {
        ReplayedPiece& d = piece(s.first);
        domain_ends(s.first, d);
        const Integer& rounds = s.second;
        const Integer above = d.image_start + d.length;
        const Integer shift = L - above;
        if (sgn(shift) == 0)
            fail(where(), "piece " + str(s.first) + "'s image ends at L, so it is not a top step");
        if (sgn(rounds) == 0) fail(where(), "M must be at least 1");
        const Integer moved = rounds * shift;
        if (moved >= d.length)
            fail(where(), "needs M * S < l_D, but M * S = " + str(rounds) + " * " + str(shift) +
                              " = " + str(moved) + " >= l_D = " + str(d.length));
        for (ReplayedPiece& p : pieces_) {
            if (p.removed || &p == &d || p.image_start < above) continue;
            if (p.event.kind == FirstEvent::none && d.event.kind != FirstEvent::none) {
                p.event.kind = d.event.kind;
                p.event.offset = p.return_time + d.event.offset;
            }
            p.return_time += rounds * d.return_time;
            p.image_start -= moved;
        }
        d.length -= moved;
        L -= moved;
        break;
    }
    case StepKind::bottom_cycle: {
        ReplayedPiece& r = piece(s.first);
        image_ends(s.first, r);
        const Integer& rounds = s.second;
        const Integer above = r.domain_start + r.length;
        const Integer shift = L - above;
        if (sgn(shift) == 0)
            fail(where(),
                 "piece " + str(s.first) + "'s domain ends at L, so it is not a bottom step");
        if (sgn(rounds) == 0) fail(where(), "M must be at least 1");
        const Integer moved = rounds * shift;
        if (moved >= r.length)
            fail(where(), "needs M * S < l_R, but M * S = " + str(rounds) + " * " + str(shift) +
                              " = " + str(moved) + " >= l_R = " + str(r.length));
        for (ReplayedPiece& p : pieces_) {
            if (p.removed || &p == &r || p.domain_start < above) continue;
            if (r.event.kind != FirstEvent::none)
                p.event = r.event;
            else if (p.event.kind != FirstEvent::none)
                p.event.offset += rounds * r.return_time;
            p.return_time += rounds * r.return_time;
            p.domain_start -= moved;
        }
        r.length -= moved;
        L -= moved;
        break;
    }
    }
}

const ReplayedPiece& ReplayedExchange::first_alone() const {
    if (induced_length_ != 1)
        fail("steps", "after the last step L = " + str(induced_length_) +
                          ", not 1 (the induction is not done)");
    const ReplayedPiece* x = nullptr;
    for (const ReplayedPiece& p : pieces_)
        if (!p.removed) {
            if (x || sgn(p.domain_start) != 0 || p.length != 1 || sgn(p.image_start) != 0)
                fail("steps", "at L = 1 the pieces left are not x alone mapped to itself");
            x = &p;
        }
    if (!x) fail("steps", "no piece is left at L = 1");
    return *x;
}

} // namespace orthoray::certify::induction_check
