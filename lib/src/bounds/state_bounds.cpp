// The lattice bound and the line-invariant bound on a trajectory's states;
// the formulas and their derivation are in docs/bounds.md.
#include "orthoray/bounds.hpp"

#include "bounds/state_count.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

namespace orthoray {
namespace {

using lattice::LatticeScene;

std::size_t bits(const Integer& x) {
    return x == 0 ? 0 : mpz_sizeinbase(x.get_mpz_t(), 2);
}

std::size_t input_bits(const Scene& scene) {
    std::size_t total = 0;
    auto take = [&](const Rational& x) { total += bits(x.get_num()) + bits(x.get_den()); };
    for (const Element& e : scene.elements)
        for (int j = 0; j < scene.dim; ++j) {
            take(e.lo[j]);
            if (j != e.axis) take(e.hi[j]);
        }
    for (int j = 0; j < scene.dim; ++j) {
        take(scene.ray().start[j]);
        take(scene.ray().direction[j]);
        take(scene.target()[j]);
    }
    return total;
}

} // namespace

StateBounds compute_bounds(const Scene& scene, bool with_pieces) {
    refuse_diagonals(scene, "bounds");
    const LatticeScene ls = lattice::make_lattice(scene);
    StateBounds b;
    b.dim = ls.dim;
    b.active = ls.active;
    b.scale = ls.scale;
    b.elements = ls.elements.size();
    b.input_bits = input_bits(scene);
    b.magnitude_bits = bits(ls.magnitude);
    b.state_bits = static_cast<std::size_t>(ls.dim) * (b.magnitude_bits + 2);
    const bounds::LineInvariant inv = bounds::line_invariant(ls);
    for (int k = 0, p = 0; k < ls.dim; ++k)
        for (int j = k + 1; j < ls.dim; ++j)
            b.line_modulus[static_cast<std::size_t>(p++)] = inv.modulus[k][j];
    const bounds::StateCount count = ls.dim == 3 ? bounds::count_space_states(ls, inv)
                                                 : bounds::count_line_and_plane_states(ls, inv);
    b.points = count.points;
    b.refined_states = count.refined;
    b.lattice_states = b.points * (1u << ls.dim);
    if (with_pieces && scene.dim == 2 && ls.dim == 2) {
        const shoot::UniformGrid<Integer, 2> grid(ls);
        const auto table = shoot::PieceTable<Integer>::build(ls, grid, ~std::size_t{0});
        b.pieces = table ? table->size() : 0;
    }
    return b;
}

std::optional<Integer> states_visited(const Answer& answer) {
    switch (answer.reason) {
    case Reason::cycle:
    case Reason::hit:
    case Reason::escape:
        return answer.reflections;
    case Reason::absorbed:
        return Integer(answer.reflections + 1);
    case Reason::lit:
    case Reason::unlit:
        return answer.states;
    case Reason::limit:
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace orthoray
