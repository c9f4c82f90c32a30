// Check 4 of docs/induction-certificates.md: the induction steps replayed on
// explicit interval positions. The engine keeps only two linked orders and
// the lengths; the checker instead keeps, for every piece of the induced map
// on [0, L), where its domain and image start, so each step's condition
// ("D's domain ends at L", "l_D > l_R", ...) is checked on positions, not
// trusted. Checker code only: it shares nothing with the induction engine
// but the step syntax.
#pragma once

#include "orthoray/number.hpp"

#include "certify/induction_certificate_parse.hpp"

#include <cstddef>
#include <vector>

namespace orthoray::certify::induction_check {

// The first event on the orbit segment a piece of the induced map stands
// for: at T^offset of its points, counted in steps of the original map.
struct FirstEvent {
    enum Kind { none, hit, escape, absorbed } kind = none;
    Integer offset;
};

// A piece of the induced map: [domain_start, domain_start + length) ->
// [image_start, image_start + length), each point returning to [0, L) after
// return_time steps of the original map.
struct ReplayedPiece {
    Integer domain_start, image_start, length;
    Integer return_time = 1;
    FirstEvent event;
    bool removed = false; // dropped by an `equal` or `invariant` step
};

class ReplayedExchange {
public:
    // The exchange as the certificate lists it, on [0, size): every piece
    // returns after one step, its event (if any) at offset 0.
    ReplayedExchange(const std::vector<PieceSpec>& pieces, const Integer& size);

    // Checks the step's conditions on the current positions, then applies
    // it. Throws CheckFailure naming the step (counted from 1) otherwise.
    void apply(const StepSpec& step);

    // After the last step: L = 1 and x (piece 0) alone maps [0, 1) to
    // itself. Returns x, whose event or return time is the answer; throws
    // CheckFailure otherwise.
    const ReplayedPiece& first_alone() const;

    const Integer& induced_length() const { return induced_length_; } // L
    const std::vector<ReplayedPiece>& pieces() const { return pieces_; }
    std::size_t steps_applied() const { return steps_applied_; }

private:
    std::vector<ReplayedPiece> pieces_;
    Integer induced_length_; // the induced map lives on [0, L)
    std::size_t steps_applied_ = 0;
};

} // namespace orthoray::certify::induction_check
