// The lattice stepper for scenes with diagonals. A state is (integer point,
// direction index); one step asks the hierarchy for the next hit, checks the
// target on the segment, moves by t w and looks the leaving direction up in
// the outcome table (lattice::OctagonalOutcomes, filled from engine/event_rule).
//
// Diagonals make the step map non-injective (where a diagonal and an axis
// element meet, a ray across both and a ray sliding along the axis element
// leave alike), so every such scene runs Brent's detector and finds the
// tail in a second pass, as scenes with one-sided elements do in
// lattice_engine.cpp, in O(1) states; limits are honoured the same way:
// max_steps inside the loop, the monitor between chunks of about 10 ms.
#include "engine/octagonal_engine.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/tail_search.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/octagonal_lattice.hpp"
#include "shoot/octagonal_bvh.hpp"

#include <algorithm>
#include <chrono>
#include <new>
#include <optional>

namespace orthoray::engine {
namespace {

using lattice::OctagonalLattice;
using Clock = std::chrono::steady_clock;

template <class Int>
struct State {
    Int p[2];
    unsigned d; // a canonical direction index
    bool operator==(const State& o) const { return p[0] == o.p[0] && p[1] == o.p[1] && d == o.d; }
};

// Whether `target` lies on the closed segment p .. p + t w (the whole ray
// when the shot escapes): target - p = tau w with 0 <= tau <= t. tau is an
// integer when it exists (gcd(w_x, w_y) = 1).
template <class Int>
bool passes(const Int (&target)[2], const Int (&p)[2], const Int (&w)[2],
            const shoot::OctagonalShot<Int>& shot) {
    const Int dx = target[0] - p[0], dy = target[1] - p[1];
    if (w[0] * dy != w[1] * dx) return false;
    const int j = w[0] != 0 ? 0 : 1;
    const Int along = j == 0 ? dx : dy;
    if (along != 0 && (along < 0) != (w[j] < 0)) return false; // behind p
    return shot.escape ||
           !(shot.t * (w[j] < 0 ? Int(-w[j]) : w[j]) < (along < 0 ? Int(-along) : along));
}

template <class Int>
class Run {
public:
    Run(const OctagonalLattice& lattice, const SolveOptions& options,
        const lattice::SetupPoll& poll)
        : lattice_(lattice), options_(options), outcomes_(lattice), shooter_(lattice, poll) {
        for (int j = 0; j < 2; ++j) {
            s_.p[j] = lattice::from_integer<Int>(lattice.start[j]);
            target_[j] = lattice::from_integer<Int>(lattice.target[j]);
        }
        for (unsigned d = 0; d < lattice::direction_count; ++d)
            for (int j = 0; j < 2; ++j) w_[d][j] = lattice::from_integer<Int>(lattice.w[d][j]);
        s_.d = 0;
        answer_.engine = EngineUsed::lattice;
        answer_.arithmetic = lattice::arithmetic_used(Int{});
        answer_.shooter = ShooterUsed::bvh;
        if (options_.path) report(s_);
    }

    // Steps to an answer or a limit, polling the monitor between chunks
    // sized from the last one's rate to take about 10 ms.
    Answer run() {
        std::uint64_t chunk = 1; // one reflection on huge numbers takes milliseconds
        while (true) {
            if (options_.monitor)
                if (const std::optional<Limit> limit = options_.monitor->poll(reflections_)) {
                    answer_.limit = *limit;
                    finish(Reason::limit);
                    return answer_;
                }
            const auto begin = Clock::now();
            if (advance(options_.monitor ? reflections_ + chunk : ~std::uint64_t{0})) {
                if (period_) tail_pass(*period_);
                return answer_;
            }
            const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
            const double scaled = seconds > 0 ? chunk * (0.01 / seconds) : 2.0 * chunk;
            chunk = static_cast<std::uint64_t>(
                std::clamp(scaled, 1.0, std::min(2.0 * chunk, double(std::uint64_t{1} << 24))));
        }
    }

    Answer& answer() { return answer_; }

private:
    const OctagonalLattice& lattice_;
    const SolveOptions& options_;
    const lattice::OctagonalOutcomes outcomes_;
    const shoot::OctagonalBvh<Int> shooter_;
    Int w_[lattice::direction_count][2];
    State<Int> s_, first_{};
    Int target_[2];
    std::uint64_t reflections_ = 0;
    BrentDetector<State<Int>> detector_;
    std::optional<std::uint64_t> period_; // found; the tail pass comes next
    Answer answer_;

    // The state after the next event, or nothing when the ray escapes or
    // stops (never on the cycle a detector has found).
    std::optional<State<Int>> next(const State<Int>& s,
                                   const shoot::OctagonalShot<Int>& shot) const {
        if (shot.escape) return std::nullopt;
        const std::uint8_t d = outcomes_.next(s.d, shot.mirrors, shot.absorbers);
        if (d == lattice::absorbed) return std::nullopt;
        State<Int> n;
        for (int j = 0; j < 2; ++j) n.p[j] = s.p[j] + shot.t * w_[s.d][j];
        n.d = d;
        return n;
    }

    // Steps until an answer (true) or until `until` reflections (false).
    bool advance(std::uint64_t until) {
        while (reflections_ < until) {
            const shoot::OctagonalShot<Int> shot = shooter_.shoot(s_.p, s_.d);
            if (passes(target_, s_.p, w_[s_.d], shot)) return finish(Reason::hit);
            if (shot.escape) return finish(Reason::escape);
            const std::optional<State<Int>> after = next(s_, shot);
            if (!after) { // absorbed: the certificate ends at the absorber
                for (int j = 0; j < 2; ++j) s_.p[j] += shot.t * w_[s_.d][j];
                if (options_.path) report(s_);
                return finish(Reason::absorbed);
            }
            if (options_.max_steps && reflections_ == *options_.max_steps)
                return finish(Reason::limit);
            s_ = *after;
            ++reflections_;
            if (options_.path) report(s_);
            if (reflections_ == 1) first_ = s_;
            if (const std::optional<std::uint64_t> period = detector_.observe(s_, reflections_)) {
                period_ = period;
                return true;
            }
        }
        return false;
    }

    // The tail of the cycle (tail_search.hpp), from the state after
    // reflection 1.
    void tail_pass(std::uint64_t lambda) {
        State<Int> behind = first_;
        auto step = [&](State<Int>& s) { s = *next(s, shooter_.shoot(s.p, s.d)); };
        const TailSearch found = search_tail(behind, lambda, step, options_.monitor, reflections_);
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
            for (int j = 0; j < 2; ++j) c[j] = lattice::to_integer(behind.p[j]);
            options_.path->cycle_start(lattice_.point(c), lattice_.direction(behind.d));
        }
    }

    void report(const State<Int>& s) {
        lattice::Coords c;
        for (int j = 0; j < 2; ++j) c[j] = lattice::to_integer(s.p[j]);
        options_.path->visit(lattice_.point(c), lattice_.direction(s.d));
    }

    bool finish(Reason reason) {
        answer_.reason = reason;
        answer_.reflections = Integer(static_cast<unsigned long>(reflections_));
        return true;
    }
};

// The answer of a run that a limit ended during its setup.
Answer stopped_in_setup(Limit limit, ArithmeticUsed arithmetic) {
    Answer answer;
    answer.engine = EngineUsed::lattice;
    answer.arithmetic = arithmetic;
    answer.limit = limit;
    answer.reflections = 0;
    return answer;
}

// `scaling`: the seconds make_octagonal_lattice took, counted in the setup.
template <class Int>
Answer run(const OctagonalLattice& lattice, const SolveOptions& options, double scaling) {
    const auto begin = Clock::now();
    std::optional<Run<Int>> run;
    try {
        // Builds the hierarchy, polling once an element (lattice/setup_poll.hpp).
        run.emplace(lattice, options, lattice::SetupPoll(options.monitor, 0));
    } catch (const std::bad_alloc&) {
        return stopped_in_setup(Limit::memory, lattice::arithmetic_used(Int{}));
    } catch (const lattice::SetupStopped& stopped) {
        return stopped_in_setup(stopped.limit, lattice::arithmetic_used(Int{}));
    }
    run->answer().stats.setup.seconds =
        scaling + std::chrono::duration<double>(Clock::now() - begin).count();
    return run->run();
}

} // namespace

Answer solve_octagonal(const Scene& scene, const SolveOptions& options) {
    if (options.shooter != Shooter::automatic && options.shooter != Shooter::bvh)
        throw UnsupportedScene("--shooter grid, pieces and section do not take diagonal "
                               "elements; --shooter bvh (the default for them) does");
    std::optional<OctagonalLattice> scaled;
    const auto begin = Clock::now();
    try {
        scaled.emplace(
            lattice::make_octagonal_lattice(scene, lattice::SetupPoll(options.monitor, 0)));
    } catch (const lattice::SetupStopped& stopped) {
        // Stopped while scaling: no integer type was chosen yet.
        return stopped_in_setup(stopped.limit, ArithmeticUsed::none);
    }
    const OctagonalLattice& lattice = *scaled;
    const double scaling = std::chrono::duration<double>(Clock::now() - begin).count();
    const bool fits64 = lattice.magnitude < lattice::int64_limit();
    const bool fits128 = lattice.magnitude < lattice::int128_limit();
    switch (options.arithmetic) {
    case Arithmetic::automatic:
        if (fits64) return run<std::int64_t>(lattice, options, scaling);
        [[fallthrough]];
    case Arithmetic::int128:
        if (fits128) return run<lattice::int128_t>(lattice, options, scaling);
        [[fallthrough]];
    case Arithmetic::wide:
        break;
    }
    return run<Integer>(lattice, options, scaling);
}

} // namespace orthoray::engine
