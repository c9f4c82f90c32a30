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
#include <optional>
#include <utility>
#include <vector>

namespace orthoray::engine {

struct StretchState {
    Vector p, v;
    bool operator==(const StretchState&) const = default;
    // The state after event e, which continues the stretch: its one way out.
    void follow(ReferenceEvent&& e) {
        p = std::move(e.point);
        v = std::move(e.outgoing.front().direction);
    }
};

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
    // The states visited, s_0 included (on a cycle, every one up to the
    // repeat that Brent's method noticed, so some twice).
    std::uint64_t visited = 0;
    // escape, absorbed, junction: the stretch's last state, whose segment
    // ends it (at a junction, `last.v` is the direction arriving there).
    StretchState last;
    // cycle: the least period.
    std::uint64_t period = 0;
    // junction: the event point, and every direction leaving it (one, where
    // only another arrival would split).
    Vector point;
    std::vector<Outgoing> outgoing;
};

// Walks the stretch from (p, v). For each of its states s_0 = (p, v), s_1,
// ... (on a cycle some twice, before Brent's method sees the repeat) it
// calls visit(point, direction, w, event): w the reflections before that
// state's segment, `event` where the segment ends. A false return stops the
// walk.
template <class Visit>
StretchEnd walk_stretch(const EventStepper& stepper, Vector p, Vector v, Visit&& visit) {
    BrentDetector<StretchState> detector;
    StretchEnd end;
    StretchState s{std::move(p), std::move(v)}; // the detector copies it only when it saves it
    for (std::uint64_t i = 1;; ++i) {
        // A state seen before: everything from here on repeats.
        if (const std::optional<std::uint64_t> period = detector.observe(s, i)) {
            end.kind = StretchEnd::Kind::cycle;
            end.period = *period;
            return end;
        }
        ReferenceEvent e = stepper.next(s.p, s.v);
        ++end.visited;
        if (!visit(s.p, s.v, end.reflections, e)) {
            end.kind = StretchEnd::Kind::stopped;
            return end;
        }
        if (e.escape || e.absorbed || e.junction) {
            end.kind = e.escape     ? StretchEnd::Kind::escape
                       : e.absorbed ? StretchEnd::Kind::absorbed
                                    : StretchEnd::Kind::junction;
            if (e.junction) {
                end.point = std::move(e.point);
                end.outgoing = std::move(e.outgoing);
            }
            end.last = std::move(s);
            return end;
        }
        if (e.outgoing.front().reflection) ++end.reflections;
        s.follow(std::move(e));
    }
}

} // namespace orthoray::engine
