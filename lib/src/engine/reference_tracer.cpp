#include "engine/reference_tracer.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/event_rule.hpp"
#include "engine/reference_step.hpp"

#include <algorithm>
#include <chrono>
#include <new>

namespace orthoray::engine {

namespace {

// Where p + t v crosses the line of an element that acts on v (so v is not
// parallel to it): an axis element's plane x_k = offset, or a diagonal's
// line y - x = lo.y - lo.x ('/') or x + y = lo.x + hi.y ('\'). Returns
// the exact t; whether p + t v lies on the element is the caller's check.
Rational crossing(const Element& e, const Vector& p, const Vector& v) {
    if (e.diagonal == Diagonal::rising) return (e.lo[1] - e.lo[0] - (p[1] - p[0])) / (v[1] - v[0]);
    if (e.diagonal == Diagonal::falling) return (e.lo[0] + e.hi[1] - (p[0] + p[1])) / (v[0] + v[1]);
    return (e.offset() - p[e.axis]) / v[e.axis];
}

} // namespace

ReferenceEvent reference_step(const Scene& scene, const Vector& p, const Vector& v) {
    ReferenceEvent event;
    std::vector<const Element*> acting;
    for (const Element& e : scene.elements) {
        if (!acts_on(e, v)) continue; // invisible to this ray (parallel, or its back)
        Rational t = crossing(e, p, v);
        if (t <= 0) continue;
        if (!event.escape && event.t < t) continue;
        Vector q;
        for (int j = 0; j < scene.dim; ++j)
            q[j] = j == e.axis ? e.offset() : Rational(p[j] + t * v[j]);
        if (!e.contains(q)) continue;
        if (event.escape || t < event.t) {
            event = ReferenceEvent{};
            event.escape = false;
            event.t = t;
            event.point = q;
            acting.clear();
        }
        acting.push_back(&e);
    }
    if (event.escape) {
        event.direction = v;
        return event;
    }
    return event_at(scene.dim, std::move(event.t), std::move(event.point), std::move(acting), v);
}

void mark_reference_junction(const Scene& scene, const Vector& v, ReferenceEvent& event) {
    if (event.escape || event.absorbed || event.junction) return;
    // Another arrival may split here, but only where a splitter lies: then
    // every element on the point counts, acting on v or not.
    const auto splitter_on = [&](const Element& e) {
        return e.kind == ElementKind::splitter && e.contains(event.point);
    };
    if (!std::any_of(scene.elements.begin(), scene.elements.end(), splitter_on)) return;
    std::vector<const Element*> present;
    for (const Element& e : scene.elements)
        if (e.contains(event.point)) present.push_back(&e);
    event.junction = is_junction(scene.dim, present, v, scene.has_diagonal());
}

ReferenceEvent event_at(int dim, Rational t, Vector point, std::vector<const Element*> acting,
                        const Vector& v) {
    ReferenceEvent event;
    event.escape = false;
    event.t = std::move(t);
    event.point = std::move(point);
    EventOutcome outcome = event_outcome(dim, acting, v);
    event.absorbed = outcome.absorbed;
    event.outgoing = std::move(outcome.outgoing);
    event.direction = event.absorbed ? v : event.outgoing.front().direction;
    event.junction = event.outgoing.size() >= 2;
    event.acting = std::move(acting);
    return event;
}

bool reference_passes(const Scene& scene, const Vector& x, const Vector& p, const Vector& v,
                      const ReferenceEvent& event) {
    // x = p + tau v: find tau from any axis where v moves, check the rest.
    bool have_tau = false;
    Rational tau;
    for (int j = 0; j < scene.dim; ++j) {
        if (v[j] == 0) {
            if (x[j] != p[j]) return false;
            continue;
        }
        Rational tj = (x[j] - p[j]) / v[j];
        if (have_tau && tj != tau) return false;
        tau = tj;
        have_tau = true;
    }
    return tau >= 0 && (event.escape || tau <= event.t);
}

namespace {

struct RationalState {
    Vector p, v;
    bool operator==(const RationalState&) const = default;
};

// The state after the next event; only called on states of a trajectory
// known to be periodic, which therefore never escapes nor stops.
RationalState next_state(const Scene& scene, const RationalState& s) {
    const ReferenceEvent e = reference_step(scene, s.p, s.v);
    return {e.point, e.direction};
}

// mu of docs/optics.md: the least i >= 1 with s_i = s_{i + lambda}, found
// by walking s_i and s_{i + lambda} side by side from i = 1 (the second pass
// of Brent's and Floyd's methods). O(1) states are kept.
// `first` ends as s_mu, the state the cycle starts at.
std::uint64_t cycle_start(const Scene& scene, RationalState& first, std::uint64_t lambda) {
    RationalState ahead = first;
    for (std::uint64_t i = 0; i < lambda; ++i) ahead = next_state(scene, ahead);
    std::uint64_t mu = 1;
    while (!(first == ahead)) {
        first = next_state(scene, first);
        ahead = next_state(scene, ahead);
        ++mu;
    }
    return mu;
}

template <class Detector>
Answer trace(const Scene& scene, const SolveOptions& options) {
    Answer answer;
    answer.engine = EngineUsed::reference;
    answer.arithmetic = ArithmeticUsed::rational;
    auto finish = [&](Reason reason, std::uint64_t reflections) {
        answer.reason = reason;
        answer.reflections = Integer(static_cast<unsigned long>(reflections));
        return answer;
    };
    RationalState s{scene.ray().start, scene.ray().direction}, first;
    if (options.path) options.path->visit(s.p, s.v);
    Detector detector;
    // A reflection costs a scan of every element, so the monitor is polled
    // by the clock (every 10 ms) rather than by a count of reflections.
    using Clock = std::chrono::steady_clock;
    auto next_poll = Clock::now();
    std::uint64_t reflections = 0;
    try {
        for (;;) {
            if (options.monitor && Clock::now() >= next_poll) {
                if (const std::optional<Limit> limit = options.monitor->poll(reflections)) {
                    answer.limit = *limit;
                    return finish(Reason::limit, reflections);
                }
                next_poll = Clock::now() + std::chrono::milliseconds(10);
            }
            ReferenceEvent e = reference_step(scene, s.p, s.v);
            if (reference_passes(scene, scene.target(), s.p, s.v, e))
                return finish(Reason::hit, reflections);
            if (e.escape) return finish(Reason::escape, reflections);
            if (e.absorbed) {
                if (options.path) options.path->visit(e.point, s.v);
                return finish(Reason::absorbed, reflections);
            }
            if (options.max_steps && reflections == *options.max_steps)
                return finish(Reason::limit, reflections);
            s = {e.point, e.direction};
            ++reflections;
            if (options.path) options.path->visit(s.p, s.v);
            if (reflections == 1) first = s;
            if (auto period = detector.observe(s, reflections)) {
                // Without one-sided elements or diagonals the step map is
                // injective and the trajectory purely periodic (tail 0,
                // semantics.md).
                if (!may_have_tail(scene)) return finish(Reason::cycle, *period);
                const std::uint64_t tail = cycle_start(scene, first, *period) - 1;
                answer.tail = Integer(static_cast<unsigned long>(tail));
                if (options.path) options.path->cycle_start(first.p, first.v);
                return finish(Reason::cycle, tail + *period);
            }
        }
    } catch (const std::bad_alloc&) {
        answer.limit = Limit::memory;
        return finish(Reason::limit, reflections);
    }
}

} // namespace

Answer solve_by_reference(const Scene& scene, const SolveOptions& options) {
    // One-sided elements and diagonals make the step map non-injective: a
    // trajectory may enter its cycle after a tail and never see its first
    // state again, so the first-state detector would loop forever. Brent's
    // is forced.
    if (detector_for(may_have_tail(scene), options.cycle_detector) == CycleDetector::brent)
        return trace<BrentDetector<RationalState>>(scene, options);
    return trace<FirstStateDetector<RationalState>>(scene, options);
}

} // namespace orthoray::engine
