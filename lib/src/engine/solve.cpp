// solve(): picks the engine the options ask for.
#include "orthoray/solve.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/illumination.hpp"
#include "engine/intensity_search.hpp"
#include "engine/lattice_engine.hpp"
#include "engine/octagonal_engine.hpp"
#include "engine/reference_illumination.hpp"
#include "engine/reference_tracer.hpp"
#include "induction/octagonal_induction.hpp"
#include "orthoray/state_graph.hpp"

#include <algorithm>
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

// The illumination question on the explicit graph of reachable states;
// max_steps caps the states it expands (one event each), as in the
// reference search. Running out of memory leaves every target unknown.
Answer solve_illumination_by_graph(const Scene& scene, const SolveOptions& options) {
    try {
        return explore_illumination_graph(scene, options.max_graph_states, options.monitor,
                                          options.max_steps);
    } catch (const std::bad_alloc&) {
    }
    Answer answer;
    answer.engine = EngineUsed::graph;
    answer.arithmetic = ArithmeticUsed::rational;
    answer.limit = Limit::memory;
    answer.targets.assign(scene.targets.size(), TargetAnswer{});
    return answer;
}

// The default engine on an octagonal maze, as on an axis-parallel 2D one
// (docs/octagonal.md): simulate on the lattice for max(16384, 64 n)
// reflections, which answers most scenes at once; if that has not
// answered, induce on the eight-sheeted cover, whose cost does not grow
// with the orbit. Without an exchange to induce on, the simulation goes on
// instead, from the start. A certificate must hold one path from p0, so the
// first simulation then runs without it and is repeated with it when it
// answers (short runs: at most the budget), and the induction, which
// writes p0 and p1 itself, writes nothing unless it answers.
Answer solve_octagonal_automatically(const Scene& scene, const SolveOptions& options) {
    const bool certify = options.path || options.induction_observer;
    const std::uint64_t budget = std::max<std::uint64_t>(16384, 64 * scene.elements.size());
    if (options.max_steps && (*options.max_steps <= budget || certify))
        return engine::solve_octagonal(scene, options);
    SolveOptions first = options;
    first.max_steps = budget;
    first.path = nullptr;
    first.induction_observer = nullptr;
    const Answer simulated = engine::solve_octagonal(scene, first);
    if (simulated.reason != Reason::limit || simulated.limit != Limit::steps)
        return certify ? engine::solve_octagonal(scene, options) : simulated;
    if (std::optional<Answer> induced = induction::induce_octagonal(scene, options))
        return *induced;
    return engine::solve_octagonal(scene, options);
}

} // namespace

const std::map<std::string, Engine>& engine_names() {
    static const std::map<std::string, Engine> names{{"auto", Engine::automatic},
                                                     {"lattice", Engine::lattice},
                                                     {"induction", Engine::induction},
                                                     {"reference", Engine::reference},
                                                     {"graph", Engine::graph}};
    return names;
}

Answer solve(const Scene& scene, const SolveOptions& options) {
    // A number out of lowest terms compares wrongly in GMP: every engine
    // would answer a different scene (Scene::in_lowest_terms).
    if (!scene.in_lowest_terms()) {
        Scene lowest = scene;
        lowest.to_lowest_terms();
        return solve(lowest, options);
    }
    // The branch searches (illumination, intensity) step on each ray's own
    // lattice with a stepper of their own; a shooter asked for by name would
    // be silently replaced, so it is refused.
    const bool branch_search =
        options.min_intensity || (!scene.single_trajectory() && options.engine != Engine::graph &&
                                  options.engine != Engine::reference);
    if (branch_search && options.shooter != Shooter::automatic)
        throw UnsupportedScene("--shooter chooses how a single ray's trajectory is followed; "
                               "the branch search of several rays or targets, splitters or "
                               "intensities steps on each ray's lattice itself and takes "
                               "--shooter auto (docs/optics.md)");
    // The intensity question has one search, stepping on the lattices or,
    // for --engine reference, with the rational scan (docs/intensity.md).
    if (options.min_intensity) {
        if (options.engine == Engine::graph || options.engine == Engine::induction)
            throw std::invalid_argument("the intensity question is decided by its branch search: "
                                        "the graph and induction engines do not take it");
        return engine::solve_intensity(scene, options);
    }
    // Diagonals (docs/octagonal.md): the illumination engines follow them,
    // and so does every engine for a single trajectory; induction and the
    // default engine have their own entries for them.
    if (scene.has_diagonal() && scene.single_trajectory() && options.engine == Engine::induction)
        return induction::solve_octagonal_by_induction(scene, options);
    if (scene.has_diagonal() && scene.single_trajectory() && options.engine == Engine::automatic)
        return solve_octagonal_automatically(scene, options);
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
    if (scene.has_diagonal()) return engine::solve_octagonal(scene, options);
    return engine::solve_on_lattice(scene, options);
}

} // namespace orthoray
