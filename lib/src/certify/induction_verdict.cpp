// The verdict of an induction certificate. At L = 1 x's piece is its whole
// orbit: its first event (offset k: the event at T^k(x), so k + 1
// reflections counting the one into x) is the answer, or with no event its
// return time is the period.
#include "certify/induction_verdict.hpp"

#include "orthoray/answer.hpp"
#include "orthoray/number.hpp"

#include "certify/induction_check_failure.hpp"
#include "certify/path_geometry.hpp"

namespace orthoray::certify::induction_check {

std::string check_verdict(const Parsed& stated, const ReplayedPiece& first) {
    const char* reason = to_string(stated.reason);
    const char* word = stated.reason == Reason::hit ? "yes" : "no";
    if (stated.answer != word)
        fail("verdict", "answer " + stated.answer + " does not go with reason " + reason);
    Reason derived = Reason::cycle;
    Integer count = first.return_time;
    std::string how =
        "x returns to itself after " + str(first.return_time) + " reflections with no event";
    if (first.event.kind != FirstEvent::none) {
        derived = first.event.kind == FirstEvent::hit      ? Reason::hit
                  : first.event.kind == FirstEvent::escape ? Reason::escape
                                                           : Reason::absorbed;
        count = first.event.offset + 1;
        how = std::string("x's first event is ") + to_string(derived) + " at offset " +
              str(first.event.offset);
    }
    if (derived != stated.reason)
        fail("verdict", std::string("reason ") + reason + ", but the induction gives " +
                            to_string(derived) + " (" + how + ")");
    if (stated.reflections != count)
        fail("verdict", "reflections " + str(stated.reflections) + ", but the induction gives " +
                            str(count) + " (" + how + ")");
    if (stated.reason == Reason::cycle && stated.period != count)
        fail("verdict", "period " + str(stated.period) + ", but the induction gives " + str(count) +
                            " (" + how + ")");
    return "valid: " + std::string(reason) + ", " + str(count) + " reflections";
}

void resimulate(const Scene& scene, const Parsed& stated) {
    // Each unit is one element tested against one segment on exact
    // rationals, some 0.4 us: 10^7 of them stay within a few seconds, where
    // 10^8 took 20-50 s and the check proper milliseconds.
    const Integer budget = stated.reflections * Integer(scene.elements.size() + 1);
    if (budget > Integer(10000000)) return;
    const int dim = 2;
    Vector p = scene.ray().start;
    Vector v = scene.ray().direction;
    Vector p1, v1;
    const Integer claim = stated.reflections;
    Integer k = 0; // reflections so far
    std::string outcome;
    for (;;) {
        const Event e = first_met(scene, p, v);
        if (on_ray(scene.target(), p, v, e, dim)) {
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
        v = outgoing(v, e, dim).front(); // one direction: no splitters here
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
    const std::string claimed = to_string(stated.reason);
    if (outcome.empty())
        fail("simulation", "the path checker's rule walks " + str(k) +
                               " reflections without the claimed " + claimed);
    if (outcome != claimed || k != claim)
        fail("simulation", "the path checker's rule gives " + outcome + " after " + str(k) +
                               " reflections, not " + claimed + " after " + str(claim));
}

} // namespace orthoray::certify::induction_check
