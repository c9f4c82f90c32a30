// The default engine: simulation on lattice states with the uniform grid.
#pragma once

#include "orthoray/solve.hpp"

namespace orthoray::engine {

Answer solve_on_lattice(const Scene& scene, const SolveOptions& options);

} // namespace orthoray::engine
