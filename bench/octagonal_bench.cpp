// octagonal_bench: reflections per second of the lattice engine on scenes
// with diagonal elements (docs/octagonal.md) against axis-only scenes of the
// same size, for bench/RESULTS.md. Not a test.
//
// For each n, one seeded layout: a closed mirror box [0, L]^2 (L = 10^6)
// holding n segments with random integer centres and lengths about
// 4 L / sqrt(n). The axis-only scene makes each segment axis-aligned; the
// octagonal scene turns every second one into a diagonal of the same
// centre and x extent. The ray starts at the same point along (1, 2) in
// both (8 directions with diagonals, 4 without). Three runs are timed:
// axis-only with the default 2D shooter of the lattice engine (grid, then
// piece tables), axis-only with the BVH, and octagonal (BVH, the only
// shooter that takes diagonals). Each is the median of --runs runs in this
// process, each capped at --steps reflections; a layout whose trajectory
// ends before the cap in any run is replaced by the next seed.
//
//     ./build/bench/octagonal_bench [--steps N] [--runs R]
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include "parse_options.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace orthoray;

namespace {

constexpr std::int64_t side = 1'000'000;

Scene layout(std::uint64_t seed, int n, bool diagonals) {
    std::mt19937_64 rng(seed);
    Scene s;
    s.dim = 2;
    const Rational zero(0), box(side);
    for (int axis = 0; axis < 2; ++axis) {
        s.add_mirror(axis, zero, {{zero, box}});
        s.add_mirror(axis, box, {{zero, box}});
    }
    const std::int64_t half = std::max<std::int64_t>(2, 2 * side / std::int64_t(std::sqrt(n)));
    for (int i = 0; i < n; ++i) {
        const std::int64_t h = uniform(rng, 1, half);
        const std::int64_t cx = uniform(rng, h + 1, side - h - 1);
        const std::int64_t cy = uniform(rng, h + 1, side - h - 1);
        const int kind = static_cast<int>(uniform(rng, 0, 1));
        if (diagonals && i % 2 == 1) {
            if (kind == 0)
                s.add_diagonal(ElementKind::mirror, cx - h, cy - h, cx + h, cy + h);
            else
                s.add_diagonal(ElementKind::mirror, cx - h, cy + h, cx + h, cy - h);
        } else if (kind == 0) {
            s.add_mirror(0, cx, {{cy - h, cy + h}});
        } else {
            s.add_mirror(1, cy, {{cx - h, cx + h}});
        }
    }
    s.ray().start = {Rational(uniform(rng, 1, side - 1)), Rational(uniform(rng, 1, side - 1)),
                     Rational(0)};
    s.ray().direction = {Rational(1), Rational(2), Rational(0)};
    s.target() = {Rational(-1), Rational(-1), Rational(0)};
    return s;
}

struct Timing {
    double median = 0; // reflections per second
    bool full = true;  // every run reached the cap
};

Timing measure(const Scene& s, Shooter shooter, std::uint64_t steps, int runs) {
    std::vector<double> rates;
    Timing t;
    for (int r = 0; r < runs; ++r) {
        SolveOptions o;
        o.engine = Engine::lattice;
        o.shooter = shooter;
        o.max_steps = steps;
        const auto begin = std::chrono::steady_clock::now();
        const Answer a = solve(s, o);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        rates.push_back(a.reflections.get_d() / seconds);
        if (a.reason != Reason::limit) { // ended early: the layout is replaced
            t.full = false;
            return t;
        }
    }
    std::sort(rates.begin(), rates.end());
    t.median = rates[rates.size() / 2];
    return t;
}

} // namespace

int main(int argc, char** argv) {
    std::uint64_t steps = 2'000'000;
    int runs = 5;
    CLI::App app{"octagonal_bench: axis-only scenes against scenes with diagonal mirrors"};
    app.add_option("--steps", steps, "reflections a run")->capture_default_str();
    app.add_option("--runs", runs, "runs per measurement (the median is reported)")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    orthoray::bench::parse_options(app, "octagonal_bench", argc, argv);
    std::printf("| n | axis-only, default (%s) | axis-only, bvh | octagonal, bvh | octagonal / "
                "axis bvh | octagonal / axis default | seed |\n|---|---|---|---|---|---|---|\n",
                "grid, then pieces");
    for (const int n : {100, 1000, 10000}) {
        for (std::uint64_t seed = 1;; ++seed) {
            const Scene axis = layout(seed, n, false), octagonal = layout(seed, n, true);
            const Timing diagonal = measure(octagonal, Shooter::automatic, steps, runs);
            if (!diagonal.full) continue;
            const Timing by_default = measure(axis, Shooter::automatic, steps, runs);
            if (!by_default.full) continue;
            const Timing by_bvh = measure(axis, Shooter::bvh, steps, runs);
            if (!by_bvh.full) continue;
            std::printf("| %d | %.3g | %.3g | %.3g | %.2f | %.2f | %llu |\n", n, by_default.median,
                        by_bvh.median, diagonal.median, diagonal.median / by_bvh.median,
                        diagonal.median / by_default.median, static_cast<unsigned long long>(seed));
            std::fflush(stdout);
            break;
        }
    }
}
