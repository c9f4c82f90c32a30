// A 2D scene with diagonal elements (docs/octagonal.md) on its integer
// lattice.
//
// Reflections on diagonals swap the direction's components, so the ray's
// directions are the start direction u = (a, b) (a primitive integer
// vector) with components negated and possibly swapped: the orbit of u
// under the eight symmetries of the square. Unlike lattice_scene.hpp, one
// scale factor serves both axes (a diagonal must stay a diagonal), so the
// ray is no longer diagonal on the lattice; instead every event point is a
// lattice point, for this reason (docs/lattice.md, "Diagonal elements"):
//
// Scale the scene by D, the lcm of its denominators: elements lie on lines
// f(q) = k with k an integer and f one of x, y, x - y, x + y. Along
// direction w the cross value c = w_x q_y - w_y q_x is constant, and it is
// an integer at the start. A reflection across a line f = k with normal
// n_f (|n_f|^2 = 1 for an axis, 2 for a diagonal) maps it to
// -c + (2 k / |n_f|^2) cross(w, n_f), an integer again; going back along -w
// maps it to -c. So every ray line is {cross(w, q) = c} with c integral,
// and it meets an element line f = k at the solution of two integer linear
// equations whose determinant is f(w), a divisor of
//     N = lcm of the nonzero |a|, |b|, |a - b|, |a + b|.
// Scaled by N * D, every such meeting point (each event point, and every
// candidate a shooter computes) is an integer point; since gcd(a, b) = 1,
// the parameter t of P + t w between two of them is an integer too.
#pragma once

#include "lattice/lattice_scene.hpp" // Coords
#include "lattice/setup_poll.hpp"
#include "orthoray/scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace orthoray::lattice {

// An element's line, by the linear form it fixes: x, y, x - y ('/'), x + y ('\').
enum Orientation : std::uint8_t { normal_x, normal_y, rising, falling };

// A direction is an index d in 0..7: the start direction with its
// components swapped when bit 2 is set, then x negated (bit 0), y negated
// (bit 1). Indices naming the same vector (u = (1, 1), or a zero component)
// are mapped to the least of them, so states compare by index.
constexpr unsigned direction_count = 8;
// The outcome table's answer when an absorber stops the ray.
constexpr std::uint8_t absorbed = 0xff;

struct OctagonalElement {
    bool absorber = false;
    Orientation orientation = normal_x;
    Coords lo, hi;           // closed bounding box (x and y); a diagonal's runs corner to corner
    Integer offset;          // k of its line f(q) = k
    std::uint8_t acting = 0; // bit d: the element acts on a ray along direction d
};

struct OctagonalLattice {
    Integer scale;   // N * D: lattice coordinates are scene coordinates times this
    Integer modulus; // N: cross(w, P) of every state (P, w) is a multiple of it
    std::array<std::array<Integer, 2>, direction_count> w; // each direction in lattice units
    std::array<std::uint8_t, direction_count> canonical;   // least index naming the same vector
    unsigned distinct_directions = 0;                      // 8, or 4 when u is symmetric
    std::vector<OctagonalElement> elements;
    Coords start, target;
    // max |coordinate| B times max(|a|, |b|): every intermediate value of
    // the shooter and the stepper is at most 8 times this.
    Integer magnitude;
    const Scene* scene = nullptr;
    const Ray* ray = nullptr; // the ray whose lattice this is

    // Back to scene coordinates (exact).
    Vector point(const Coords& p) const;
    Vector direction(unsigned d) const;
};

// What leaves an event on a lattice: for direction d, where the mirrors
// meeting the event have the orientations in `mirrors` (bit o) and the
// absorbers those in `absorbers`, a canonical direction index, or
// `absorbed`. Each entry is asked of engine/event_rule once, when the table
// is built (about two thousand calls, some 0.3 ms). The octagonal engine
// reads it once a reflection; the branch search's lattices do not build
// it, since they ask the acting rule about the elements at each hit.
class OctagonalOutcomes {
public:
    explicit OctagonalOutcomes(const OctagonalLattice& lattice);
    std::uint8_t next(unsigned d, unsigned mirrors, unsigned absorbers) const {
        return table_[(d * 16 + mirrors) * 16 + absorbers];
    }

private:
    std::array<std::uint8_t, direction_count * 16 * 16> table_{};
};

// The lattice of ray number `ray_index` (from 0) of the scene; its `target`
// is the first target's. Throws std::invalid_argument unless the scene is
// 2D. `poll` is called once an element (SetupPoll: it may throw
// SetupStopped).
OctagonalLattice make_octagonal_lattice(const Scene& scene, const SetupPoll& poll = {},
                                        std::size_t ray_index = 0);

} // namespace orthoray::lattice
