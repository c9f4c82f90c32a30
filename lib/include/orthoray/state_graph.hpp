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
    std::uint64_t states = 0;    // vertices that are lattice states
    std::uint64_t reachable = 0; // of them, reachable from the start
    bool injective = true;       // no state is the image of two states
    Answer answer;
};

// std::nullopt when the scene has more than max_states lattice states. A
// monitor is polled every 1024 states; when it reports a limit the report's
// answer is that limit (Reason::limit, 0 reflections).
std::optional<StateGraphReport> explore_state_graph(const Scene& scene, std::uint64_t max_states,
                                                    RunMonitor* monitor = nullptr);

} // namespace orthoray
