// The lattice stepper. A state is (integer point, direction mask); one step
// asks a shooter for the next hit, checks the target on the segment, and
// reflects by flipping the mask bits of the mirrors' normal axes.
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
#include "engine/poll_pacer.hpp"
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

namespace orthoray::engine {
namespace {

using lattice::LatticeScene;

// Reflections stepped on the grid before building piece tables. The tables
// cost about 10 microseconds a mirror and repay it only after some 60 to 600
// reflections a mirror (bench/RESULTS.md: 10^3 and 10^5 mirrors), so the
// switch waits longer in bigger scenes.
std::uint64_t grid_phase(std::size_t elements) {
    return std::max<std::uint64_t>(std::uint64_t{1} << 14, 64 * std::uint64_t{elements});
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
constexpr std::uint32_t no_mirror = ~std::uint32_t{0};

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

template <class Int, int M>
struct State {
    Int p[M];
    unsigned negative;
    bool operator==(const State& o) const {
        for (int j = 0; j < M; ++j)
            if (p[j] != o.p[j]) return false;
        return negative == o.negative;
    }
};

// +1 or -1 for axis j of a direction mask: multiplying by it instead of
// branching on the mask keeps the hot loop free of unpredictable jumps.
template <class Int>
Int sign(unsigned negative, int j) {
    return Int(1 - 2 * static_cast<int>((negative >> j) & 1u));
}

// Whether `target` lies on the closed segment p .. p + t*sigma (or on the
// whole ray when the shot escapes): target - p = tau * sigma, 0 <= tau <= t.
template <class Int, int M>
bool passes(const Int (&target)[M], const State<Int, M>& s, const shoot::Shot<Int>& shot) {
    const Int tau = sign<Int>(s.negative, 0) * Int(target[0] - s.p[0]);
    if (tau < 0 || (!shot.escape && shot.t < tau)) return false;
    for (int j = 1; j < M; ++j)
        if (sign<Int>(s.negative, j) * Int(target[j] - s.p[j]) != tau) return false;
    return true;
}

template <class Int, int M, class Detector>
class Run {
public:
    Run(const LatticeScene& ls, const SolveOptions& options) : ls_(ls), options_(options) {
        for (int j = 0; j < M; ++j) {
            s_.p[j] = lattice::from_integer<Int>(ls.start[j]);
            target_[j] = lattice::from_integer<Int>(ls.target[j]);
        }
        s_.negative = ls.start_direction;
        answer_.engine = EngineUsed::lattice;
        answer_.arithmetic = lattice::arithmetic_used(Int{});
        if (options_.path) report();
    }

    // Steps with `shoot(state, mirror)` until an answer, or until `until`
    // reflections have been performed (then returns false). A call may end
    // after its last shot was computed but before that reflection is taken;
    // the shot is kept and taken first by the next call, since a shooter may
    // have moved on with it (the piece tables' cursor does).
    template <class Shoot>
    bool advance(Shoot&& shoot, std::uint64_t until) {
        // One bound for both reasons to stop stepping.
        const std::uint64_t stop =
            options_.max_steps ? std::min(until, *options_.max_steps) : until;
        // An answer; a cycle of a scene with one-sided elements first has
        // its tail found.
        auto ended = [&](Step step) {
            if (step == Step::answered && period_) tail_pass(shoot.fresh(), *period_);
            return step == Step::answered;
        };
        if (pending_) {
            const shoot::Shot<Int> shot = *pending_;
            pending_.reset();
            if (const Step step = take(shot, stop); step != Step::next) return ended(step);
        }
        while (true) {
            // The tables' fast path takes the plain reflections; a step it
            // leaves (escape, absorber, target near, back at state 1) is
            // taken here. It keeps no path and knows only the first-state
            // detector, and it leaves mirror_ behind (a placed cursor no
            // longer reads it).
            if constexpr (requires { shoot.glide(s_, stop, first_); } &&
                          std::is_same_v<Detector, FirstStateDetector<State<Int, M>>>)
                if (reflections_ >= 1 && !options_.path)
                    reflections_ += shoot.glide(s_, stop - reflections_, first_);
            if (const Step step = take(shoot(s_, mirror_), stop); step != Step::next)
                return ended(step);
        }
    }

    // advance() in chunks, polling the monitor between them (without one, a
    // single call). A chunk is sized from the last one's rate to take about
    // 10 ms, so a stop request is seen within a few tens of milliseconds
    // however slow a reflection is, and the loop itself has no checks.
    template <class Shoot>
    bool advance_in_chunks(Shoot&& shoot, std::uint64_t until) {
        if (!options_.monitor) return advance(shoot, until);
        using Clock = std::chrono::steady_clock;
        constexpr double chunk_seconds = 0.01;
        // From 1: on 10^6-digit coordinates one reflection takes milliseconds.
        std::uint64_t chunk = 1;
        while (true) {
            if (const std::optional<Limit> limit = options_.monitor->poll(reflections_)) {
                answer_.limit = *limit;
                return finish(Reason::limit);
            }
            if (reflections_ >= until) return false;
            const std::uint64_t next = until - reflections_ > chunk ? reflections_ + chunk : until;
            const auto begin = Clock::now();
            if (advance(shoot, next)) return true;
            const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
            const double scaled = seconds > 0 ? chunk * (chunk_seconds / seconds) : 2.0 * chunk;
            chunk = static_cast<std::uint64_t>(
                std::clamp(scaled, 1.0, std::min(2.0 * chunk, double(std::uint64_t{1} << 24))));
        }
    }

    // Ends the run with a limit that struck outside advance() (memory).
    void stop(Limit limit) {
        answer_.limit = limit;
        finish(Reason::limit);
    }

    // Between setup phases (scaling, a shooter, the tables), each of which
    // can take a while on huge numbers: true, with the run ended, when the
    // monitor asks to stop.
    bool stopped_by_monitor() {
        if (!options_.monitor) return false;
        const std::optional<Limit> limit = options_.monitor->poll(reflections_);
        if (limit) stop(*limit);
        return limit.has_value();
    }

    // Polls the monitor from inside a setup phase (lattice/setup_poll.hpp):
    // at every unit on GMP integers, where one can take milliseconds, and
    // every 64 units on machine integers, where one takes about a microsecond.
    lattice::SetupPoll setup_poll() const {
        return {options_.monitor, reflections_, std::is_same_v<Int, Integer> ? 1u : 64u};
    }

    std::uint64_t reflections() const { return reflections_; }
    const Int (&target() const)[M] { return target_; }
    Answer& answer() { return answer_; }

private:
    const LatticeScene& ls_;
    const SolveOptions& options_;
    State<Int, M> s_;
    Int target_[M];
    std::uint32_t mirror_ = no_mirror; // a mirror the current point lies on, once reflected
    std::uint64_t reflections_ = 0;
    Detector detector_;
    Answer answer_;

    std::optional<shoot::Shot<Int>> pending_; // computed, reflection not yet taken

    // One-sided elements: the state and mirror after reflection 1, where the
    // tail pass starts, and the period once Brent's detector has found it.
    State<Int, M> first_{};
    std::uint32_t first_mirror_ = no_mirror;
    std::optional<std::uint64_t> period_;

    // mu of docs/optics.md: the least i >= 1 with s_i = s_(i + lambda). Two
    // walkers, s_i and s_(i + lambda), step side by side from i = 1 (the
    // second pass of Brent's method) with their own copies of `shoot`; O(1)
    // states. The cycle is known, so no walker escapes or stops, and there
    // are fewer than 2 r steps (r: the reflections taken, >= mu + lambda).
    // The monitor is polled between chunks of about 10 ms, as in stepping.
    template <class Shoot>
    void tail_pass(const Shoot& fresh, std::uint64_t lambda) {
        struct Walker {
            State<Int, M> s;
            std::uint32_t mirror;
            Shoot next_hit;
            void step() {
                const shoot::Shot<Int> shot = next_hit(s, mirror);
                for (int j = 0; j < M; ++j) s.p[j] += sign<Int>(s.negative, j) * shot.t;
                s.negative ^= shot.flip;
                mirror = shot.mirror;
            }
        };
        Walker behind{first_, first_mirror_, fresh}, ahead = behind;
        PollPacer pacer;
        // One pair of steps (or one step of `ahead` while it runs ahead);
        // false when the monitor stopped the run.
        auto paced = [&] {
            if (!options_.monitor || !pacer.due()) return true;
            if (const std::optional<Limit> limit = options_.monitor->poll(reflections_)) {
                answer_.limit = *limit;
                finish(Reason::limit);
                return false;
            }
            return true;
        };
        for (std::uint64_t i = 0; i < lambda; ++i) {
            ahead.step();
            if (!paced()) return;
        }
        std::uint64_t mu = 1;
        while (!(behind.s == ahead.s)) {
            behind.step();
            ahead.step();
            ++mu;
            if (!paced()) return;
        }
        answer_.tail = Integer(static_cast<unsigned long>(mu - 1));
        reflections_ = mu - 1 + lambda;
        finish(Reason::cycle);
        if (options_.path) {
            lattice::Coords c;
            for (int j = 0; j < M; ++j) c[j] = lattice::to_integer(behind.s.p[j]);
            options_.path->cycle_start(ls_.point(c), ls_.direction(behind.s.negative));
        }
    }

    enum class Step { next, answered, paused };
    Step answered(Reason reason) {
        finish(reason);
        return Step::answered;
    }

    // One step with `shot`: go on, an answer, or a pause at `stop` (the
    // shot kept for the next call).
    [[gnu::always_inline]] Step take(const shoot::Shot<Int>& shot, std::uint64_t stop) {
        if (ls_.target_reachable && shot.near_target && passes(target_, s_, shot))
            return answered(Reason::hit);
        if (shot.escape) return answered(Reason::escape);
        for (int j = 0; j < M; ++j) s_.p[j] += sign<Int>(s_.negative, j) * shot.t;
        if (shot.absorber) {
            if (options_.path) report();
            return answered(Reason::absorbed);
        }
        if (reflections_ == stop) {
            if (options_.max_steps && reflections_ == *options_.max_steps)
                return answered(Reason::limit);
            for (int j = 0; j < M; ++j) // not taken yet: undo the move, keep the shot
                s_.p[j] -= sign<Int>(s_.negative, j) * shot.t;
            pending_ = shot;
            return Step::paused;
        }
        s_.negative ^= shot.flip;
        mirror_ = shot.mirror;
        ++reflections_;
        if (options_.path) report();
        if (reflections_ == 1) {
            first_ = s_;
            first_mirror_ = mirror_;
        }
        if (auto period = detector_.observe(s_, reflections_)) {
            if (ls_.one_sided) { // not yet: advance() runs the tail pass
                period_ = *period;
                return Step::answered;
            }
            // Injective: purely periodic, the tail is 0 (semantics.md).
            reflections_ = *period;
            return answered(Reason::cycle);
        }
        return Step::next;
    }

    void report() {
        lattice::Coords c;
        for (int j = 0; j < M; ++j) c[j] = lattice::to_integer(s_.p[j]);
        options_.path->visit(ls_.point(c), ls_.direction(s_.negative));
    }

    bool finish(Reason reason) {
        answer_.reason = reason;
        answer_.reflections = Integer(static_cast<unsigned long>(reflections_));
        return true;
    }
};

// How a run asks for its next hit: shoot(state, mirror) with the mirror the
// state lies on (no_mirror before the first reflection). fresh() is the same
// shooter with no memory of a trajectory, for the tail pass's walkers.
template <class Int, int M, class NextHit>
struct Stateless {
    const NextHit* next_hit;
    shoot::Shot<Int> operator()(const State<Int, M>& s, std::uint32_t) const {
        return next_hit->shoot(s.p, s.negative);
    }
    Stateless fresh() const { return *this; }
};

// The piece tables follow the ray with a cursor, placed at its first
// reflection (before it, the grid answers).
template <class Int>
struct TableWalk {
    const shoot::PieceTable<Int>* table;
    const shoot::UniformGrid<Int, 2>* grid;
    bool placed = false;
    typename shoot::PieceTable<Int>::Cursor where{};
    shoot::Shot<Int> operator()(const State<Int, 2>& s, std::uint32_t mirror) {
        if (!placed) {
            if (mirror == no_mirror) return grid->shoot(s.p, s.negative);
            where = table->at(mirror, s.negative);
            placed = true;
        }
        return table->shoot(s.p, where);
    }
    // Plain reflections on the tables in one tight loop (PieceTable::glide),
    // once the cursor is placed; the number taken.
    std::uint64_t glide(State<Int, 2>& s, std::uint64_t limit, const State<Int, 2>& first) {
        if (!placed) return 0;
        return table->glide(s.p, s.negative, where, limit, first.p, first.negative);
    }
    TableWalk fresh() const { return {table, grid}; }
};

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
        auto table = shoot::PieceTable<Int>::build(ls, grid,
                                                   options.engine == Engine::induction
                                                       ? induction::piece_cap(grid.size())
                                                       : 64 * grid.size() + 1024,
                                                   run.setup_poll());
        if (table && ls.target_reachable) table->mark_target(grid, run.target(), run.setup_poll());
        setup.seconds += seconds_since(begin);
        if (run.stopped_by_monitor()) return run.answer();
        if (table) {
            setup.pieces = table->size();
            run.answer().shooter = ShooterUsed::pieces;
            // Until the ray first reflects, the tables cannot say where it is.
            TableWalk<Int> by_table{&*table, &grid};
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
                    return run.answer();
                }
                // The answer needs more reflections than max_steps: simulate up to it.
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
    LatticeScene ls;
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
    // The narrowest type the bound proves safe, unless a wider one is asked for.
    const bool fits64 = ls.magnitude < lattice::int64_limit();
    const bool fits128 = ls.magnitude < lattice::int128_limit();
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
}

} // namespace orthoray::engine
