// Bounds on the number of states a trajectory can visit (docs/bounds.md):
// the lattice bound behind the PSPACE membership proof, and a refined bound
// from the invariant of the trajectory's unfolded line.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <cstddef>
#include <optional>

namespace orthoray {

// With several rays (the illumination question) every ray has its own
// lattice: the fields describe the first ray's, except points,
// lattice_states and refined_states, which are sums over the rays.
struct StateBounds {
    int dim = 0;                    // M: the active axes (nonzero direction components)
    bool octagonal = false;         // diagonal elements: one scale, up to 8 directions
    unsigned directions = 0;        // distinct directions of a trajectory: 2^M, or 4 or 8
    std::size_t rays = 1;           // rays summed over
    std::array<int, 3> active{};    // scene axis of active axis i
    std::array<Integer, 3> scale;   // lattice coordinate = scene coordinate * scale[i]
    std::size_t elements = 0;       // elements the ray can meet
    std::size_t input_bits = 0;     // bits of every numerator and denominator in the scene
    std::size_t magnitude_bits = 0; // bits of the largest |lattice coordinate|
    std::size_t state_bits = 0;     // bits of one lattice state: coordinates and direction
    Integer points;                 // integer points on the elements, each counted once
    Integer lattice_states;         // points * directions: no trajectory visits more states
    // 2D: G of the line invariant (octagonal: N); 3D: G_xy, G_xz, G_yz.
    std::array<Integer, 3> line_modulus;
    Integer refined_states;            // states that also keep the line invariant of the start
    std::optional<std::size_t> pieces; // 2D: pieces of the piece tables (docs/piece-tables.md)
};

// The bounds of a scene. `with_pieces` builds the 2D piece tables to count
// their pieces (time and memory about linear in the pieces).
StateBounds compute_bounds(const Scene& scene, bool with_pieces = true);

// The distinct lattice states a solved trajectory visited, the states the
// bounds count (a reflection point with the direction leaving it, or the
// point where an absorber stops the ray): the period for a cycle (the step
// map is injective, so the orbit is purely periodic and its states are the
// period's), the reflections plus the absorption state when absorbed, the
// reflections otherwise. std::nullopt for an undecided answer.
std::optional<Integer> states_visited(const Answer& answer);

} // namespace orthoray
