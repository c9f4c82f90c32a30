// The polynomial-time 2D engine: build the interval exchange from the piece
// tables, induce on it, and turn the orbit of x into an answer
// (docs/induction.md). The lattice engine calls it once a run has its
// tables: right away for Engine::induction, after a short simulation for
// Engine::automatic.
#pragma once

#include "lattice/lattice_scene.hpp"
#include "orthoray/exchange.hpp"
#include "orthoray/solve.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>

namespace orthoray::induction {

// The most pieces the induction engine lets the piece tables have: its cost
// grows with the pieces, not with the reflections, so it allows more than
// simulation does (64 a mirror, lattice_engine.cpp).
inline std::size_t piece_cap(std::size_t elements) {
    return std::max<std::size_t>(64 * elements + 1024, std::size_t{1} << 20);
}

// The answer's reason and reflections from an induced orbit (the axis
// engine's and the octagonal one's alike): a cycle of its period, or the
// event at T^e(x), which the ray meets after reflection e + 1.
void set_outcome(Answer& answer, const InducedOrbit& orbit);

struct Decision {
    // Decided within options.max_steps, or (without a certificate:
    // options.path, options.induction_observer) the limit a simulation
    // would reach at max_steps.
    std::optional<Answer> answer;
    std::optional<Limit> limit; // the monitor stopped the induction
    // With `limit`, once the exchange was built: how far the induction got.
    std::optional<Answer::Stats::Induction> stopped_at;
};

// Decides the run whose first reflection has been taken (`reflections` so
// far, for the monitor). No answer and no limit means the answer needs more
// reflections than options.max_steps allows and a certificate wants every
// point up to there: the caller simulates up to it.
// `poll` polls the monitor while the exchange is built; it throws
// lattice::SetupStopped, which the caller catches.
template <class Int>
Decision decide(const lattice::LatticeScene& scene, const shoot::UniformGrid<Int, 2>& grid,
                const shoot::PieceTable<Int>& table, const SolveOptions& options,
                std::uint64_t reflections, const lattice::SetupPoll& poll);

} // namespace orthoray::induction
