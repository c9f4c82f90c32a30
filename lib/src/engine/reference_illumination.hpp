// The reference illumination search: the plainest reading of the
// illumination question of docs/optics.md, kept as the test oracle beside
// the branch-state search (illumination.hpp) and the state graph. Every
// state (event point, outgoing direction) is stored as exact rationals in a
// std::map, and Dijkstra's order on (reflections, ray) settles them, so
// memory grows with the states explored: small scenes only. It shares with
// the branch-state search only the reference step (reference_step.hpp),
// not the branch states, stretches, labels' early stop or the compact set.
#pragma once

#include "orthoray/solve.hpp"

namespace orthoray::engine {

// Which targets some branch passes through, with the least reflections
// before it first does and the least-numbered ray achieving that; `states`
// counts every distinct state stored. options.max_steps caps the states
// expanded; a cap or a monitor's limit gives Reason::limit with the targets
// lit so far and the rest unknown. It writes no certificate.
Answer solve_illumination_by_reference(const Scene& scene, const SolveOptions& options);

} // namespace orthoray::engine
