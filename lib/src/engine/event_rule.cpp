#include "engine/event_rule.hpp"

namespace orthoray::engine {

bool acts_on(const Element& element, const Vector& v) {
    if (element.is_diagonal()) return element.diagonal_acts_on(v);
    return element.acts_on_sign(sgn(v[element.axis]));
}

namespace {

// v reflected by a diagonal: '/' swaps the components, '\' swaps and
// negates them (the mirror image across the lines y = x and y = -x).
Vector swapped(const Vector& v, Diagonal diagonal) {
    if (diagonal == Diagonal::rising) return {v[1], v[0], v[2]};
    return {-v[1], -v[0], v[2]};
}

// The octagonal rule (docs/octagonal.md) at a point where a diagonal acts.
// One slope alone acts like one axis: an absorber stops the ray, else a
// mirror reflects it, else the splitters transmit it and reflect it. Two
// orientations at once (both slopes, or a slope and an axis) have no
// reflection law of their own: an absorber among them stops the ray, else
// it goes back the way it came, as at the corner of an x- and a y-mirror.
EventOutcome diagonal_outcome(const std::vector<const Element*>& acting, const Vector& v) {
    EventOutcome outcome;
    bool mixed = false, mirror = false;
    const Element& first = *acting.front();
    for (const Element* e : acting) {
        mixed =
            mixed || e->diagonal != first.diagonal || (!e->is_diagonal() && e->axis != first.axis);
        outcome.absorbed = outcome.absorbed || e->kind == ElementKind::absorber;
        mirror = mirror || e->kind == ElementKind::mirror;
    }
    if (outcome.absorbed) return outcome;
    if (mixed) {
        outcome.outgoing.push_back({{-v[0], -v[1], -v[2]}, true});
        return outcome;
    }
    if (!mirror) outcome.outgoing.push_back({v, false}); // a splitter lets it through
    outcome.outgoing.push_back({swapped(v, first.diagonal), true});
    return outcome;
}

} // namespace

EventOutcome event_outcome(int dim, const std::vector<const Element*>& acting, const Vector& v) {
    for (const Element* e : acting)
        if (e->is_diagonal()) return diagonal_outcome(acting, v);
    EventOutcome outcome;
    unsigned reflecting = 0, splitting = 0;
    for (const Element* e : acting) {
        switch (e->kind) {
        case ElementKind::absorber:
            outcome.absorbed = true;
            break;
        case ElementKind::mirror:
            reflecting |= 1u << e->axis;
            break;
        case ElementKind::splitter:
            splitting |= 1u << e->axis;
            break;
        }
    }
    if (outcome.absorbed) return outcome;
    // A mirror on an axis wins over a splitter on the same axis.
    splitting &= ~reflecting;
    // Every subset of the splitting axes, the empty one first.
    for (unsigned extra = 0;; extra = (extra - splitting) & splitting) {
        const unsigned flipped = reflecting | extra;
        Outgoing out{v, flipped != 0};
        for (int j = 0; j < dim; ++j)
            if (flipped & (1u << j)) out.direction[j] = -v[j];
        outcome.outgoing.push_back(out);
        if (extra == splitting) break;
    }
    return outcome;
}

} // namespace orthoray::engine
