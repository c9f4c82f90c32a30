// The answer of a search over branch states (the illumination search and
// the intensity search, docs/optics.md and docs/intensity.md) once it has
// stopped: each target with a candidate lit (after a limit, with its best
// candidate so far, marked when another could still beat it), or else
// unlit after a complete search and unknown after a limit (never a wrong
// "no").
#pragma once

#include "orthoray/answer.hpp"

#include <cstddef>
#include <optional>

namespace orthoray::engine {

// `lit(t, target)` fills target t (from 0) and returns true when the
// search holds a candidate for it (setting `best_proven` when none can
// beat it); otherwise it leaves it alone.
// Sets the targets, `reflections` (the most among lit targets), `reason`
// and `limit`.
template <class Lit>
void conclude_targets(Answer& answer, std::size_t targets, std::optional<Limit> limit, Lit&& lit) {
    answer.targets.assign(targets, TargetAnswer{});
    bool all = true;
    for (std::size_t t = 0; t < targets; ++t) {
        TargetAnswer& target = answer.targets[t];
        if (lit(t, target)) {
            target.status = TargetAnswer::Status::lit;
            if (target.reflections > answer.reflections) answer.reflections = target.reflections;
        } else {
            target.status = limit ? TargetAnswer::Status::unknown : TargetAnswer::Status::unlit;
            all = false;
        }
    }
    answer.reason = limit ? Reason::limit : all ? Reason::lit : Reason::unlit;
    if (limit) answer.limit = *limit;
}

} // namespace orthoray::engine
