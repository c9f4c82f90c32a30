#include "induction/induction_engine.hpp"

#include "induction/exchange_builder.hpp"

#include <chrono>

namespace orthoray::induction {

template <class Int>
Decision decide(const lattice::LatticeScene& scene, const lattice::UniformGrid<Int, 2>& grid,
                const lattice::PieceTable<Int>& table, const SolveOptions& options,
                std::uint64_t reflections) {
    using Clock = std::chrono::steady_clock;
    const auto begin = Clock::now();
    Decision decision;
    // x, the state after reflection 1: the run has taken it, so the first
    // shot neither escapes nor is absorbed.
    Int start[2];
    for (int j = 0; j < 2; ++j) start[j] = lattice::from_integer<Int>(scene.start[j]);
    const lattice::Shot<Int> first = grid.shoot(start, scene.start_direction);
    Integer x[2];
    for (int j = 0; j < 2; ++j)
        x[j] = scene.start[j] + (((scene.start_direction >> j) & 1u)
                                     ? Integer(-lattice::to_integer(first.t))
                                     : lattice::to_integer(first.t));
    auto stop = [&](std::uint64_t) {
        if (!options.monitor) return false;
        decision.limit = options.monitor->poll(reflections);
        return decision.limit.has_value();
    };
    const IntervalExchange exchange =
        build_exchange(scene, grid, table, x, scene.start_direction ^ first.flip);
    if (stop(0)) return decision; // building it takes a while on huge numbers
    const std::optional<OrbitOfFirst> orbit = induce(exchange, nullptr, stop);
    if (!orbit) return decision;

    Answer answer;
    answer.engine = "induction";
    answer.arithmetic = orbit->arithmetic;
    answer.shooter = "pieces";
    switch (orbit->event) {
    case EventKind::none:
        answer.reason = Reason::cycle;
        answer.reflections = orbit->period;
        break;
    case EventKind::hit:
        answer.reason = Reason::hit;
        break;
    case EventKind::escape:
        answer.reason = Reason::escape;
        break;
    case EventKind::absorbed:
        answer.reason = Reason::absorbed;
        break;
    }
    // The event at T^e(x) is at the state after reflection e + 1.
    if (orbit->event != EventKind::none) answer.reflections = orbit->offset + 1;
    if (options.max_steps) {
        // As a simulation would: it notices a cycle one reflection after the period.
        const Integer needed =
            answer.reflections + (answer.reason == Reason::cycle ? Integer(1) : Integer(0));
        if (needed > Integer(static_cast<unsigned long>(*options.max_steps))) return decision;
    }
    answer.induction.pieces = exchange.pieces.size();
    answer.induction.states = exchange.size;
    answer.induction.steps = orbit->steps;
    answer.induction.rounds = orbit->rounds;
    if (options.path)
        if (ExchangeRecorder* recorder = options.path->exchange_recorder()) {
            // Run again, streaming the steps: the certificate only gets them
            // once the answer is known to stand (within max_steps).
            recorder->begin(exchange);
            if (!induce(exchange, recorder, stop)) return decision;
        }
    answer.induction.seconds = std::chrono::duration<double>(Clock::now() - begin).count();
    decision.answer = std::move(answer);
    return decision;
}

template Decision decide<std::int64_t>(const lattice::LatticeScene&,
                                       const lattice::UniformGrid<std::int64_t, 2>&,
                                       const lattice::PieceTable<std::int64_t>&,
                                       const SolveOptions&, std::uint64_t);
template Decision decide<lattice::int128_t>(const lattice::LatticeScene&,
                                            const lattice::UniformGrid<lattice::int128_t, 2>&,
                                            const lattice::PieceTable<lattice::int128_t>&,
                                            const SolveOptions&, std::uint64_t);
template Decision decide<Integer>(const lattice::LatticeScene&,
                                  const lattice::UniformGrid<Integer, 2>&,
                                  const lattice::PieceTable<Integer>&, const SolveOptions&,
                                  std::uint64_t);

} // namespace orthoray::induction
