// How the illumination search finds the next event of a state. The search
// sees the scene only through this small interface, so the lattice stepper
// (lattice_stepper.hpp) and the rational scan below are interchangeable
// without touching the search or its certificates.
#pragma once

#include "engine/reference_step.hpp"
#include "orthoray/answer.hpp"

namespace orthoray::engine {

class EventStepper {
public:
    virtual ~EventStepper() = default;
    // The first acting event from p along v, with every outgoing direction.
    virtual ReferenceEvent next(const Vector& p, const Vector& v) const = 0;
    // Whether x lies on the segment from p to that event (to infinity on an
    // escape, up to and including the point of an absorption).
    virtual bool passes(const Vector& x, const Vector& p, const Vector& v,
                        const ReferenceEvent& event) const = 0;
    // Tells the answer what finds the events: `shooter` and the setup
    // statistics (the scan has neither).
    virtual void describe(Answer&) const {}
};

// The reference scan: exact rationals, every element looked at per event.
class ReferenceStepper final : public EventStepper {
public:
    explicit ReferenceStepper(const Scene& scene) : scene_(scene) {}
    ReferenceEvent next(const Vector& p, const Vector& v) const override {
        ReferenceEvent event = reference_step(scene_, p, v);
        mark_reference_junction(scene_, v, event);
        return event;
    }
    bool passes(const Vector& x, const Vector& p, const Vector& v,
                const ReferenceEvent& event) const override {
        return reference_passes(scene_, x, p, v, event);
    }

private:
    const Scene& scene_;
};

} // namespace orthoray::engine
