// One ray's integer lattice with a shooter on it, as the lattice stepper
// (lattice_stepper.hpp) keeps one for each ray whose states no other ray's
// lattice holds. Two kinds: axis-parallel scenes step on the lattice of
// lattice/lattice_scene.hpp with its uniform grid (lattice_stepper.cpp);
// 2D scenes with diagonals on the octagonal lattice of
// lattice/octagonal_lattice.hpp with its bounding volume hierarchy
// (octagonal_ray_lattice.cpp).
#pragma once

#include "engine/reference_step.hpp"
#include "lattice/setup_poll.hpp"

#include <cstddef>
#include <memory>
#include <optional>

namespace orthoray::engine {

class RayLattice {
public:
    virtual ~RayLattice() = default;
    // The next event of (p, v), the reference scan's to the last field
    // (junction included), or nullopt when (p, v) is not a state of this
    // lattice (another ray's branch).
    virtual std::optional<ReferenceEvent> next(const Vector& p, const Vector& v) const = 0;
    // The uniform grid's cells (0 for a hierarchy), for the answer's
    // `grid_cells`.
    virtual std::size_t cells() const = 0;
};

// The lattice of ray number `ray` of a scene without diagonal elements,
// and of one of a 2D scene with them; each in the narrowest integer type
// that lattice/lattice_int.hpp proves safe for its coordinates.
std::unique_ptr<RayLattice> axis_ray_lattice(const Scene& scene, std::size_t ray,
                                             const lattice::SetupPoll& poll);
std::unique_ptr<RayLattice> octagonal_ray_lattice(const Scene& scene, std::size_t ray,
                                                  const lattice::SetupPoll& poll);

} // namespace orthoray::engine
