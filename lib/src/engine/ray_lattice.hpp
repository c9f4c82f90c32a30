// One ray's integer lattice with a shooter on it, as the lattice stepper
// (lattice_stepper.hpp) keeps one for each ray whose states no other ray's
// lattice holds. Two kinds: axis-parallel scenes step on the lattice of
// lattice/lattice_scene.hpp with its uniform grid (lattice_stepper.cpp);
// 2D scenes with diagonals on the octagonal lattice of
// lattice/octagonal_lattice.hpp with its bounding volume hierarchy
// (octagonal_ray_lattice.cpp).
#pragma once

#include "engine/reference_step.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/setup_poll.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
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

// Asked, with a lattice's estimated bytes (lattice_bytes), whether it may be
// built: once its numbers, and so its integer type, are known, before its
// shooter is.
using LatticeAfford = std::function<bool(std::size_t bytes)>;

// About what a lattice and its shooter keep, from the elements its ray can
// meet, the scene's dimension and the integer type (64 bits, 128, or GMP's
// when `wide`): the growth of the resident set per lattice and element,
// measured with 50 to 100 rays on distinct lattices among 10^4 random
// elements (bench/RESULTS.md: 111 bytes in 2D, 350 in 3D, 100 with
// diagonals; 186 and 320 in 2D on 128 bits and GMP), rounded up. 3D on
// 128 bits and GMP was not measured: its figures grow from 64 bits as the
// 2D ones do.
std::size_t lattice_bytes(std::size_t elements, int dim, bool int128, bool wide);

// build(Int{}) with the narrowest integer type lattice/lattice_int.hpp
// proves safe for a lattice whose values are below `magnitude`, once
// `afford` has accepted the lattice's estimated bytes; null when it has not.
template <class Build>
std::unique_ptr<RayLattice> build_narrowest(const Integer& magnitude, std::size_t elements, int dim,
                                            const LatticeAfford& afford, Build&& build) {
    const bool int64 = magnitude < lattice::int64_limit();
    const bool int128 = !int64 && magnitude < lattice::int128_limit();
    if (!afford(lattice_bytes(elements, dim, int128, !int64 && !int128))) return nullptr;
    if (int64) return build(std::int64_t{});
    if (int128) return build(lattice::int128_t{});
    return build(Integer{});
}

// The lattice of ray number `ray` of a scene without diagonal elements,
// and of one of a 2D scene with them; each in the narrowest integer type
// that lattice/lattice_int.hpp proves safe for its coordinates. Null when
// `afford` refuses its bytes.
std::unique_ptr<RayLattice> axis_ray_lattice(const Scene& scene, std::size_t ray,
                                             const lattice::SetupPoll& poll,
                                             const LatticeAfford& afford);
std::unique_ptr<RayLattice> octagonal_ray_lattice(const Scene& scene, std::size_t ray,
                                                  const lattice::SetupPoll& poll,
                                                  const LatticeAfford& afford);

} // namespace orthoray::engine
