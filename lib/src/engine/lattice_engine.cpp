// The lattice engine: it scales the scene to its lattice, picks a shooter and
// steps a run (lattice_run.hpp: a state is an integer point and a direction
// mask) with it, switching shooters or handing over to induction on the way.
//
// Shooters (docs/shooting.md): in 3D the cross-section grid looks the ray's
// line up in one cell. In 2D the uniform grid answers any query with no
// setup beyond its cells, and the piece tables answer one with a search
// among a mirror's few pieces but cost a preprocessing pass, so by default a
// run starts on the grid and switches to the tables only if it has not ended
// after grid_phase(n) reflections. Crowded scenes get the BVH.
//
// One-sided elements: every shooter meets only the elements acting on the
// ray's direction (filtered when it is built, docs/shooting.md), so the steps
// are the acting rule's. The step map may then be non-injective: Brent's
// detector finds the period, and a second pass (tail_pass) the tail.
#include "engine/lattice_engine.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/lattice_run.hpp"
#include "induction/induction_engine.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/bvh.hpp"
#include "shoot/cross_section_grid.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <chrono>
#include <new>
#include <optional>
#include <string>

namespace orthoray::engine {
namespace {

using lattice_run::no_mirror;
using lattice_run::Run;
using lattice_run::State;
using lattice_run::Stateless;
using lattice_run::TableWalk;

using lattice::LatticeScene;

// Reflections stepped on the grid before building piece tables. This is
// the ski-rental choice: rent (step on the grid) until the rent paid equals
// the price (the tables' build), then buy; no run then costs more than about
// twice what it would with the better choice known in advance. The build
// costs 2-3 microseconds a mirror and saves some 140 ns a reflection
// (random boxes of 10^3 to 10^5 mirrors, bench/RESULTS.md, sixteenth pass),
// so it repays itself after 16 to 22 reflections a mirror on that machine;
// 32 leaves room for one that builds up to twice as slowly.
std::uint64_t grid_phase(std::size_t elements) {
    return std::max<std::uint64_t>(std::uint64_t{1} << 14, 32 * std::uint64_t{elements});
}

// The reflections that cost about as much as `reflections` on integers of
// at most 128 bits. On GMP integers a reflection copies, adds and compares
// numbers of the coordinates' size, so its cost grows with their bits (about
// 3 ms a reflection at 10^6 digits, where a 64-bit one takes 20 ns): the
// phases counted in reflections shrink in proportion, to at least 16.
std::uint64_t at_step_cost(std::uint64_t reflections, const Integer& magnitude) {
    const std::uint64_t bits = mpz_sizeinbase(magnitude.get_mpz_t(), 2);
    if (bits <= 128) return reflections;
    return std::max<std::uint64_t>(16, reflections / (bits / 128));
}

// Reflections on the piece tables worth at most about one induction on
// them. An induction takes about k log2 N steps (k pieces, N states, log2 N
// about the coordinates' bits) of some 250 ns; a table step takes 20 ns on
// int64 and up to 60 ns on wider integers (bench/RESULTS.md), so
// 2 k log2 N reflections cost a quarter to half an induction.
// Past 128 bits that estimate fails: the induction's division steps cover
// many reflections each, so it takes far fewer than log2 N steps (a box with
// 10^6-digit sides: 28 steps, where log2 N is 3.3 million). The budget stops
// growing there, and at_step_cost scales it to the cost of a step.
std::uint64_t induction_budget(std::size_t pieces, const Integer& magnitude) {
    const std::uint64_t bits =
        std::min<std::uint64_t>(mpz_sizeinbase(magnitude.get_mpz_t(), 2) + 8, 136);
    return 2 * std::uint64_t{pieces} * bits;
}

// The largest piece table that is composed with itself for the glide
// (two_step_table.hpp). Measured in bench/RESULTS.md ("Two reflections a
// lookup"): the two-step table pays while both tables stay near L2.
constexpr std::size_t two_step_cap = std::size_t{1} << 15;

double seconds_since(std::chrono::steady_clock::time_point begin) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
}

// Steps to the answer with `shooter`, reporting which it is.
template <class Int, int M, class Detector, class NextHit>
Answer finish_with(Run<Int, M, Detector>& run, ShooterUsed name, const NextHit& shooter) {
    run.answer().shooter = name;
    run.advance_in_chunks(Stateless<Int, M, NextHit>{&shooter}, ~std::uint64_t{0});
    return run.answer();
}

// The same with a shooter built by `make`, its setup time counted.
template <class Int, int M, class Detector, class Make>
Answer build_and_finish(Run<Int, M, Detector>& run, ShooterUsed name, Make&& make) {
    const auto begin = std::chrono::steady_clock::now();
    const auto shooter = make();
    run.answer().stats.setup.seconds += seconds_since(begin);
    if (run.stopped_by_monitor()) return run.answer();
    return finish_with(run, name, shooter);
}

// A shooter suits elements spread over their box; when many crowd into a few
// cells (one cell holding more than 64 elements and 16 times its share), a
// shot through them tests them all, and the hierarchy is faster. Measured in
// docs/shooting.md.
bool clustered(std::size_t fullest, std::size_t members, std::size_t cells) {
    const std::size_t share = members / std::max<std::size_t>(1, cells) + 1;
    return fullest > 64 && fullest > 16 * share;
}

// 2D: the uniform grid first (no setup, so short questions stay instant),
// then the piece tables once a run has gone on for grid_phase reflections.
template <class Int, int M, class Detector>
Answer run_planar(Run<Int, M, Detector>& run, const LatticeScene& ls, const SolveOptions& options) {
    auto begin = std::chrono::steady_clock::now();
    const shoot::UniformGrid<Int, M> grid(ls, options.grid_density ? options.grid_density : 2,
                                          run.setup_poll());
    Answer::Stats::Setup& setup = run.answer().stats.setup;
    setup.seconds += seconds_since(begin);
    setup.cells = grid.cell_count();
    run.answer().shooter = ShooterUsed::grid;
    if (run.stopped_by_monitor()) return run.answer();
    // The induction engine stands on the tables and starts from state 1; it
    // needs a bijection, so one-sided scenes are simulated (docs/induction.md).
    const bool induce =
        ls.scene->dim == 2 && !ls.one_sided &&
        (options.engine == Engine::induction ||
         (options.engine == Engine::automatic &&
          (options.shooter == Shooter::automatic || options.shooter == Shooter::pieces)));
    const bool tables =
        induce || options.shooter == Shooter::automatic || options.shooter == Shooter::pieces;
    if (tables) {
        // Reflections on the grid first: the grid phase, or none when the
        // tables are asked for at once; the induction needs state 1 taken.
        std::uint64_t first = options.shooter == Shooter::pieces
                                  ? 0
                                  : at_step_cost(grid_phase(grid.size()), ls.magnitude);
        if (induce && (options.engine == Engine::induction || first == 0)) first = 1;
        const Stateless<Int, M, shoot::UniformGrid<Int, M>> by_grid{&grid};
        if (run.advance_in_chunks(by_grid, first)) return run.answer();
        // Piece tables may grow quadratic with crossings: past 64 pieces a
        // mirror on average, stay on the grid.
        begin = std::chrono::steady_clock::now();
        // The induction engine takes more: its cost grows with the pieces, not
        // with the reflections.
        auto table = shoot::PieceTable<Int>::build(grid,
                                                   options.engine == Engine::induction
                                                       ? induction::piece_cap(grid.size())
                                                       : 64 * grid.size() + 1024,
                                                   run.setup_poll());
        if (table && ls.target_reachable) table->mark_target(grid, run.target(), run.setup_poll());
        // Two reflections a lookup (two_step_table.hpp) while both tables
        // stay near the cache, for a run that glides (not with a path or
        // Brent's detector); the induction does not glide for long.
        std::optional<shoot::TwoStepTable<Int>> two_step;
        if (table && !induce && run.glides() && table->size() <= two_step_cap)
            two_step =
                shoot::TwoStepTable<Int>::build(*table, grid, 4 * two_step_cap, run.setup_poll());
        setup.seconds += seconds_since(begin);
        if (run.stopped_by_monitor()) return run.answer();
        if (table) {
            setup.pieces = table->size();
            run.answer().shooter = ShooterUsed::pieces;
            // Until the ray first reflects, the tables cannot say where it is.
            setup.two_step_pieces = two_step ? two_step->size() : 0;
            TableWalk<Int> by_table{&*table, &grid, two_step ? &*two_step : nullptr};
            if (induce) {
                // Auto: step on the tables about as long as inducing would
                // take, then induce; no answer costs more than twice the
                // faster engine's time.
                // A certificate's path prefix is checked point by point, so
                // with one the induction starts right away.
                const std::uint64_t budget =
                    options.engine == Engine::induction || options.path
                        ? 0
                        : at_step_cost(induction_budget(table->size(), ls.magnitude), ls.magnitude);
                if (run.advance_in_chunks(by_table, run.reflections() + budget))
                    return run.answer();
                induction::Decision decision = induction::decide(
                    ls, grid, *table, options, run.reflections(), run.setup_poll());
                if (decision.answer) {
                    decision.answer->stats.setup = setup;
                    return *decision.answer;
                }
                if (decision.limit) {
                    run.stop(*decision.limit);
                    if (decision.stopped_at) {
                        run.answer().engine = EngineUsed::induction;
                        run.answer().stats.induction = *decision.stopped_at;
                    }
                    return run.answer();
                }
                // The answer needs more reflections than max_steps, and the
                // path wants every point up to there: simulate up to it.
            }
            run.advance_in_chunks(by_table, ~std::uint64_t{0});
            return run.answer();
        }
    }
    if (options.shooter == Shooter::bvh ||
        (options.shooter == Shooter::automatic &&
         clustered(grid.fullest_cell(), grid.size(), grid.cell_count())))
        return build_and_finish(run, ShooterUsed::bvh, [&] {
            return shoot::BoundingVolumeHierarchy<Int, M>(ls, run.setup_poll());
        });
    if (options.shooter == Shooter::section)
        return build_and_finish(run, ShooterUsed::section, [&] {
            return shoot::CrossSectionGrid<Int, M>(ls, 1, run.setup_poll());
        });
    return finish_with(run, ShooterUsed::grid, grid);
}

// 1D and 3D: the cross-section grid, which looks the ray's line up instead
// of walking cells (docs/shooting.md), or the BVH when elements cluster.
template <class Int, int M, class Detector>
Answer run_spatial(Run<Int, M, Detector>& run, const LatticeScene& ls,
                   const SolveOptions& options) {
    switch (options.shooter) {
    case Shooter::grid:
        return build_and_finish(run, ShooterUsed::grid, [&] {
            return shoot::UniformGrid<Int, M>(ls, options.grid_density ? options.grid_density : 32,
                                              run.setup_poll());
        });
    case Shooter::bvh:
        return build_and_finish(run, ShooterUsed::bvh, [&] {
            return shoot::BoundingVolumeHierarchy<Int, M>(ls, run.setup_poll());
        });
    default:
        break;
    }
    auto begin = std::chrono::steady_clock::now();
    // Sixteen cells an element to start from: the grid coarsens until its
    // registrations fit its limits, so this refines only small scenes
    // (docs/shooting.md).
    const shoot::CrossSectionGrid<Int, M> section(ls, 16, run.setup_poll());
    Answer::Stats::Setup& setup = run.answer().stats.setup;
    setup.seconds += seconds_since(begin);
    setup.cells = section.cell_count();
    if (options.shooter == Shooter::automatic &&
        clustered(section.fullest_cell(), section.member_count(), section.cell_count()))
        return build_and_finish(run, ShooterUsed::bvh, [&] {
            return shoot::BoundingVolumeHierarchy<Int, M>(ls, run.setup_poll());
        });
    return finish_with(run, ShooterUsed::section, section);
}

template <class Int, int M, class Detector>
Answer run(const LatticeScene& ls, const SolveOptions& options) {
    Run<Int, M, Detector> run(ls, options);
    if (run.stopped_by_monitor()) return run.answer(); // the scaling took long
    try {
        if constexpr (M == 2)
            return run_planar(run, ls, options);
        else
            return run_spatial(run, ls, options);
    } catch (const lattice::SetupStopped& stopped) {
        // Stopped inside a setup phase (a shooter, the tables, the
        // exchange): the phase is dropped, the reflections taken stand.
        run.stop(stopped.limit);
        return run.answer();
    } catch (const std::bad_alloc&) {
        // Building a shooter (grid, tables, hierarchy) is what allocates;
        // the reflections performed before it are still exact.
        run.stop(Limit::memory);
        return run.answer();
    }
}

// The detector follows the scene, as in the reference tracer, so that both
// stop at the same reflection under a cap even when the ray can meet none
// of the one-sided elements (then ls.one_sided is false and the tail 0).
template <class Int, int M>
Answer run_with_detector(const LatticeScene& ls, const SolveOptions& options) {
    if (detector_for(ls.scene->has_one_sided(), options.cycle_detector) == CycleDetector::brent)
        return run<Int, M, BrentDetector<State<Int, M>>>(ls, options);
    return run<Int, M, FirstStateDetector<State<Int, M>>>(ls, options);
}

template <class Int>
Answer run_with_int(const LatticeScene& ls, const SolveOptions& options) {
    switch (ls.dim) {
    case 1:
        return run_with_detector<Int, 1>(ls, options);
    case 2:
        return run_with_detector<Int, 2>(ls, options);
    default:
        return run_with_detector<Int, 3>(ls, options);
    }
}

} // namespace

Answer solve_on_lattice(const Scene& scene, const SolveOptions& options) {
    // Asked for by name, a shooter is used or refused, never replaced.
    if (options.shooter == Shooter::pieces && scene.dim != 2)
        throw UnsupportedScene("--shooter pieces takes 2D scenes (the piece tables are a 2D "
                               "first-return map); in " +
                               std::to_string(scene.dim) + "D --shooter grid, bvh or section does");
    LatticeScene ls;
    const auto begin = std::chrono::steady_clock::now();
    try {
        ls = lattice::make_lattice(scene, lattice::SetupPoll(options.monitor, 0));
    } catch (const lattice::SetupStopped& stopped) {
        // Stopped while scaling: no reflection taken, no arithmetic chosen yet.
        Answer answer;
        answer.engine = EngineUsed::lattice;
        answer.reason = Reason::limit;
        answer.limit = stopped.limit;
        return answer;
    }
    // Scaling the scene to the lattice is setup too: the time to the first
    // reflection starts from the scene as read (as a float tracer's setup
    // starts from converting it).
    const double scaling = seconds_since(begin);
    // The narrowest type the bound proves safe, unless a wider one is asked for.
    const bool fits64 = ls.magnitude < lattice::int64_limit();
    const bool fits128 = ls.magnitude < lattice::int128_limit();
    Answer answer = [&] {
        switch (options.arithmetic) {
        case Arithmetic::automatic:
            if (fits64) return run_with_int<std::int64_t>(ls, options);
            [[fallthrough]];
        case Arithmetic::int128:
            if (fits128) return run_with_int<lattice::int128_t>(ls, options);
            [[fallthrough]];
        case Arithmetic::wide:
            break;
        }
        return run_with_int<Integer>(ls, options);
    }();
    answer.stats.setup.seconds += scaling;
    return answer;
}

} // namespace orthoray::engine
