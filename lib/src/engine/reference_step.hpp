// One step of the reference tracer: the spec's motion rule read literally,
// in rationals, scanning every element (O(n) per step). Only elements that
// act on the ray (docs/optics.md: not parallel, not seen from their back)
// make events. It is the oracle the
// tests hold the fast engine to, so it is kept as plain as possible.
#pragma once

#include "engine/event_rule.hpp"
#include "orthoray/scene.hpp"

#include <vector>

namespace orthoray::engine {

struct ReferenceEvent {
    bool escape = true;    // nothing is met for t > 0
    bool absorbed = false; // an absorber is met at `point`
    Rational t;            // parameter of `point` along p + t v
    Vector point;
    Vector direction; // the first of `outgoing` (the only one without splitters)
    // Every direction leaving `point` (docs/optics.md); empty on escape or
    // absorption.
    std::vector<Outgoing> outgoing;
    // `point` is a junction (event_rule.hpp, docs/optics.md): this arrival
    // or another has two or more ways out there. A stretch ends at one.
    // The event steppers set it fully; reference_step alone, only for this
    // arrival.
    bool junction = false;
    // The elements acting at `point` (empty on escape), for the factors of
    // the outgoing directions (outgoing_factor, docs/intensity.md).
    std::vector<const Element*> acting;
};

// The first acting event from p along v. Its `junction` says only whether
// this arrival splits; mark_reference_junction adds the other arrivals for
// the callers that end stretches there (the others skip that scan).
ReferenceEvent reference_step(const Scene& scene, const Vector& p, const Vector& v);

// Sets event.junction where another arrival splits at event.point
// (is_junction over every element on the point): O(n), like the step.
void mark_reference_junction(const Scene& scene, const Vector& v, ReferenceEvent& event);

// The event at `point`, parameter t along p + t v, where `acting` (not empty)
// are the elements that act on v there: the acting rule's outcome
// (event_rule.hpp) in an event's fields. Every stepper ends with it, then
// sets `junction` where the event alone does not make the point one.
ReferenceEvent event_at(int dim, Rational t, Vector point, std::vector<const Element*> acting,
                        const Vector& v);

// Whether x lies on p + tau v for 0 <= tau <= event.t (any tau >= 0 on escape).
bool reference_passes(const Scene& scene, const Vector& x, const Vector& p, const Vector& v,
                      const ReferenceEvent& event);

} // namespace orthoray::engine
