// A stretch (docs/optics.md): the deterministic walk from a branch state up
// to the next junction (exclusive: an event point where some arrival has
// two or more ways out, event_rule.hpp), an escape, an absorption, or
// forever. Its states are never stored: Brent's method
// (engine/cycle_detector.hpp) notices a stretch that has entered a cycle
// while keeping O(1) states, so memory does not grow with its length.
#pragma once

#include "engine/cycle_detector.hpp"
#include "engine/event_stepper.hpp"

#include <cstdint>
#include <vector>

namespace orthoray::engine {

struct StretchEnd {
    enum class Kind {
        escape,   // the last segment goes to infinity
        absorbed, // an absorber stops it
        junction, // an event at a junction ends it
        cycle,    // it came back to a state it had already been in
        stopped,  // the visitor asked to stop
    };
    Kind kind = Kind::stopped;
    // Reflections along the stretch before its end (before the junction's event).
    std::uint64_t reflections = 0;
    // junction: the event point, the direction arriving there, and every
    // direction leaving it (one, where only another arrival would split).
    Vector point, incoming;
    std::vector<Outgoing> outgoing;
};

struct StretchState {
    Vector p, v;
    bool operator==(const StretchState&) const = default;
};

// Walks the stretch from (p, v). For each of its states s_0 = (p, v),
// s_1, ... (each seen once, also on a cycle) it calls
// visit(point, direction, w, event): w the reflections before that state's
// segment, `event` where the segment ends. A false return stops the walk.
template <class Visit>
StretchEnd walk_stretch(const EventStepper& stepper, Vector p, Vector v, Visit&& visit) {
    BrentDetector<StretchState> detector;
    StretchEnd end;
    StretchState s{std::move(p), std::move(v)}; // the detector copies it only when it saves it
    for (std::uint64_t i = 1;; ++i) {
        // A state seen before: everything from here on repeats.
        if (detector.observe(s, i)) {
            end.kind = StretchEnd::Kind::cycle;
            return end;
        }
        ReferenceEvent e = stepper.next(s.p, s.v);
        if (!visit(s.p, s.v, end.reflections, e)) {
            end.kind = StretchEnd::Kind::stopped;
            return end;
        }
        if (e.escape || e.absorbed) {
            end.kind = e.escape ? StretchEnd::Kind::escape : StretchEnd::Kind::absorbed;
            return end;
        }
        if (e.junction) {
            end.kind = StretchEnd::Kind::junction;
            end.point = std::move(e.point);
            end.incoming = std::move(s.v);
            end.outgoing = std::move(e.outgoing);
            return end;
        }
        if (e.outgoing.front().reflection) ++end.reflections;
        s.p = std::move(e.point);
        s.v = std::move(e.outgoing.front().direction);
    }
}

} // namespace orthoray::engine
