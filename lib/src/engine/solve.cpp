// solve(): picks the engine the options ask for.
#include "orthoray/solve.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/illumination.hpp"
#include "engine/lattice_engine.hpp"
#include "engine/reference_illumination.hpp"
#include "engine/reference_tracer.hpp"
#include "orthoray/state_graph.hpp"

#include <new>
#include <stdexcept>

namespace orthoray {
namespace {

// The graph engine answers all at once; to honour max_steps like the
// simulations, it reports a limit when they would have needed more
// reflections (a cycle of period L is seen at reflection L + 1, a rho cycle
// where Brent's detector sees it).
Answer solve_by_graph(const Scene& scene, const SolveOptions& options) {
    if (options.path) throw std::invalid_argument("the graph engine does not write certificates");
    Answer answer;
    answer.engine = EngineUsed::graph;
    answer.arithmetic = ArithmeticUsed::rational;
    std::optional<StateGraphReport> report;
    try {
        report = explore_state_graph(scene, options.max_graph_states, options.monitor);
    } catch (const std::bad_alloc&) {
        answer.limit = Limit::memory;
        return answer;
    }
    if (!report) { // too many states to hold: Reason::limit, 0 reflections
        answer.limit = Limit::memory;
        return answer;
    }
    answer = report->answer;
    if (answer.decided() && options.max_steps) {
        Integer needed = answer.reflections + (answer.reason == Reason::cycle ? 1 : 0);
        // With one-sided elements or diagonals the simulations run Brent's
        // detector.
        if (answer.reason == Reason::cycle && engine::may_have_tail(scene))
            needed = Integer(static_cast<unsigned long>(
                engine::brent_detection(answer.tail.get_ui() + 1, answer.period().get_ui())));
        Integer cap = Integer(static_cast<unsigned long>(*options.max_steps));
        if (needed > cap) {
            answer.reason = Reason::limit;
            answer.reflections = cap;
        }
    }
    return answer;
}

// The illumination question on the explicit graph of reachable states; a
// scene with too many of them is a memory limit with every target unknown.
Answer solve_illumination_by_graph(const Scene& scene, const SolveOptions& options) {
    try {
        if (std::optional<Answer> answer =
                explore_illumination_graph(scene, options.max_graph_states, options.monitor))
            return *answer;
    } catch (const std::bad_alloc&) {
    }
    Answer answer;
    answer.engine = EngineUsed::graph;
    answer.arithmetic = ArithmeticUsed::rational;
    answer.limit = Limit::memory;
    answer.targets.assign(scene.targets.size(), TargetAnswer{});
    return answer;
}

} // namespace

Answer solve(const Scene& scene, const SolveOptions& options) {
    // Diagonals (docs/octagonal.md): the illumination engines and, for a
    // single trajectory, the reference tracer and the state graph follow
    // them; the lattice and induction engines do not yet.
    if (scene.single_trajectory() && options.engine != Engine::reference &&
        options.engine != Engine::graph)
        refuse_diagonals(scene, "this engine (--engine reference or graph can solve it)");
    // The illumination question (several rays or targets, splitters) is
    // decided by its own search (or the state graph when asked for). A
    // single trajectory goes to the engine asked for: with one-sided
    // elements the lattice engine filters them by side and finds the tail
    // (docs/optics.md), and induction, which needs a bijection, is not used
    // (the answer's engine says lattice).
    if (!scene.single_trajectory()) {
        // Its evidence goes to an IlluminationObserver; a bare PathSink
        // would silently receive nothing.
        if (options.path && !options.illumination_observer)
            throw std::invalid_argument("the illumination question streams its certificate to an "
                                        "IlluminationObserver, not a PathSink");
        if (options.engine != Engine::graph && options.engine != Engine::reference)
            return engine::solve_illumination(scene, options);
        if (options.illumination_observer)
            throw std::invalid_argument("the graph and reference engines write no illumination "
                                        "certificates");
        return options.engine == Engine::graph
                   ? solve_illumination_by_graph(scene, options)
                   : engine::solve_illumination_by_reference(scene, options);
    }
    switch (options.engine) {
    case Engine::reference:
        return engine::solve_by_reference(scene, options);
    case Engine::graph:
        return solve_by_graph(scene, options);
    case Engine::automatic:
    case Engine::lattice:
    case Engine::induction:
        break;
    }
    return engine::solve_on_lattice(scene, options);
}

} // namespace orthoray
