// The ctest bench_smoke check (bench/README.md): quick, and fails on a real
// problem.
#include "bench_util.hpp"
#include "measurement.hpp"
#include "orthoray_bench.hpp"
#include "scenes.hpp"

#include <chrono>
#include <cstdio>
#include <string>

namespace orthoray::bench {
namespace {

// FNV-1a over the scene's numbers, in text.
std::uint64_t scene_checksum(const Scene& scene) {
    std::uint64_t h = 0xcbf29ce484222325u;
    auto add = [&](const Rational& x) {
        for (char c : to_string(x) + ' ') h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3u;
    };
    for (const Element& e : scene.elements)
        for (int j = 0; j < scene.dim; ++j) add(e.lo[j]), add(e.hi[j]);
    for (int j = 0; j < scene.dim; ++j)
        add(scene.ray().start[j]), add(scene.ray().direction[j]), add(scene.target()[j]);
    return h;
}
constexpr std::uint64_t expected_checksum_2d = 0xceac008fd3a2c256u,
                        expected_checksum_3d = 0xc3cfa51feec8ea1cu;

} // namespace

int smoke() {
    const auto begin = std::chrono::steady_clock::now();
    int failures = 0;
    auto fail = [&](const std::string& what) {
        std::printf("FAIL: %s\n", what.c_str());
        ++failures;
    };
    // 1. On the box-corner family the float tracer must still agree with the
    //    exact engine (answer, reason, reflections).
    std::uint64_t compared = 0;
    for (std::int64_t m = 1; m <= 30; ++m)
        for (std::int64_t n = 1; n <= 30; ++n) {
            const Scene s = box_corner(m, n);
            const Verdict e = exact_verdict(s, 100'000), f = float_verdict(s, 100'000, 1e-9);
            ++compared;
            if (!(e == f))
                fail("box-corner " + std::to_string(m) + "x" + std::to_string(n) + ": exact " +
                     verdict_text(e) + ", float " + verdict_text(f));
        }
    for (std::int64_t m = 1; m <= 7; ++m)
        for (std::int64_t n = 1; n <= 7; ++n)
            for (std::int64_t k = 1; k <= 7; ++k) {
                const Scene s = box_corner_3d(m, n, k);
                const Verdict e = exact_verdict(s, 100'000), f = float_verdict(s, 100'000, 1e-9);
                ++compared;
                if (!(e == f))
                    fail("box-corner 3D " + std::to_string(m) + "x" + std::to_string(n) + "x" +
                         std::to_string(k) + ": exact " + verdict_text(e) + ", float " +
                         verdict_text(f));
            }
    // A big one, where 45-degree float arithmetic is still exact enough.
    {
        const Scene s = box_corner(1'000'003, 1'000'000);
        const Verdict e = exact_verdict(s, 10'000'000), f = float_verdict(s, 10'000'000, 1e-9);
        ++compared;
        if (!(e == f))
            fail("box-corner 1000003x1000000: exact " + verdict_text(e) + ", float " +
                 verdict_text(f));
        if (e.reason != Reason::cycle) fail("box-corner 1000003x1000000 should cycle");
    }
    // 2. The scenes keep their promises: the closed forms of box-corner and
    //    unit-square, and random boxes that only stop at the step cap.
    if (!(exact_verdict(box_corner(3, 5), 100) == Verdict{Reason::hit, 6}))
        fail("box-corner 3x5 should be a hit after 6 reflections");
    if (!(exact_verdict(unit_square(2, 3), 100) == Verdict{Reason::cycle, 10}))
        fail("unit-square slope 2/3 should cycle with period 10");
    for (int dim : {2, 3}) {
        const Scene s = random_box(dim, 1000, 1000 * static_cast<std::uint64_t>(dim) + 1);
        const Verdict e = exact_verdict(s, 200'000), f = float_verdict(s, 200'000, 1e-9);
        const Verdict r = exact_verdict(s, 200, Engine::reference);
        ++compared;
        if (!(e == Verdict{Reason::limit, 200'000}))
            fail("random " + std::to_string(dim) + "D box should run to the cap, got exact " +
                 verdict_text(e));
        if (!(f == e)) fail("random box: float " + verdict_text(f) + ", exact " + verdict_text(e));
        if (!(r == Verdict{Reason::limit, 200})) fail("random box: reference " + verdict_text(r));
    }
    // 3. The demonstration instance is still a float failure, and the exact
    //    engine and the reference tracer still agree on it.
    {
        const Scene s = float_wrong_near_miss();
        const Verdict e = exact_verdict(s, 1000), r = exact_verdict(s, 1000, Engine::reference),
                      f = float_verdict(s, 1000, 1e-9);
        if (!(e == r) || !(e == Verdict{Reason::hit, 0}))
            fail("near-miss instance: exact " + verdict_text(e) + ", reference " + verdict_text(r));
        if (f == e) fail("near-miss instance: the float tracer is no longer wrong");
    }
    // 4. The scenes are the ones RESULTS.md measured: the same seed gives the
    //    same scene (a checksum of random 2D n=100 and random 3D n=100).
    for (int dim : {2, 3}) {
        const std::uint64_t sum =
            scene_checksum(random_box(dim, 100, 1000 * static_cast<std::uint64_t>(dim) + 1));
        const std::uint64_t expected = dim == 2 ? expected_checksum_2d : expected_checksum_3d;
        if (sum != expected) {
            char text[120];
            std::snprintf(text, sizeof text, "random %dD n=100 has checksum %llx, expected %llx",
                          dim, static_cast<unsigned long long>(sum),
                          static_cast<unsigned long long>(expected));
            fail(text);
        }
    }
    // 5. Embree, when built in, still runs the random boxes without leaking.
    compared += static_cast<std::uint64_t>(embree_smoke(fail));
    const double seconds = seconds_since(begin);
    std::printf("bench smoke: %llu scenes compared, %d failures, %.2f s\n",
                static_cast<unsigned long long>(compared), failures, seconds);
    return failures == 0 ? 0 : 1;
}

} // namespace orthoray::bench
