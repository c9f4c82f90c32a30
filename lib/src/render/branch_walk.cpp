// walk_branches (orthoray/render.hpp): every state reachable from the rays,
// each walked once, in order of least reflections, for pictures. The step
// is the illumination search's (on the rays' lattices, or the reference
// scan for diagonals), so the acting rule is event_rule.cpp's.
#include "orthoray/render.hpp"

#include "engine/lattice_stepper.hpp"

#include <chrono>
#include <deque>
#include <map>
#include <memory>
#include <new>
#include <tuple>
#include <vector>

namespace orthoray {
namespace {

struct State {
    Vector p, v;
    bool operator<(const State& other) const { return std::tie(p, v) < std::tie(other.p, other.v); }
};

struct Queued {
    std::size_t state;
    std::uint64_t reflections;
};

} // namespace

BranchWalk walk_branches(const Scene& scene, BranchSink& sink, std::uint64_t max_states,
                         RunMonitor* monitor) {
    BranchWalk walk;
    std::map<State, std::size_t> id;
    std::vector<State> states;
    std::vector<bool> walked;
    // 0-1 breadth-first search: an edge of weight 0 goes to the front, of
    // weight 1 to the back, so states leave the queue in nondecreasing order
    // of reflections and the first time a state leaves, its count is least.
    std::deque<Queued> queue;
    auto reach = [&](const State& s, std::uint64_t reflections, bool front) {
        auto [it, added] = id.emplace(s, states.size());
        if (added) {
            states.push_back(s);
            walked.push_back(false);
        }
        if (walked[it->second]) return;
        const Queued q{it->second, reflections};
        front ? queue.push_front(q) : queue.push_back(q);
    };
    using Clock = std::chrono::steady_clock;
    auto next_poll = Clock::now();
    try {
        const std::unique_ptr<engine::EventStepper> stepper = engine::fastest_stepper(scene);
        for (const Ray& ray : scene.rays) reach({ray.start, ray.direction}, 0, false);
        while (!queue.empty()) {
            const Queued q = queue.front();
            queue.pop_front();
            if (walked[q.state]) continue;
            if (walk.states == max_states) return walk;
            if (monitor && Clock::now() >= next_poll) {
                if (const std::optional<Limit> limit = monitor->poll(walk.states)) {
                    walk.limit = *limit;
                    return walk;
                }
                next_poll = Clock::now() + std::chrono::milliseconds(10);
            }
            walked[q.state] = true;
            ++walk.states;
            const State s = states[q.state];
            const engine::ReferenceEvent e = stepper->next(s.p, s.v);
            BranchSegment segment;
            segment.from = s.p;
            segment.direction = s.v;
            segment.escape = e.escape;
            segment.absorbed = e.absorbed;
            if (!e.escape) segment.to = e.point;
            segment.reflections = q.reflections;
            sink.segment(segment);
            for (const engine::Outgoing& out : e.outgoing)
                reach({e.point, out.direction}, q.reflections + (out.reflection ? 1 : 0),
                      !out.reflection);
        }
    } catch (const std::bad_alloc&) {
        walk.limit = Limit::memory;
        return walk;
    }
    walk.complete = true;
    return walk;
}

} // namespace orthoray
