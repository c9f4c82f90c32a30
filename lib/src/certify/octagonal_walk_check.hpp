// The walk of an octagonal induction certificate where two states step to
// one (docs/induction-certificates.md, "The walk"): the searches between
// special states, each an induction on the listed exchange re-rooted at
// its start, and the answer they prove. Checker code only: it shares
// nothing with the engine's walk (lib/src/induction/rho_walk.cpp) but the
// statement syntax.
#pragma once

#include "certify/induction_certificate_parse.hpp"
#include "certify/replayed_exchange.hpp"
#include "orthoray/answer.hpp"

#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace orthoray::certify::induction_check {

// What the walk proves: an event after `reflections`, or a cycle.
struct WalkAnswer {
    Reason reason = Reason::cycle;
    Integer reflections, tail;
};

class WalkCheck {
public:
    // `listed`: the certificate's pieces (x = 0), already checked; `twin_of`
    // gives the other state at the same point leaving in the same
    // direction, if the listing has one (rotated coordinates).
    WalkCheck(std::vector<PieceSpec> listed, Integer size,
              std::function<std::optional<Integer>(const Integer&)> twin_of);

    // `walk-search FROM all` or `walk-search FROM only Z`: the exchange its
    // steps run on. Throws CheckFailure when it is not the search the walk
    // needs next.
    std::vector<PieceSpec> search(const Integer& from, const std::optional<Integer>& only);
    // The replayed search ended with x (its piece 0) alone.
    void finished(const ReplayedPiece& x);
    // The answer, once the searches have proven one.
    const WalkAnswer& answer() const;

private:
    bool is_cut(const Integer& s, Integer* join) const;
    bool flagged(const Integer& s) const; // the segment from s passes the target
    void advance();                       // over cut states, by hand
    bool visit(const Integer& s, const Integer& t);
    void end(Reason reason, const Integer& reflections);

    std::vector<PieceSpec> listed_;
    Integer size_;
    std::function<std::optional<Integer>(const Integer&)> twin_of_;
    std::vector<Integer> marks_; // x, cut states, joins and their twins
    Integer at_, time_;          // where the walk is, after how many steps of T
    std::optional<Integer> only_, hit_offset_;
    bool expecting_only_ = false;
    std::map<Integer, Integer> seen_;
    std::optional<WalkAnswer> answer_;
};

} // namespace orthoray::certify::induction_check
