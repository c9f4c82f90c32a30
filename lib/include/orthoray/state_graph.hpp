// The explicit state graph of a small instance: every lattice state (a lattice
// point on a mirror and a direction) is a vertex, the step map gives each one
// out-edge, and the answer is read off with graph algorithms (Boost.Graph):
// breadth-first distances from the start find the first target pass, escape
// or absorption; strongly connected components give the period. It is an
// independent cross-check of the simulation engines on instances whose whole
// state space fits in memory, and a check of the theorem that the step map is
// injective.
#pragma once

#include "orthoray/answer.hpp"
#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <cstdint>
#include <optional>

namespace orthoray {

struct StateGraphReport {
    // Vertices that are lattice states; with diagonals (docs/octagonal.md)
    // only the states reachable from the start are built.
    std::uint64_t states = 0;
    std::uint64_t reachable = 0; // of them, reachable from the start
    bool injective = true;       // no state is the image of two states
    Answer answer;
};

// std::nullopt when the scene has more than max_states lattice states. A
// monitor is polled every 1024 states; when it reports a limit the report's
// answer is that limit (Reason::limit, 0 reflections).
std::optional<StateGraphReport> explore_state_graph(const Scene& scene, std::uint64_t max_states,
                                                    RunMonitor* monitor = nullptr);

// The illumination question (docs/optics.md) on the graph of the states
// reachable from the rays, one out-edge per outgoing direction: lit or
// unlit by breadth-first search, the least reflections by Dijkstra on 0/1
// weights. It stops early, with Reason::limit, when more than max_states
// states are reachable (Limit::memory), when max_expanded states have been
// expanded (one event each; Limit::steps, the cap of SolveOptions::max_steps)
// or when the monitor, polled every 1024 states, says so. Then the targets
// passed by the states built so far are lit (optics.md: "the targets lit so
// far"), with the least count over the graph built so far, which is proven
// least (TargetAnswer::best_proven) only when it is 0 reflections from ray 1;
// the others are unknown.
Answer explore_illumination_graph(const Scene& scene, std::uint64_t max_states,
                                  RunMonitor* monitor = nullptr,
                                  std::optional<std::uint64_t> max_expanded = std::nullopt);

} // namespace orthoray
