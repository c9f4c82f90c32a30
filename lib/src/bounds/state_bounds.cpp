// The lattice bound and the line-invariant bound on a trajectory's states;
// the formulas and their derivation are in docs/bounds.md.
#include "orthoray/bounds.hpp"

#include "bounds/state_count.hpp"
#include "lattice/lattice_scene.hpp"
#include "lattice/octagonal_lattice.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>

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
    for (const Ray& ray : scene.rays)
        for (int j = 0; j < scene.dim; ++j) {
            take(ray.start[j]);
            take(ray.direction[j]);
        }
    for (const Vector& target : scene.targets)
        for (int j = 0; j < scene.dim; ++j) take(target[j]);
    return total;
}

// A scene with diagonals on its octagonal lattice (docs/bounds.md,
// "Diagonal elements"); no piece tables.
StateBounds octagonal_bounds(const Scene& scene) {
    const lattice::OctagonalLattice l = lattice::make_octagonal_lattice(scene);
    StateBounds b;
    b.dim = 2;
    b.octagonal = true;
    b.directions = l.distinct_directions;
    b.active = {0, 1, 0};
    b.scale = {l.scale, l.scale, 0};
    b.elements = l.elements.size();
    Integer largest = 0;
    auto track = [&](const lattice::Coords& p) {
        for (int j = 0; j < 2; ++j) largest = std::max<Integer>(largest, abs(p[j]));
    };
    track(l.start);
    track(l.target);
    for (const lattice::OctagonalElement& e : l.elements) {
        track(e.lo);
        track(e.hi);
    }
    b.magnitude_bits = bits(largest);
    b.state_bits = 2 * (b.magnitude_bits + 1) + 3; // two signed coordinates, one of 8 directions
    b.line_modulus[0] = l.modulus;
    const bounds::StateCount count = bounds::count_octagonal_states(l);
    b.points = count.points;
    b.refined_states = count.refined;
    b.lattice_states = b.points * b.directions;
    return b;
}

// The bounds of the scene's first ray on its own lattice.
StateBounds ray_bounds(const Scene& scene, bool with_pieces) {
    if (scene.has_diagonal()) return octagonal_bounds(scene);
    const LatticeScene ls = lattice::make_lattice(scene);
    StateBounds b;
    b.dim = ls.dim;
    b.directions = 1u << ls.dim;
    b.active = ls.active;
    b.scale = ls.scale;
    b.elements = ls.elements.size();
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
    b.lattice_states = b.points * b.directions;
    if (with_pieces && scene.dim == 2 && ls.dim == 2) {
        const shoot::UniformGrid<Integer, 2> grid(ls);
        const auto table = shoot::PieceTable<Integer>::build(grid, ~std::size_t{0});
        b.pieces = table ? table->size() : 0;
    }
    return b;
}

} // namespace

StateBounds compute_bounds(const Scene& scene, bool with_pieces) {
    StateBounds b = ray_bounds(scene, with_pieces);
    b.input_bits = input_bits(scene);
    b.rays = scene.rays.size();
    // Every branch of ray r stays on ray r's own lattice (its directions
    // are ray r's with signs changed, or swapped): the state sets add up.
    Scene one = scene;
    for (std::size_t r = 1; r < scene.rays.size(); ++r) {
        one.rays = {scene.rays[r]};
        const StateBounds more = ray_bounds(one, false);
        b.points += more.points;
        b.lattice_states += more.lattice_states;
        b.refined_states += more.refined_states;
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
