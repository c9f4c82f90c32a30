// The evidence of a search over branch states for a certificate: each
// target's verdict in order, and the witness of a lit target (the
// illumination search and the intensity search): the branch that gave the
// target its candidate, replayed for a certificate. Its branch states are
// found by following each state's parent back to a ray's start; the
// stretches between them are walked again forward, each up to the junction
// that gave the next state (whose first step is that junction's point and
// direction), the last up to its first segment passing the target. The
// first pass is the one that set the candidate: later passes in the same
// stretch come after more reflections with no more intensity.
#pragma once

#include "engine/branch_state_set.hpp"
#include "engine/stretch.hpp"
#include "orthoray/answer.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace orthoray::engine {

// The parent of a ray's start state.
constexpr std::uint32_t no_parent = std::numeric_limits<std::uint32_t>::max();

// `parent_of(s)` is the state whose stretch reached state s (no_parent at a
// ray's start); `last` is the state whose stretch passes `target`. Calls
// observer.step(point, direction) for the ray's start and every event.
template <class ParentOf, class Observer>
void replay_witness(const BranchStateSet& states, const EventStepper& stepper, ParentOf&& parent_of,
                    std::uint32_t last, const Vector& target, Observer& observer) {
    std::vector<std::uint32_t> chain;
    for (std::uint32_t s = last; s != no_parent; s = parent_of(s)) chain.push_back(s);
    Vector p, v;
    for (std::size_t i = chain.size(); i-- > 0;) {
        states.state(chain[i], p, v);
        walk_stretch(stepper, p, v,
                     [&](const Vector& q, const Vector& u, std::uint64_t, const ReferenceEvent& e) {
                         observer.step(q, u);
                         return i > 0 || !stepper.passes(target, q, u, e);
                     });
    }
}

// Each target's verdict in order, as both searches' observers take them:
// `lit(t)` reports target t (from 0) lit and replays its witness; unlit and
// unknown targets go to observer.unlit and observer.unknown (from 1).
template <class Observer, class Lit>
void report_targets(const Answer& answer, Observer& observer, Lit&& lit) {
    for (std::size_t t = 0; t < answer.targets.size(); ++t) {
        switch (answer.targets[t].status) {
        case TargetAnswer::Status::lit:
            lit(t);
            break;
        case TargetAnswer::Status::unlit:
            observer.unlit(t + 1);
            break;
        case TargetAnswer::Status::unknown:
            observer.unknown(t + 1);
            break;
        }
    }
}

} // namespace orthoray::engine
