// The induction certificate checker (docs/induction-certificates.md).
//
// It reads the whole certificate first (syntax errors win over everything),
// then checks, in the order of the doc's "What verify checks":
//   1. the header: p0, the first reflection (p1, v1) by the path checker's
//      own rational scan, the scale (integral lattice, diagonal direction);
//   2. the transversals: non-empty, pairwise disjoint state sets, every
//      state on a mirror, `first` naming (p1, v1)
//      (1 and 2: induction_exchange_check.cpp);
//   3. the pieces: domains and images tile [0, N), and each piece's claim
//      holds for all its states at once (induction_piece_check.cpp);
//   4. the induction steps, replayed on explicit interval positions with
//      their conditions (replayed_exchange.cpp), and the verdict they give
//      for piece 0, x (induction_verdict.cpp);
//   5. for short answers, a re-simulation with the path checker's rule.
// The statements are read by induction_certificate_parse.cpp.
// Nothing here comes from a solver: only the public scene and number types,
// the certificate tokenizer and the path checker's geometry
// (path_geometry.hpp) are used.
#include "certify/induction_verifier.hpp"

#include "certify/induction_certificate_parse.hpp"
#include "certify/induction_check_failure.hpp"
#include "certify/induction_exchange_check.hpp"
#include "certify/induction_piece_check.hpp"
#include "certify/induction_verdict.hpp"
#include "certify/replayed_exchange.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace orthoray::certify {
namespace {

using namespace induction_check;

class InductionCheck {
public:
    InductionCheck(const Scene& scene, const PathPrefix& prefix, Parsed parsed)
        : scene_(scene), prefix_(prefix), parsed_(std::move(parsed)) {}

    // Checks 1 to 3, then sets up the replay.
    void begin() {
        checks_.guard([&] {
            const LatticeExchange exchange =
                check_header_and_transversals(scene_, prefix_, parsed_);
            check_pieces(exchange, parsed_.pieces);
            replay_.emplace(parsed_.pieces, exchange.state_count);
        });
    }

    // Check 4, one step at a time as they are read (they are not kept).
    void step(const StepSpec& s) {
        checks_.guard([&] { replay_->apply(s); });
    }

    // After the verdict has been read into `stated`.
    Verdict finish(std::size_t steps, const Parsed& stated) {
        parsed_.steps = steps;
        parsed_.answer = stated.answer;
        parsed_.reason = stated.reason;
        parsed_.reflections = stated.reflections;
        parsed_.period = stated.period;
        std::optional<Verdict> verdict;
        checks_.guard([&] {
            if (parsed_.reason == Reason::limit) {
                if (parsed_.answer != "unknown")
                    fail("verdict", "answer " + parsed_.answer + " does not go with reason limit");
                verdict = Verdict{false, "partial certificate: the exchange and " +
                                             std::to_string(parsed_.steps) +
                                             " induction steps checked, no answer proven"};
                return;
            }
            verdict = Verdict{true, check_verdict(parsed_, replay_->first_alone())};
            resimulate(scene_, parsed_);
        });
        if (checks_.failure()) return {false, *checks_.failure()};
        return *verdict;
    }

private:
    const Scene& scene_;
    const PathPrefix& prefix_;
    Parsed parsed_;
    std::optional<ReplayedExchange> replay_; // set once checks 1 to 3 pass
    FirstFailure checks_;
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
        ++steps;
        check.step(s);
        in.advance();
    }
    Parsed stated;
    parse_verdict(in, stated);
    return check.finish(steps, stated);
}

} // namespace orthoray::certify
