// One run of the lattice stepper (lattice_engine.cpp): the state (an
// integer point and a direction mask), one step with a shot (the target on
// the segment, an escape, an absorber, a reflection flipping the mask bits of
// the mirrors' normal axes, the cycle detector), chunked stepping that polls
// the monitor, the tail pass of one-sided scenes, and the two ways a run asks
// for its next hit (a stateless shooter, or the piece tables' cursor).
#pragma once

#include "engine/cycle_detector.hpp"
#include "engine/tail_search.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "lattice/setup_poll.hpp"
#include "orthoray/solve.hpp"
#include "shoot/piece_table.hpp"
#include "shoot/two_step_table.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <type_traits>

namespace orthoray::engine::lattice_run {

using lattice::LatticeScene;

// The mirror of a state before its first reflection: none.
constexpr std::uint32_t no_mirror = ~std::uint32_t{0};

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
            if constexpr (requires { shoot.glide(s_, stop, first_); } && may_glide)
                if (reflections_ >= 1 && glides())
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

    // Whether a shooter's fast path (glide) is used: it keeps no path and
    // knows only the first-state detector.
    static constexpr bool may_glide = std::is_same_v<Detector, FirstStateDetector<State<Int, M>>>;
    bool glides() const { return may_glide && !options_.path; }

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
    lattice::Coords report_coords_;           // report()'s storage, reused
    Vector report_point_;

    // One-sided elements: the state and mirror after reflection 1, where the
    // tail pass starts, and the period once Brent's detector has found it.
    State<Int, M> first_{};
    std::uint32_t first_mirror_ = no_mirror;
    std::optional<std::uint64_t> period_;

    // The tail of a cycle of a one-sided scene (tail_search.hpp): two
    // walkers from the state after reflection 1, each with its own copy of
    // `shoot`. They take fewer than 2 r steps (r: the reflections taken,
    // >= mu + lambda).
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
            bool operator==(const Walker& o) const { return s == o.s; }
        };
        Walker behind{first_, first_mirror_, fresh};
        const TailSearch found = search_tail(
            behind, lambda, [](Walker& w) { w.step(); }, options_.monitor, reflections_);
        if (found.limit) {
            answer_.limit = *found.limit;
            finish(Reason::limit);
            return;
        }
        answer_.tail = Integer(static_cast<unsigned long>(found.mu - 1));
        reflections_ = found.mu - 1 + lambda;
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

    // One point a reflection to the path's sink (a certificate): into
    // rationals kept from the last report, so no step allocates.
    void report() {
        for (int j = 0; j < M; ++j) lattice::set_integer(report_coords_[j], s_.p[j]);
        ls_.point_into(report_coords_, report_point_);
        options_.path->visit(report_point_, ls_.direction(s_.negative));
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
    // The table composed with itself, when built: the glide takes two
    // reflections a lookup on it.
    const shoot::TwoStepTable<Int>* two_step = nullptr;
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
    // Plain reflections on the tables in one tight loop (PieceTable::glide,
    // TwoStepTable::glide), once the cursor is placed; the number taken.
    std::uint64_t glide(State<Int, 2>& s, std::uint64_t limit, const State<Int, 2>& first) {
        if (!placed) return 0;
        if (two_step)
            return two_step->glide(s.p, s.negative, where, limit, first.p, first.negative);
        return table->glide(s.p, s.negative, where, limit, first.p, first.negative);
    }
    TableWalk fresh() const { return {table, grid, two_step}; }
};

} // namespace orthoray::engine::lattice_run
