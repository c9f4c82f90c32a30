#include "engine/event_rule.hpp"

#include <algorithm>

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

bool is_junction(int dim, const std::vector<const Element*>& present, const Vector& v, bool swaps) {
    // Only a splitter gives an event two ways out.
    if (std::none_of(present.begin(), present.end(),
                     [](const Element* e) { return e->kind == ElementKind::splitter; }))
        return false;
    std::vector<const Element*> acting;
    for (int swap = 0; swap <= (swaps ? 1 : 0); ++swap) {
        const Vector base = swap ? Vector{v[1], v[0], v[2]} : v;
        unsigned moving = 0; // the axes along which it moves: their signs vary
        for (int j = 0; j < dim; ++j)
            if (base[j] != 0) moving |= 1u << j;
        for (unsigned negated = 0;; negated = (negated - moving) & moving) {
            Vector u = base;
            for (int j = 0; j < dim; ++j)
                if (negated & (1u << j)) u[j] = -u[j];
            acting.clear();
            for (const Element* e : present)
                if (acts_on(*e, u)) acting.push_back(e);
            if (!acting.empty() && event_outcome(dim, acting, u).outgoing.size() >= 2) return true;
            if (negated == moving) break;
        }
    }
    return false;
}

namespace {

const Rational& reflectance(const Element& e) {
    static const Rational one(1);
    return e.reflectance ? *e.reflectance : one;
}

const Rational& transmittance(const Element& e) {
    static const Rational one(1);
    return e.transmittance ? *e.transmittance : one;
}

// The factor where a diagonal acts (the cases of diagonal_outcome).
Rational diagonal_factor(const std::vector<const Element*>& acting, const Vector& v,
                         const Vector& out) {
    bool mixed = false, mirror = false;
    const Element& first = *acting.front();
    for (const Element* e : acting) {
        mixed =
            mixed || e->diagonal != first.diagonal || (!e->is_diagonal() && e->axis != first.axis);
        mirror = mirror || e->kind == ElementKind::mirror;
    }
    Rational factor(1);
    for (const Element* e : acting) {
        if (mixed || (mirror && e->kind == ElementKind::mirror))
            factor *= reflectance(*e);
        else if (!mirror)
            factor *= out == v ? transmittance(*e) : reflectance(*e);
    }
    return factor;
}

} // namespace

Rational outgoing_factor(const std::vector<const Element*>& acting, const Vector& v,
                         const Vector& out) {
    bool plain = true; // every attribute absent: the factor is 1, no arithmetic
    for (const Element* e : acting) plain = plain && !e->reflectance && !e->transmittance;
    if (plain) return Rational(1);
    for (const Element* e : acting)
        if (e->is_diagonal()) return diagonal_factor(acting, v, out);
    unsigned mirrored = 0;
    for (const Element* e : acting)
        if (e->kind == ElementKind::mirror) mirrored |= 1u << e->axis;
    Rational factor(1);
    for (const Element* e : acting) {
        if (e->kind == ElementKind::mirror)
            factor *= reflectance(*e);
        else if (e->kind == ElementKind::splitter && !(mirrored & (1u << e->axis)))
            factor *= out[e->axis] != v[e->axis] ? reflectance(*e) : transmittance(*e);
    }
    return factor;
}

} // namespace orthoray::engine
