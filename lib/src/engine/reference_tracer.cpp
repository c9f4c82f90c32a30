#include "engine/reference_tracer.hpp"

#include "engine/cycle_detector.hpp"
#include "engine/reference_step.hpp"

#include <chrono>
#include <new>

namespace orthoray::engine {

ReferenceEvent reference_step(const Scene& scene, const Vector& p, const Vector& v) {
    ReferenceEvent event;
    std::array<bool, 3> flip{};
    for (const Element& e : scene.elements) {
        const int k = e.axis;
        if (v[k] == 0) continue; // parallel to the element's plane: never met
        Rational t = (e.offset() - p[k]) / v[k];
        if (t <= 0) continue;
        if (!event.escape && event.t < t) continue;
        Vector q;
        bool on = true;
        for (int j = 0; j < scene.dim && on; ++j) {
            q[j] = j == k ? e.offset() : Rational(p[j] + t * v[j]);
            on = e.lo[j] <= q[j] && q[j] <= e.hi[j];
        }
        if (!on) continue;
        if (event.escape || t < event.t) {
            event = ReferenceEvent{};
            event.escape = false;
            event.t = t;
            event.point = q;
            flip = {};
        }
        if (e.kind == ElementKind::absorber)
            event.absorbed = true;
        else
            flip[k] = true;
    }
    event.direction = v;
    for (int j = 0; j < scene.dim; ++j)
        if (flip[j]) event.direction[j] = -v[j];
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
    RationalState s{scene.ray().start, scene.ray().direction};
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
            if (auto period = detector.observe(s, reflections))
                return finish(Reason::cycle, *period);
        }
    } catch (const std::bad_alloc&) {
        answer.limit = Limit::memory;
        return finish(Reason::limit, reflections);
    }
}

} // namespace

Answer solve_by_reference(const Scene& scene, const SolveOptions& options) {
    if (options.cycle_detector == CycleDetector::brent)
        return trace<BrentDetector<RationalState>>(scene, options);
    return trace<FirstStateDetector<RationalState>>(scene, options);
}

} // namespace orthoray::engine
