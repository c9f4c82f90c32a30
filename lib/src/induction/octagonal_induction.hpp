// The induction engine on octagonal mazes (2D scenes with diagonal
// elements, docs/octagonal.md): the first reflection by one exact shot, the
// exchange of the eight-sheeted cover (octagonal_exchange.hpp), Rauzy-Zorich
// induction on it, and, on a double cover, a second induction that finds
// whether the physical orbit closes after half the lifted period
// (docs/induction.md, "Octagonal mazes").
#pragma once

#include "orthoray/exchange.hpp"
#include "orthoray/solve.hpp"

#include <optional>
#include <ostream>

namespace orthoray::induction {

// Decides the single trajectory of a 2D scene with diagonal elements. A
// scene whose step map is not injective (a ray sliding along a diagonal
// into a vertex, possible when the direction is axis-parallel or
// diagonal), or whose exchange would exceed the piece cap, is answered by
// the reference tracer instead (the answer's engine says so), and so is
// one with one-sided elements. Certificates are refused (UnsupportedScene).
Answer solve_octagonal_by_induction(const Scene& scene, const SolveOptions& options);

// The same, but nothing where there is no exchange to induce on (one-sided
// elements, a non-injective step map, too many pieces), so that the
// caller can go on simulating (solve()'s automatic engine).
std::optional<Answer> induce_octagonal(const Scene& scene, const SolveOptions& options);

// The exchange (on the cover) solve_octagonal_by_induction would induce; nothing when
// the ray meets nothing before, or at, its first event or when the exchange
// cannot be built (see above).
std::optional<IntervalExchange> octagonal_exchange_of(const Scene& scene);

// Writes the first-return map on the cover (`orthoray pieces`): its
// transversals and raw pieces, on the class of the orbit of the state after
// reflection 1. Returns the number of pieces, nothing when there is no
// reflection or no exchange (two images sharing more than one state).
std::optional<std::size_t> write_octagonal_pieces(const Scene& scene, std::ostream& out);

} // namespace orthoray::induction
