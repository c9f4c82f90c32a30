#include "engine/reference_illumination.hpp"

#include "engine/reference_step.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <new>
#include <queue>
#include <tuple>
#include <vector>

namespace orthoray::engine {
namespace {

// A state: a point and the direction the ray leaves it in. Ordered
// lexicographically on exact rationals for the visited map.
struct State {
    Vector p, v;
    bool operator<(const State& other) const { return std::tie(p, v) < std::tie(other.p, other.v); }
};

// Dijkstra's label of a state: reflections on the way there, then the ray
// it came from. Extending a path adds to the count and keeps the ray, which
// preserves this order, so the first label a state is settled with is the
// least (reflections, ray) pair over every branch reaching it.
struct Label {
    std::uint64_t reflections;
    std::size_t ray; // from 1
    std::size_t state;
    bool operator>(const Label& other) const {
        return std::tie(reflections, ray, state) >
               std::tie(other.reflections, other.ray, other.state);
    }
};

} // namespace

Answer solve_illumination_by_reference(const Scene& scene, const SolveOptions& options) {
    Answer answer;
    answer.engine = EngineUsed::reference;
    answer.arithmetic = ArithmeticUsed::rational;
    answer.targets.assign(scene.targets.size(), TargetAnswer{});

    std::map<State, std::size_t> id;
    std::vector<State> states;
    std::vector<bool> settled;
    std::priority_queue<Label, std::vector<Label>, std::greater<>> queue;
    auto reach = [&](const State& s, std::uint64_t reflections, std::size_t ray) {
        auto [it, added] = id.emplace(s, states.size());
        if (added) {
            states.push_back(s);
            settled.push_back(false);
        }
        if (!settled[it->second]) queue.push(Label{reflections, ray, it->second});
    };

    using Clock = std::chrono::steady_clock;
    auto next_poll = Clock::now();
    std::uint64_t expanded = 0;
    std::size_t unlit = scene.targets.size();
    auto stop = [&](Limit limit) {
        answer.reason = Reason::limit;
        answer.limit = limit;
        answer.states = Integer(static_cast<unsigned long>(states.size()));
        answer.states_lower_bound = true;
        return answer;
    };
    try {
        for (std::size_t r = 0; r < scene.rays.size(); ++r)
            reach({scene.rays[r].start, scene.rays[r].direction}, 0, r + 1);
        while (!queue.empty() && unlit > 0) {
            const Label label = queue.top();
            queue.pop();
            if (settled[label.state]) continue;
            settled[label.state] = true;
            const State s = states[label.state];
            // Labels leave the queue in order, so a target lit by this state
            // is lit with this label. One at the state's own point needs no
            // step to be seen: credited before the cap, so that even a cap
            // of 0 reports a target at a ray's start (0 reflections).
            auto light = [&](std::size_t t) {
                TargetAnswer& target = answer.targets[t];
                target.status = TargetAnswer::Status::lit;
                target.reflections = Integer(static_cast<unsigned long>(label.reflections));
                target.ray = label.ray;
                // Targets are lit in order of reflections: the last one lit
                // needed the most, and the answer's count is that one's.
                answer.reflections = target.reflections;
                --unlit;
            };
            for (std::size_t t = 0; t < scene.targets.size(); ++t)
                if (answer.targets[t].status != TargetAnswer::Status::lit &&
                    scene.targets[t] == s.p)
                    light(t);
            if (unlit == 0) break;
            if (options.max_steps && expanded == *options.max_steps) return stop(Limit::steps);
            if (options.monitor && Clock::now() >= next_poll) {
                if (const std::optional<Limit> limit = options.monitor->poll(expanded))
                    return stop(*limit);
                next_poll = Clock::now() + std::chrono::milliseconds(10);
            }
            ++expanded;
            const ReferenceEvent e = reference_step(scene, s.p, s.v);
            for (std::size_t t = 0; t < scene.targets.size(); ++t)
                if (answer.targets[t].status != TargetAnswer::Status::lit &&
                    reference_passes(scene, scene.targets[t], s.p, s.v, e))
                    light(t);
            for (const Outgoing& out : e.outgoing)
                reach({e.point, out.direction}, label.reflections + (out.reflection ? 1 : 0),
                      label.ray);
        }
    } catch (const std::bad_alloc&) {
        return stop(Limit::memory);
    }
    // Every reachable state was expanded (or every target is lit): the
    // targets not lit are proven unlit.
    for (TargetAnswer& target : answer.targets)
        if (target.status == TargetAnswer::Status::unknown)
            target.status = TargetAnswer::Status::unlit;
    answer.reason = unlit == 0 ? Reason::lit : Reason::unlit;
    answer.states = Integer(static_cast<unsigned long>(states.size()));
    return answer;
}

} // namespace orthoray::engine
