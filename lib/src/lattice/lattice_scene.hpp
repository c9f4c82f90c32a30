// The scene on its integer lattice.
//
// Let u be the ray's direction scaled to a primitive integer vector, L the
// lcm of its nonzero components and D the lcm of every denominator in the
// scene. Scaling each axis j with u_j != 0 by D * L / |u_j| (a different
// factor per axis) makes every mirror, the start and the target integral and
// turns the direction into (±L, ..., ±L), i.e. a diagonal (±1, ..., ±1).
// Reflections only flip signs, so the ray stays diagonal forever, and a
// diagonal ray from an integer point meets integer hyperplanes at integer
// points: every reflection point is a lattice point (Reif, Tygar and Yoshida
// 1994). Axes with u_j = 0 never change: they are dropped ("inactive"),
// together with every element the ray can never meet (normal on an inactive
// axis, or not spanning the ray's fixed coordinate). What remains is an
// M-dimensional problem, M = number of nonzero direction components.
#pragma once

#include "lattice/setup_poll.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace orthoray::lattice {

using Coords = std::array<Integer, 3>;

struct LatticeElement {
    bool absorber = false;
    int axis = 0;  // normal axis, in active coordinates
    Coords lo, hi; // closed box; lo[axis] == hi[axis]
    // Bit d set: the element acts on a ray moving in direction mask d
    // (engine/event_rule's acts_on, asked once per mask by make_lattice).
    // Every bit for a two-sided element (the default); half of them for a
    // one-sided one.
    unsigned acting = ~0u;
    std::uint32_t source = 0; // its index in Scene::elements
    bool acts_on(unsigned negative) const { return (acting >> negative) & 1u; }
};

struct LatticeScene {
    int dim = 0;                 // M: active axes, 1..3
    std::array<int, 3> active{}; // scene axis of active axis i
    Coords scale;                // X_i = x_active[i] * scale[i]
    std::vector<LatticeElement> elements;
    Coords start;
    unsigned start_direction = 0;  // bit i set: moving towards -infinity on active axis i
    bool target_reachable = false; // false when the target is off the ray's fixed coordinates
    Coords target;
    Integer magnitude; // max |value| over elements, start and target
    // Some element acts on only some directions (a one-sided element the ray
    // can meet): the step map may be non-injective (docs/optics.md).
    bool one_sided = false;
    const Scene* scene = nullptr;
    const Ray* ray = nullptr; // the ray whose lattice this is
    // The ray's 2^dim directions in scene coordinates, by mask: built once,
    // since every element is asked about each, and a path reports one a
    // reflection.
    std::vector<Vector> directions;

    // Back to scene coordinates (exact): a lattice point, a direction mask.
    Vector point(const Coords& p) const;
    // The same into x, reusing its storage (a path reports a point a
    // reflection; fresh rationals would cost an allocation each).
    void point_into(const Coords& p, Vector& x) const;
    const Vector& direction(unsigned mask) const { return directions[mask]; }
    // Whether a scene point lies on the lattice (inactive coordinates equal
    // the start's, active ones integral after scaling); if so, its coordinates.
    bool to_lattice(const Vector& x, Coords& out) const;
};

// The lattice of ray number `ray_index` (from 0) of the scene; its
// `target` and `target_reachable` are the first target's. `poll` is called
// once an element (SetupPoll: it may throw SetupStopped).
LatticeScene make_lattice(const Scene& scene, const SetupPoll& poll = {},
                          std::size_t ray_index = 0);

} // namespace orthoray::lattice
