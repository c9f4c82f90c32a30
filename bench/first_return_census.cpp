// first_return_census: how many pieces a first-return table of a random
// mirror scene needs at the least, in 2D and 3D (issue 17, item 2).
//
// A slot is one side of one element and one direction leaving it: in 2D two
// directions a side, in 3D four. The first-return map of a slot sends a point
// of the face to the first element the ray from it meets; where that element
// is the same, the map is one translation, so a piece table needs at least
// one piece for every distinct element the slot's points reach (an escape
// counts as one). Shooting from a g x g grid of the face's lattice points
// (g points in 2D) and counting the distinct elements met gives a lower bound
// on the pieces of that slot; it grows with g towards the true count.
//
// In 2D the true count is known (the piece tables: shoot/piece_table.hpp),
// so the 2D rows show how close the bound gets. In 3D no table is built: the
// bound says whether one could fit the memory the issue allows.
//
// Every shot is orthoray's exact shooter (int64 lattice arithmetic): the
// counts are exact for the sampled points. Not a test. How to run it:
// bench/README.md.
#include "parse_options.hpp"
#include "scenes.hpp"

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/cross_section_grid.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace orthoray;
using namespace orthoray::bench;
using Int = std::int64_t;

// The element met first, or `escape`.
constexpr std::uint32_t escape = ~std::uint32_t{0};

struct Census {
    std::size_t slots = 0;
    std::size_t distinct = 0; // summed over the slots: the lower bound
    std::size_t most = 0;     // the most in one slot
};

// Sample i of g between lo and hi, strictly inside: lo + (hi - lo)(2i + 1)/(2g).
Int sample(Int lo, Int hi, int i, int g) {
    return lo + (hi - lo) * (2 * i + 1) / (2 * g);
}

template <int M, class Shooter>
Census census(const lattice::LatticeScene& ls, const Shooter& shooter, int g) {
    Census c;
    std::vector<std::uint32_t> met;
    for (const lattice::LatticeElement& e : ls.elements) {
        if (e.absorber) continue;
        int other[2] = {0, 0}, others = 0;
        for (int j = 0; j < M; ++j)
            if (j != e.axis) other[others++] = j;
        Int lo[M], hi[M];
        for (int j = 0; j < M; ++j) {
            lo[j] = lattice::from_integer<Int>(e.lo[j]);
            hi[j] = lattice::from_integer<Int>(e.hi[j]);
        }
        const int rows = M == 3 ? g : 1;
        for (unsigned negative = 0; negative < (1u << M); ++negative) {
            met.clear();
            for (int i = 0; i < g; ++i)
                for (int r = 0; r < rows; ++r) {
                    Int p[M];
                    p[e.axis] = lo[e.axis];
                    p[other[0]] = sample(lo[other[0]], hi[other[0]], i, g);
                    if (M == 3) p[other[1]] = sample(lo[other[1]], hi[other[1]], r, g);
                    const shoot::Shot<Int> hit = shooter.shoot(p, negative);
                    met.push_back(hit.escape ? escape : hit.mirror);
                }
            std::sort(met.begin(), met.end());
            const std::size_t distinct =
                static_cast<std::size_t>(std::unique(met.begin(), met.end()) - met.begin());
            ++c.slots;
            c.distinct += distinct;
            c.most = std::max(c.most, distinct);
        }
    }
    return c;
}

template <int M>
void run(std::int64_t n, const std::vector<int>& grids) {
    const Scene scene = random_box(M, n, 1);
    const lattice::LatticeScene ls = lattice::make_lattice(scene);
    // The 2D tables' pieces, or the 3D cross-section grid's registrations:
    // what each dimension's engine holds today.
    std::string held;
    std::vector<Census> rows;
    if constexpr (M == 2) {
        const shoot::UniformGrid<Int, 2> grid(ls);
        for (int g : grids) rows.push_back(census<2>(ls, grid, g));
        const auto table = shoot::PieceTable<Int>::build(grid, ~std::size_t{0}, {});
        held = table ? std::to_string(table->size()) + " pieces" : "over the cap";
    } else {
        const shoot::CrossSectionGrid<Int, 3> grid(ls, 16); // as the 3D engine builds it
        for (int g : grids) rows.push_back(census<3>(ls, grid, g));
        held = std::to_string(grid.member_count()) + " registrations";
    }
    for (std::size_t i = 0; i < grids.size(); ++i) {
        const Census& c = rows[i];
        std::printf("| %dD | %lld | %zu | %d | %zu | %.2f | %zu | %s |\n", M,
                    static_cast<long long>(n), c.slots, grids[i], c.distinct,
                    static_cast<double>(c.distinct) / static_cast<double>(c.slots), c.most,
                    held.c_str());
    }
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"first_return_census: a lower bound on the pieces of a first-return table of "
                 "bench/scenes.hpp's random boxes, from exact shots at sampled face points"};
    std::vector<std::int64_t> sizes{100, 1000, 10000, 100000};
    std::vector<int> grids{4, 8, 16};
    std::vector<int> dims{2, 3};
    app.add_option("--mirrors", sizes, "random mirrors (besides the box)")
        ->check(CLI::Range(std::int64_t{1}, std::int64_t{1'000'000}));
    app.add_option("--grid", grids, "points a face side (g x g points a 3D face, g a 2D one)")
        ->check(CLI::Range(1, 256));
    app.add_option("--dim", dims, "2, 3 or both")->check(CLI::IsMember({2, 3}));
    parse_options(app, "first_return_census", argc, argv);

    std::printf("| dim | mirrors | slots | g | distinct first elements (pieces at least) | a "
                "slot | most in a slot | the engine's structure holds |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    for (int dim : dims)
        for (std::int64_t n : sizes) dim == 2 ? run<2>(n, grids) : run<3>(n, grids);
}
