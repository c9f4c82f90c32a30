// The intensity question (docs/intensity.md): does some branch reach each
// target with an intensity above a threshold, intensities multiplied by the
// elements' reflectances and transmittances and floored to a natural number
// after every event. A Dijkstra-like search over the branch states of the
// illumination search (illumination.hpp), the most intense first.
#pragma once

#include "engine/event_stepper.hpp"
#include "orthoray/solve.hpp"

namespace orthoray::engine {

// Each target is lit when some branch passes it with intensity greater than
// *options.min_intensity; a lit target's answer carries the greatest such
// intensity, the ray of a branch achieving it and that branch's
// reflections. Every ray must carry an intensity (UnsupportedScene
// otherwise). options.max_steps caps the events stepped, options.monitor
// and options.max_state_bytes stop it as in the illumination search: then
// targets whose best intensity is final are lit, the others unknown.
// Certificates are not written (std::invalid_argument with an observer).
Answer solve_intensity(const Scene& scene, const SolveOptions& options);

// The same search stepping with `stepper` (the tests compare them).
Answer solve_intensity(const Scene& scene, const SolveOptions& options,
                       const EventStepper& stepper);

} // namespace orthoray::engine
