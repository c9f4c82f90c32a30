// The illumination question (docs/optics.md): several rays, several targets,
// splitters. Every branch of every ray is explored in exact rationals with
// the reference first-event scan.
#pragma once

#include "orthoray/solve.hpp"

namespace orthoray::engine {

// Which targets some branch passes through, with the least reflections
// before it first does and the least-numbered ray achieving that. States
// (event point, outgoing direction) are kept in a visited set, so memory
// grows with the number of distinct states explored (not bounded yet).
// options.max_steps caps the states explored; a cap or a monitor's limit
// gives Reason::limit with the targets lit so far and the rest unknown.
Answer solve_illumination(const Scene& scene, const SolveOptions& options);

} // namespace orthoray::engine
