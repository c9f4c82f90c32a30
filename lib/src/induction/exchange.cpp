// The public exchange API (orthoray/exchange.hpp): the exchange the
// induction engine would build for a scene, and the induction on it.
#include "orthoray/exchange.hpp"

#include "induction/exchange_builder.hpp"
#include "induction/induction_engine.hpp"
#include "induction/octagonal_induction.hpp"
#include "induction/rauzy_induction.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

namespace orthoray {
namespace {

// As the lattice engine builds them for Engine::induction: the default grid,
// the tables with the induction's cap and the target marked.
template <class Int>
std::optional<IntervalExchange> exchange_on(const lattice::LatticeScene& scene) {
    const shoot::UniformGrid<Int, 2> grid(scene);
    auto table = shoot::PieceTable<Int>::build(grid, induction::piece_cap(grid.size()));
    if (!table) return std::nullopt;
    if (scene.target_reachable) {
        Int target[2];
        for (int j = 0; j < 2; ++j) target[j] = lattice::from_integer<Int>(scene.target[j]);
        table->mark_target(grid, target);
    }
    return induction::build_exchange_from_start(scene, grid, *table);
}

} // namespace

std::optional<IntervalExchange> exchange_of(const Scene& scene) {
    if (scene.has_diagonal()) return induction::octagonal_exchange_of(scene);
    if (scene.dim != 2) return std::nullopt;
    const lattice::LatticeScene ls = lattice::make_lattice(scene);
    if (ls.dim != 2) return std::nullopt; // a direction along an axis: no exchange
    // A one-way mirror the ray can meet lets two states step to one: the
    // first-return map is no bijection, so there is no exchange to give.
    if (ls.one_sided) return std::nullopt;
    // The exchange is in exact integers whatever the tables ran on; the
    // narrowest type the scene's bound allows is the fastest.
    if (ls.magnitude < lattice::int64_limit()) return exchange_on<std::int64_t>(ls);
    if (ls.magnitude < lattice::int128_limit()) return exchange_on<lattice::int128_t>(ls);
    return exchange_on<Integer>(ls);
}

InducedOrbit induce(const IntervalExchange& exchange, InductionObserver* observer) {
    if (observer) observer->begin(exchange, [] { return false; });
    return *induction::induce(exchange, observer, nullptr);
}

} // namespace orthoray
