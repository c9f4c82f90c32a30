// The acting rule of docs/optics.md in one place: which elements act on a
// ray at an event point, whether an absorber stops it, and which directions
// leave the point. Every engine that knows splitters or one-sided elements
// asks this file, so the rule cannot drift between them.
#pragma once

#include "orthoray/scene.hpp"

#include <vector>

namespace orthoray::engine {

// Whether `element` acts on a ray moving along v at a point that lies on it:
// the ray is not parallel to the element's plane (or diagonal line), and the
// element is two-sided or its sign names the side the ray arrives from.
bool acts_on(const Element& element, const Vector& v);

// One direction leaving an event point.
struct Outgoing {
    Vector direction;
    bool reflection = false; // the direction changed (a pass-through is not one)
};

struct EventOutcome {
    bool absorbed = false;
    // Empty when absorbed. Otherwise v with the components of F negated, for
    // every F with R <= F <= R + S (R: axes where a mirror acts, S: axes
    // where only splitters act); the first entry is F = R, the ray's only
    // way on when no splitter acts. Where a diagonal acts (docs/octagonal.md):
    // -v when another orientation acts too; else v swapped (and negated for
    // '\') by a mirror, or v then v swapped by splitters.
    std::vector<Outgoing> outgoing;
};

// The outcome for a ray moving along v at a point where `acting` are the
// elements that act on it (the caller has checked that the point lies on
// each and that acts_on holds). `dim` is the scene's dimension.
EventOutcome event_outcome(int dim, const std::vector<const Element*>& acting, const Vector& v);

// Whether a point is a **junction** (docs/optics.md): some arrival there
// has two or more ways out. `present` are all the elements the point lies
// on, acting or not; the arrivals tried are v with any of its components
// negated, and with `swaps` also with x and y exchanged: every direction a
// branch moving along v can have (with diagonals, `swaps` must be set).
// A point no splitter lies on is never a junction.
bool is_junction(int dim, const std::vector<const Element*>& present, const Vector& v, bool swaps);

// The fraction of a ray's intensity that leaves an event along `out`, one of
// event_outcome's directions for v at a point where `acting` act
// (docs/intensity.md): the product, over the elements that decide `out`, of
// their reflectance where they turn it and a splitter's transmittance where
// it lets it through. Axis by axis: a mirror of the axis gives its
// reflectance (a splitter of the same axis is overruled and gives nothing);
// else each splitter of the axis gives its reflectance if `out` flips that
// axis, its transmittance if not. With a diagonal: the mirrors' reflectances
// if one slope has a mirror, else each splitter's reflectance or
// transmittance; where orientations mix (the ray goes back) every acting
// element's reflectance. Absent attributes are 1.
Rational outgoing_factor(const std::vector<const Element*>& acting, const Vector& v,
                         const Vector& out);

} // namespace orthoray::engine
