// The reference engine: the spec's rules stepped in rationals, O(n) a step.
#pragma once

#include "orthoray/solve.hpp"

namespace orthoray::engine {

Answer solve_by_reference(const Scene& scene, const SolveOptions& options);

} // namespace orthoray::engine
