// The illumination question (docs/optics.md): several rays, several targets,
// splitters. Dijkstra's algorithm over branch states only; the deterministic
// stretch between them is walked again when needed, never stored.
#pragma once

#include "engine/event_stepper.hpp"
#include "orthoray/solve.hpp"

namespace orthoray::engine {

// Which targets some branch passes through, with the least reflections before
// it first does and the least-numbered ray achieving that. Memory grows with
// the number of branch states (rays' starts and states leaving a junction,
// where some arrival has two or more ways out), not with the length of the
// stretches between them. options.max_steps caps the events stepped (one
// stretch can be endless), options.max_state_bytes the bytes held for branch
// states; a cap or a monitor's limit gives Reason::limit, the lit targets whose
// count is already final, and the rest unknown. options.illumination_observer,
// when set, is given every branch state, label and witness at the end (and the
// search then explores every reachable branch state). Stretches are stepped on
// the rays' lattices (lattice_stepper.hpp) unless the scene has diagonals.
Answer solve_illumination(const Scene& scene, const SolveOptions& options);

// The same search stepping with `stepper` (the benchmark compares them).
Answer solve_illumination(const Scene& scene, const SolveOptions& options,
                          const EventStepper& stepper);

} // namespace orthoray::engine
