// The lattice stepper. A state is (integer point, direction mask); one step
// asks the grid for the next hit, checks the target on the segment, and
// reflects by flipping the mask bits of the mirrors' normal axes.
#include "engine/lattice_engine.hpp"

#include "engine/cycle_detector.hpp"
#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/uniform_grid.hpp"

namespace orthoray::engine {
namespace {

using lattice::LatticeScene;

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

// Whether `target` lies on the closed segment p .. p + t*sigma (or on the
// whole ray when the shot escapes): target - p = tau * sigma, 0 <= tau <= t.
template <class Int, int M>
bool passes(const Int (&target)[M], const State<Int, M>& s, const lattice::Shot<Int>& shot) {
    auto signed_gap = [&](int j) {
        return (s.negative >> j) & 1u ? Int(s.p[j] - target[j]) : Int(target[j] - s.p[j]);
    };
    Int tau = signed_gap(0);
    if (tau < 0 || (!shot.escape && shot.t < tau)) return false;
    for (int j = 1; j < M; ++j)
        if (signed_gap(j) != tau) return false;
    return true;
}

template <class Int, int M, class Detector>
Answer run(const LatticeScene& ls, const SolveOptions& options) {
    Answer answer;
    answer.engine = "lattice";
    answer.arithmetic = lattice::arithmetic_name(Int{});
    const lattice::UniformGrid<Int, M> grid(ls);

    State<Int, M> s;
    Int target[M];
    for (int j = 0; j < M; ++j) {
        s.p[j] = lattice::from_integer<Int>(ls.start[j]);
        target[j] = lattice::from_integer<Int>(ls.target[j]);
    }
    s.negative = ls.start_direction;

    PathSink* path = options.path;
    auto report = [&](const State<Int, M>& at) {
        lattice::Coords c;
        for (int j = 0; j < M; ++j) c[j] = lattice::to_integer(at.p[j]);
        path->visit(ls.point(c), ls.direction(at.negative));
    };
    auto finish = [&](Reason reason, std::uint64_t reflections) {
        answer.reason = reason;
        answer.reflections = Integer(static_cast<unsigned long>(reflections));
        return answer;
    };

    if (path) report(s);
    Detector detector;
    for (std::uint64_t reflections = 0;;) {
        const lattice::Shot<Int> shot = grid.shoot(s.p, s.negative);
        if (ls.target_reachable && passes(target, s, shot)) return finish(Reason::hit, reflections);
        if (shot.escape) return finish(Reason::escape, reflections);
        for (int j = 0; j < M; ++j) {
            if ((s.negative >> j) & 1u)
                s.p[j] -= shot.t;
            else
                s.p[j] += shot.t;
        }
        if (shot.absorber) {
            if (path) report(s);
            return finish(Reason::absorbed, reflections);
        }
        if (options.max_steps && reflections == *options.max_steps)
            return finish(Reason::limit, reflections);
        s.negative ^= shot.flip;
        ++reflections;
        if (path) report(s);
        if (auto period = detector.observe(s, reflections)) return finish(Reason::cycle, *period);
    }
}

template <class Int, int M>
Answer run_with_detector(const LatticeScene& ls, const SolveOptions& options) {
    if (options.cycle_detector == CycleDetector::brent)
        return run<Int, M, BrentDetector<State<Int, M>>>(ls, options);
    return run<Int, M, FirstStateDetector<State<Int, M>>>(ls, options);
}

template <class Int>
Answer run_with_int(const LatticeScene& ls, const SolveOptions& options) {
    switch (ls.dim) {
    case 1:
        return run_with_detector<Int, 1>(ls, options);
    case 2:
        return run_with_detector<Int, 2>(ls, options);
    default:
        return run_with_detector<Int, 3>(ls, options);
    }
}

} // namespace

Answer solve_on_lattice(const Scene& scene, const SolveOptions& options) {
    const LatticeScene ls = lattice::make_lattice(scene);
    // The narrowest type the bound proves safe, unless a wider one is asked for.
    const bool fits64 = ls.magnitude < lattice::int64_limit();
    const bool fits128 = ls.magnitude < lattice::int128_limit();
    switch (options.arithmetic) {
    case Arithmetic::automatic:
        if (fits64) return run_with_int<std::int64_t>(ls, options);
        [[fallthrough]];
    case Arithmetic::int128:
        if (fits128) return run_with_int<lattice::int128_t>(ls, options);
        [[fallthrough]];
    case Arithmetic::wide:
        break;
    }
    return run_with_int<Integer>(ls, options);
}

} // namespace orthoray::engine
