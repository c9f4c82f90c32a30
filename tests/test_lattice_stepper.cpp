// The illumination search's lattice stepper against the reference scan:
// event for event (point, parameter, absorption, every outgoing direction
// and whether it reflects) along random branches of random scenes with
// splitters, one-sided elements and several rays, on every integer type
// the stepper picks (coordinates shifted past 2^59 and 2^123).
#include "engine/lattice_stepper.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace orthoray;

namespace {

// The scene moved by `by` on every axis: answers and directions are kept,
// only the coordinates' size changes.
Scene shifted(Scene s, const Integer& by) {
    auto move = [&](Vector& x) {
        for (int j = 0; j < s.dim; ++j) x[j] += by;
    };
    for (Element& e : s.elements) {
        move(e.lo);
        move(e.hi);
    }
    for (Ray& r : s.rays) move(r.start);
    for (Vector& t : s.targets) move(t);
    return s;
}

void require_same(const engine::ReferenceEvent& fast, const engine::ReferenceEvent& plain) {
    REQUIRE(fast.escape == plain.escape);
    CHECK(fast.direction == plain.direction);
    if (plain.escape) return;
    CHECK(fast.t == plain.t);
    CHECK(fast.point == plain.point);
    CHECK(fast.absorbed == plain.absorbed);
    REQUIRE(fast.outgoing.size() == plain.outgoing.size());
    for (std::size_t k = 0; k < plain.outgoing.size(); ++k) {
        CHECK(fast.outgoing[k].direction == plain.outgoing[k].direction);
        CHECK(fast.outgoing[k].reflection == plain.outgoing[k].reflection);
    }
}

} // namespace

TEST_CASE("the lattice stepper finds the reference scan's events on random branches",
          "[illumination][property]") {
    std::mt19937_64 rng(24'112'026);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 30;
    shape.one_sided_percent = 30;
    const Integer shifts[] = {Integer(0), Integer(1) << 62, Integer(1) << 126};
    const int cases = test::case_count(1200);
    std::uint64_t events = 0, splits = 0, absorbed = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        // Up to 60 elements, so that the grids have many cells to walk.
        shape.scene.max_elements = i % 3 == 0 ? 60 : 12;
        shape.scene.range = i % 3 == 0 ? 20 : 6;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        const Scene s = shifted(test::random_optics_scene(rng, shape), shifts[i % 3]);
        INFO("case " << i << "\n" << write_scene(s));
        const engine::LatticeStepper fast(s);
        const engine::ReferenceStepper plain(s);
        // The rays take turns, so the stepper switches lattices at every
        // step where the scene's rays lie on several.
        struct Branch {
            Vector p, v;
            bool done = false;
        };
        std::vector<Branch> branches;
        for (const Ray& ray : s.rays) branches.push_back({ray.start, ray.direction});
        for (int step = 0; step < 40; ++step)
            for (Branch& b : branches) {
                if (b.done) continue;
                const engine::ReferenceEvent e = plain.next(b.p, b.v);
                require_same(fast.next(b.p, b.v), e);
                ++events;
                if (e.escape || e.absorbed) {
                    absorbed += e.absorbed;
                    b.done = true;
                    continue;
                }
                splits += e.outgoing.size() > 1;
                b.p = e.point;
                b.v = e.outgoing[test::pick_index(rng, 0, e.outgoing.size() - 1)].direction;
            }
    }
    // The branches met every kind of event.
    // (15,023 events, 2,275 splits and 373 absorptions at full size.)
    CHECK(events > 10u * static_cast<unsigned>(cases));
    CHECK(splits > events / 10);
    CHECK(absorbed > static_cast<unsigned>(cases) / 5);
}

TEST_CASE("a state off every ray's lattice is refused, not answered", "[illumination]") {
    const Scene s = parse_scene("dim 2\nmirror x 5 y -5 5\nray 0 0 1 1\ntarget 5 5\n", "s.scene",
                                SceneFormat::text);
    const engine::LatticeStepper stepper(s);
    // The ray's own states are answered ...
    CHECK(stepper.next(s.ray().start, s.ray().direction).point == Vector{5, 5, 0});
    // ... a direction that is no sign change of the ray's is not.
    CHECK_THROWS_AS(stepper.next(s.ray().start, Vector{1, 2, 0}), std::logic_error);
    // Neither is a point between the lattice's points.
    CHECK_THROWS_AS(stepper.next(Vector{Rational(1, 3), 0, 0}, s.ray().direction),
                    std::logic_error);
}

TEST_CASE("rays on one line of directions but different lattices are told apart",
          "[illumination]") {
    // Both rays move along (1, 1) with nothing held fixed, so they share a
    // lookup key; the second starts at a third, so its lattice is three
    // times finer and the first's does not hold it.
    const Scene s = parse_scene("dim 2\nmirror x 6 y -10 10\nmirror x 0 y -10 10\n"
                                "ray 0 0 1 1\nray 1/3 0 1 1\nray 2 -3 1 0\nray 4 -3 1 0\n"
                                "target 50 50\n",
                                "s.scene", SceneFormat::text);
    const engine::LatticeStepper fast(s);
    const engine::ReferenceStepper plain(s);
    // Alternate between the rays, each from its start and from its first
    // event, so that every lookup comes after a switch.
    for (int round = 0; round < 2; ++round)
        for (const Ray& ray : s.rays) {
            Vector p = ray.start, v = ray.direction;
            for (int step = 0; step < round; ++step) {
                const engine::ReferenceEvent e = plain.next(p, v);
                p = e.point;
                v = e.outgoing.front().direction;
            }
            INFO("ray from " << ray.start[0] << "," << ray.start[1] << ", round " << round);
            require_same(fast.next(p, v), plain.next(p, v));
        }
    // A point of the finer lattice on neither ray's line is still refused
    // where the key matches neither lattice's scale.
    CHECK_THROWS_AS(fast.next(Vector{Rational(1, 5), 0, 0}, Vector{1, 1, 0}), std::logic_error);
}

TEST_CASE("a ray starting beyond another ray's numbers is stepped on its own lattice",
          "[illumination]") {
    // Both rays run along y = 0, so the first's lattice holds the second's
    // start; but that start, 2^64 + 20, is beyond the 64-bit numbers the
    // first lattice was built for (its scene reaches 30), and read there it
    // would wrap to 20 and meet x = 10 instead of x = 30.
    const Scene s = parse_scene("dim 2\nmirror x 10 y -5 5\nmirror x 30 y -5 5\n"
                                "ray 20 0 1 0\nray 18446744073709551636 0 -1 0\n"
                                "target -1000000 0\n",
                                "s.scene", SceneFormat::text);
    const engine::LatticeStepper fast(s);
    const engine::ReferenceStepper plain(s);
    for (const Ray& ray : s.rays)
        require_same(fast.next(ray.start, ray.direction), plain.next(ray.start, ray.direction));
    CHECK(fast.next(s.rays[1].start, s.rays[1].direction).point == Vector{30, 0, 0});
    // The search counts ray 2's state leaving x = 30 along +x, which ray 1
    // never has: five states in all, as the state graph says.
    SolveOptions options;
    CHECK(solve(s, options).states == 5);
}
