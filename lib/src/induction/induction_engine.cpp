#include "induction/induction_engine.hpp"

#include "induction/exchange_builder.hpp"
#include "induction/rauzy_induction.hpp"

#include <chrono>

namespace orthoray::induction {

void set_outcome(Answer& answer, const InducedOrbit& orbit) {
    switch (orbit.event) {
    case ExchangeEvent::none:
        answer.reason = Reason::cycle;
        answer.reflections = orbit.period;
        return;
    case ExchangeEvent::hit:
        answer.reason = Reason::hit;
        break;
    case ExchangeEvent::escape:
        answer.reason = Reason::escape;
        break;
    case ExchangeEvent::absorbed:
        answer.reason = Reason::absorbed;
        break;
    }
    answer.reflections = orbit.offset + 1;
}

namespace {

// On the build's integers Num throughout; the public exchange (GMP) only
// for an observer.
template <class Num, class Int>
Decision decide_on(const lattice::LatticeScene& scene, const shoot::UniformGrid<Int, 2>& grid,
                   const shoot::PieceTable<Int>& table, const SolveOptions& options,
                   std::uint64_t reflections, const lattice::SetupPoll& poll) {
    using Clock = std::chrono::steady_clock;
    const auto begin = Clock::now();
    Decision decision;
    // The run has taken reflection 1, so the first shot neither escapes nor
    // is absorbed: the exchange is there. Its transversals only for an
    // observer, which sees the public exchange.
    const FirstState first = *first_state(scene, grid);
    const ExchangeOn<Num> exchange = build_exchange_on<Num>(
        scene, grid, table, first.x, first.negative, poll, options.induction_observer != nullptr);

    // A stop during the steps reports the induction's engine and how far
    // it got, not the simulation that took the first reflection.
    Answer::Stats::Induction progress;
    progress.pieces = exchange.pieces.size();
    progress.states = lattice::to_integer(exchange.size);
    auto stop = [&](std::uint64_t steps) {
        if (!options.monitor) return false;
        decision.limit = options.monitor->poll(reflections);
        if (!decision.limit) return false;
        progress.steps = steps;
        progress.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
        decision.stopped_at = progress;
        return true;
    };
    if (stop(0)) return decision; // building it takes a while on huge numbers
    const std::optional<InducedOrbit> orbit = induce(exchange, stop);
    if (!orbit) return decision;

    Answer answer;
    answer.engine = EngineUsed::induction;
    answer.arithmetic = orbit->arithmetic;
    answer.shooter = ShooterUsed::pieces;
    set_outcome(answer, *orbit);
    if (options.max_steps) {
        // As a simulation would: it notices a cycle one reflection after the period.
        const Integer needed =
            answer.reflections + (answer.reason == Reason::cycle ? Integer(1) : Integer(0));
        if (needed > Integer(static_cast<unsigned long>(*options.max_steps))) {
            // A certificate needs every point up to the limit, so the
            // caller steps there. Without one, stepping would show no more
            // than the induction has: the answer lies past max_steps. So
            // the limit is the simulation's, at once, where stepping to it
            // could take years (10^8 reflections a second, max_steps up to
            // 2^64 - 1), as the octagonal induction does (capped()).
            if (options.path || options.induction_observer) return decision;
            answer.reason = Reason::limit;
            answer.limit = Limit::steps;
            answer.reflections = Integer(static_cast<unsigned long>(*options.max_steps));
        }
    }
    answer.stats.induction.pieces = exchange.pieces.size();
    answer.stats.induction.states = lattice::to_integer(exchange.size);
    answer.stats.induction.steps = orbit->steps;
    answer.stats.induction.rounds = orbit->rounds;
    if (InductionObserver* observer = options.induction_observer) {
        // Run again, streaming the steps: an observer (a certificate) only
        // gets them once the answer is known to stand (within max_steps).
        const IntervalExchange shown = to_public(exchange);
        if (!observer->begin(shown, [&] { return stop(0); })) return decision;
        if (!induce(shown, observer, stop)) return decision;
    }
    answer.stats.induction.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    decision.answer = std::move(answer);
    return decision;
}

} // namespace

template <class Int>
Decision decide(const lattice::LatticeScene& scene, const shoot::UniformGrid<Int, 2>& grid,
                const shoot::PieceTable<Int>& table, const SolveOptions& options,
                std::uint64_t reflections, const lattice::SetupPoll& poll) {
    switch (build_arithmetic<Int>(scene)) {
    case ArithmeticUsed::int64:
        return decide_on<std::int64_t>(scene, grid, table, options, reflections, poll);
    case ArithmeticUsed::int128:
        return decide_on<lattice::int128_t>(scene, grid, table, options, reflections, poll);
    default:
        return decide_on<Integer>(scene, grid, table, options, reflections, poll);
    }
}

template Decision decide<std::int64_t>(const lattice::LatticeScene&,
                                       const shoot::UniformGrid<std::int64_t, 2>&,
                                       const shoot::PieceTable<std::int64_t>&, const SolveOptions&,
                                       std::uint64_t, const lattice::SetupPoll&);
template Decision decide<lattice::int128_t>(const lattice::LatticeScene&,
                                            const shoot::UniformGrid<lattice::int128_t, 2>&,
                                            const shoot::PieceTable<lattice::int128_t>&,
                                            const SolveOptions&, std::uint64_t,
                                            const lattice::SetupPoll&);
template Decision decide<Integer>(const lattice::LatticeScene&,
                                  const shoot::UniformGrid<Integer, 2>&,
                                  const shoot::PieceTable<Integer>&, const SolveOptions&,
                                  std::uint64_t, const lattice::SetupPoll&);

} // namespace orthoray::induction
