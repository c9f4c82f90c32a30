// The illumination search's lattice stepper against the reference scan:
// event for event (point, parameter, absorption, every outgoing direction
// and whether it reflects) along random branches of random scenes with
// splitters, one-sided elements and several rays, on every integer type
// the stepper picks (coordinates shifted past 2^59 and 2^123).
#include "engine/illumination.hpp"
#include "engine/lattice_stepper.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_octagonal.hpp"
#include "support/random_optics.hpp"

#include <catch2/catch.hpp>

#include <optional>
#include <stdexcept>
#include <string>

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
    CHECK(fast.junction == plain.junction);
    CHECK(fast.acting == plain.acting);
    REQUIRE(fast.outgoing.size() == plain.outgoing.size());
    for (std::size_t k = 0; k < plain.outgoing.size(); ++k) {
        CHECK(fast.outgoing[k].direction == plain.outgoing[k].direction);
        CHECK(fast.outgoing[k].reflection == plain.outgoing[k].reflection);
    }
}

struct Tally {
    std::uint64_t events = 0, splits = 0, absorbed = 0, junctions = 0;
    std::uint64_t partly_scanned = 0; // scenes whose stepper scanned some ray's branches
};

void walk_branches_once(std::mt19937_64& rng, const Scene& s, const engine::EventStepper& fast,
                        const engine::EventStepper& plain, Tally& tally) {
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
            ++tally.events;
            tally.junctions += e.junction;
            if (e.escape || e.absorbed) {
                tally.absorbed += e.absorbed;
                b.done = true;
                continue;
            }
            tally.splits += e.outgoing.size() > 1;
            b.p = e.point;
            b.v = e.outgoing[test::pick_index(rng, 0, e.outgoing.size() - 1)].direction;
        }
}

// Every fourth case, a cap with room for the first ray's lattice only: the
// other rays' branches are scanned, in turns with the first's.
std::optional<std::size_t> cap_for_one_lattice(const Scene& s, int i) {
    if (i % 4 != 3) return std::nullopt;
    return engine::LatticeStepper::lattice_bytes_of(s, 0);
}

// Random branches of every ray, 40 events each at most (`rounds` times),
// the rays taking turns so that the stepper switches lattices at every
// step where the scene's rays lie on several: each event of the lattice
// stepper must be the reference scan's.
// `max_bytes`: the lattice stepper's cap on its lattices; the branches of
// rays past it go to the reference scan. Tallies the scenes where that
// happened.
void walk_branches(std::mt19937_64& rng, const Scene& s, Tally& tally, int rounds = 1,
                   std::optional<std::size_t> max_bytes = {}) {
    const engine::LatticeStepper fast(s, {}, max_bytes);
    const engine::ReferenceStepper plain(s);
    tally.partly_scanned += fast.scans();
    for (int round = 0; round < rounds; ++round) walk_branches_once(rng, s, fast, plain, tally);
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
    Tally tally;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 2 == 0 ? 3 : 2;
        // Up to 60 elements, so that the grids have many cells to walk.
        shape.scene.max_elements = i % 3 == 0 ? 60 : 12;
        shape.scene.range = i % 3 == 0 ? 20 : 6;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        const Scene s = shifted(test::random_optics_scene(rng, shape), shifts[i % 3]);
        INFO("case " << i << "\n" << write_scene(s));
        walk_branches(rng, s, tally, 1, cap_for_one_lattice(s, i));
    }
    // The branches met every kind of event.
    // (15,023 events, 2,275 splits and 373 absorptions at full size.)
    CHECK(tally.events > 10u * static_cast<unsigned>(cases));
    CHECK(tally.splits > tally.events / 10);
    CHECK(tally.absorbed > static_cast<unsigned>(cases) / 5);
    CHECK(tally.partly_scanned > static_cast<unsigned>(cases) / 20);
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

TEST_CASE("with diagonals, rays of one direction class but different lattices are told apart",
          "[illumination][octagonal]") {
    // Every ray moves along (1, 2) up to signs and swaps, so all share a
    // lookup key. The octagonal lattice of (1, 2) scales by N = 6: ray 1's
    // start (0, 0) gives lines cross(w, q) = 0 mod 6; ray 2's, (1/3, 0),
    // scales to the integer point (2, 0) but lies on cross = -4, off every
    // line of ray 1's lattice, where a shot would divide inexactly. Ray 3
    // has a denominator ray 1's scale does not hold.
    const Scene s =
        parse_scene("dim 2\nmirror / 0 -20 40 20\nmirror x 30 y -40 40\nmirror y 35 x -40 40\n"
                    "splitter x -10 y -40 40\n"
                    "ray 0 0 1 2\nray 1/3 0 1 2\nray 1/7 0 -2 1\ntarget 1000 1000\n",
                    "s.scene", SceneFormat::text);
    std::mt19937_64 rng(5);
    Tally tally;
    walk_branches(rng, s, tally, 20);
    CHECK(tally.events > 200u);
}

TEST_CASE("a ray starting beyond another ray's numbers is stepped on its own lattice",
          "[illumination]") {
    // Both rays run along y = 0, so the first's lattice holds the second's
    // start; but that start, 2^64 + 20, is beyond the 64-bit numbers the
    // first lattice was built for (its scene reaches 30), and read there it
    // would wrap to 20 and meet x = 10 instead of x = 30. The same on the
    // octagonal lattice, which a diagonal far away brings in.
    const std::string scene = "dim 2\nmirror x 10 y -5 5\nmirror x 30 y -5 5\n"
                              "ray 20 0 1 0\nray 18446744073709551636 0 -1 0\n"
                              "target -1000000 0\n";
    for (const std::string extra : {"", "mirror / 100 100 101 101\n"}) {
        const Scene s = parse_scene(scene + extra, "s.scene", SceneFormat::text);
        INFO(write_scene(s));
        const engine::LatticeStepper fast(s);
        const engine::ReferenceStepper plain(s);
        for (const Ray& ray : s.rays)
            require_same(fast.next(ray.start, ray.direction), plain.next(ray.start, ray.direction));
        CHECK(fast.next(s.rays[1].start, s.rays[1].direction).point == Vector{30, 0, 0});
        // The search counts ray 2's state leaving x = 30 along +x, which
        // ray 1 never has: five states in all, as the state graph says.
        SolveOptions options;
        CHECK(solve(s, options).states == 5);
    }
}

TEST_CASE("with diagonals, the lattice stepper finds the reference scan's events on random "
          "branches",
          "[illumination][octagonal][property]") {
    std::mt19937_64 rng(30'112'026);
    test::RandomOctagonalShape shape;
    shape.splitter_percent = 35;
    shape.one_sided_percent = 30;
    shape.max_rays = 4;
    shape.max_targets = 1;
    // Shifted past 2^59 and 2^123 (the 64- and 128-bit limits divided by
    // the octagonal lattice's factor of 8 and the direction's size).
    const Integer shifts[] = {Integer(0), Integer(1) << 62, Integer(1) << 126};
    const int cases = test::case_count(1500);
    Tally tally;
    for (int i = 0; i < cases; ++i) {
        shape.box = i % 3 == 0 ? 12 : 4;
        shape.max_elements = i % 3 == 0 ? 40 : 8;
        const Scene s = shifted(test::random_octagonal_scene(rng, shape), shifts[i % 3]);
        INFO("case " << i << "\n" << write_scene(s));
        walk_branches(rng, s, tally, 1, cap_for_one_lattice(s, i));
    }
    // The branches met every kind of event, junctions too.
    CHECK(tally.events > 10u * static_cast<unsigned>(cases));
    CHECK(tally.splits > tally.events / 20);
    CHECK(tally.junctions > tally.splits);
    // (71,657 events, 9,570 splits, 10,319 junctions and 1,300 absorptions
    // at full size.)
    CHECK(tally.absorbed > static_cast<unsigned>(cases) / 10);
    CHECK(tally.partly_scanned > static_cast<unsigned>(cases) / 20);
}

TEST_CASE("past the lattices' byte cap, rays are scanned and the answers stay", "[illumination]") {
    // Four rays on four lines: four lattices; or, with room for the first
    // only, one and three rays left to the reference scan; or none.
    const Scene s = parse_scene("dim 2\nmirror x 0 y 0 10\nmirror x 10 y 0 10\n"
                                "splitter y 5 x 2 8\nmirror y 0 x 0 10\nmirror y 10 x 0 10\n"
                                "ray 1 1 1 0\nray 1 2 1 0\nray 1 3 1 0\nray 1 4 0 1\n"
                                "target 20 20\ntarget 1 9\n",
                                "s.scene", SceneFormat::text);
    const engine::LatticeStepper all(s);
    CHECK(all.lattice_count() == 4);
    CHECK_FALSE(all.scans());
    const std::size_t first = engine::LatticeStepper::lattice_bytes_of(s, 0);
    CHECK(first > 4096u);
    const engine::LatticeStepper one(s, {}, first);
    CHECK(one.lattice_count() == 1);
    CHECK(one.scans());
    const engine::LatticeStepper none(s, {}, first - 1);
    CHECK(none.lattice_count() == 0);
    CHECK(none.scans());
    std::mt19937_64 rng(7);
    Tally tally;
    walk_branches(rng, s, tally, 10, first);
    CHECK(tally.events > 100u);
    // The search through either stepper gives the same answer and count.
    SolveOptions options;
    const Answer full = engine::solve_illumination(s, options, all);
    const Answer capped = engine::solve_illumination(s, options, one);
    CHECK(full.reason == Reason::unlit);
    CHECK(capped.reason == full.reason);
    CHECK(capped.states == full.states);
    REQUIRE(capped.targets.size() == 2);
    CHECK(capped.targets[1].status == full.targets[1].status);
    CHECK(capped.targets[1].reflections == full.targets[1].reflections);
    const Answer scanned = engine::solve_illumination(s, options, none);
    CHECK(scanned.states == full.states);
}
