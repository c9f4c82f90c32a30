// The intensity question (docs/intensity.md): closed forms of floor chains
// in a mirror corridor and at a splitter and a corner, the search held to a
// brute-force enumeration of (state, intensity) pairs on random scenes with
// random reflectances and transmittances, limits that never claim more than
// they proved, and the attributes read, written and refused.
#include "engine/intensity_search.hpp"
#include "engine/reference_step.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <map>
#include <set>
#include <tuple>

using namespace orthoray;

namespace {

using Status = TargetAnswer::Status;

Answer solve_with(const Scene& scene, long min_intensity) {
    SolveOptions options;
    options.min_intensity = Integer(min_intensity);
    return solve(scene, options);
}

// floor(i * num / den), applied `times` times: the intensity after that
// many events of one factor.
Integer floor_chain(Integer i, long num, long den, int times) {
    for (int k = 0; k < times; ++k) i = i * num / den;
    return i;
}

// The factor of one outgoing direction, read plainly from docs/intensity.md
// for axis-aligned elements: every acting mirror gives its reflectance;
// a splitter whose axis no mirror holds gives its reflectance if the
// direction flipped its axis, its transmittance if not.
Rational plain_factor(const std::vector<const Element*>& acting, const Vector& v,
                      const Vector& out) {
    Rational f(1);
    for (const Element* e : acting) {
        const Rational r = e->reflectance.value_or(Rational(1));
        const Rational t = e->transmittance.value_or(Rational(1));
        if (e->kind == ElementKind::mirror) {
            f *= r;
            continue;
        }
        bool overruled = false;
        for (const Element* m : acting)
            overruled = overruled || (m->kind == ElementKind::mirror && m->axis == e->axis);
        if (!overruled) f *= out[e->axis] == v[e->axis] ? t : r;
    }
    return f;
}

// Every branch of every ray, one (point, direction, intensity, ray) at a
// time, until its intensity is <= eps or the quadruple was seen: the best
// intensity any branch of each ray carries past each target (0: none).
std::vector<std::vector<Integer>> brute_force(const Scene& scene, const Integer& eps) {
    using Item = std::tuple<Vector, Vector, Integer, std::size_t>;
    std::vector<std::vector<Integer>> best(scene.targets.size(),
                                           std::vector<Integer>(scene.rays.size() + 1));
    std::set<Item> seen;
    std::vector<Item> work;
    for (std::size_t r = 0; r < scene.rays.size(); ++r)
        work.emplace_back(scene.rays[r].start, scene.rays[r].direction, *scene.rays[r].intensity,
                          r + 1);
    while (!work.empty()) {
        Item item = work.back();
        work.pop_back();
        const auto& [p, v, i, r] = item;
        if (i <= eps || !seen.insert(item).second) continue;
        const engine::ReferenceEvent e = engine::reference_step(scene, p, v);
        for (std::size_t t = 0; t < scene.targets.size(); ++t)
            if (engine::reference_passes(scene, scene.targets[t], p, v, e) && best[t][r] < i)
                best[t][r] = i;
        for (const engine::Outgoing& out : e.outgoing) {
            const Rational f = plain_factor(e.acting, v, out.direction);
            work.emplace_back(e.point, out.direction, Integer(i * f.get_num() / f.get_den()), r);
        }
    }
    return best;
}

} // namespace

TEST_CASE("a mirror corridor floors the intensity once a reflection", "[intensity]") {
    // Walls x = 0 and x = 1 of reflectance 2/3; the ray zigzags up from
    // (1/2, 0) and passes (1/2, k) after exactly k reflections.
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 100 reflectance 2/3\n"
                               "mirror x 1 y 0 100 reflectance 2/3\n"
                               "ray 1/2 0 1 1 intensity 1000\n"
                               "target 1/2 0\ntarget 1/2 1\ntarget 1/2 4\ntarget 1/2 9\n"
                               "target 1/2 12\ntarget 1/2 30\n");
    const int ks[] = {0, 1, 4, 9, 12, 30};
    for (long eps : {0L, 5L, 26L, 1000L}) {
        INFO("eps " << eps);
        const Answer a = solve_with(s, eps);
        for (std::size_t t = 0; t < std::size(ks); ++t) {
            const Integer chain = floor_chain(1000, 2, 3, ks[t]);
            INFO("k " << ks[t] << " chain " << chain);
            if (chain > eps) {
                REQUIRE(a.targets[t].status == Status::lit);
                CHECK(*a.targets[t].intensity == chain);
                CHECK(a.targets[t].reflections == ks[t]);
            } else {
                CHECK(a.targets[t].status == Status::unlit);
            }
        }
    }
    // 1000 (2/3)^k floored: 666, 444, 296, 197, 131, 87, 58, 38, 25, ...
    CHECK(floor_chain(1000, 2, 3, 4) == 197);
    CHECK(*solve_with(s, 0).targets[2].intensity == 197);
}

TEST_CASE("a splitter keeps its transmittance and reflectance apart, a corner multiplies",
          "[intensity]") {
    const Scene split = read_scene("dim 2\nsplitter x 2 y -1 1 reflectance 1/2 transmittance 1/3\n"
                                   "ray 0 0 1 0 intensity 1000\ntarget 3 0\ntarget -1 0\n");
    Answer a = solve_with(split, 0);
    CHECK(*a.targets[0].intensity == 333);
    CHECK(*a.targets[1].intensity == 500);
    CHECK(a.targets[1].reflections == 1);
    CHECK(a.reason == Reason::lit);
    a = solve_with(split, 333);
    CHECK(a.targets[0].status == Status::unlit);
    CHECK(a.targets[1].status == Status::lit);
    CHECK(a.reason == Reason::unlit);

    // Into the corner of an x-mirror (1/2) and a y-mirror (1/3): straight
    // back with 600 / 6.
    const Scene corner = read_scene("dim 2\nmirror x 2 y 0 2 reflectance 1/2\n"
                                    "mirror y 2 x 0 2 reflectance 1/3\n"
                                    "ray 0 0 1 1 intensity 600\ntarget 1 1\ntarget -1 -1\n");
    a = solve_with(corner, 0);
    CHECK(*a.targets[0].intensity == 600);
    CHECK(*a.targets[1].intensity == 100);
    CHECK(a.targets[1].reflections == 1);
}

TEST_CASE("the most intense branch wins over the one with fewer reflections", "[intensity]") {
    // Straight through a dim splitter (transmittance 1/10) after 0
    // reflections, or turned by it and two perfect mirrors after 3.
    const Scene s = read_scene("dim 2\nsplitter x 2 y 1 3 transmittance 1/10\n"
                               "mirror x 0 y 3 5\nmirror y 6 x 1 3\n"
                               "ray 0 0 1 1 intensity 100\ntarget 4 4\n");
    const Answer fewest = solve(s);
    CHECK(fewest.targets[0].reflections == 0);
    const Answer a = solve_with(s, 0);
    REQUIRE(a.targets[0].status == Status::lit);
    CHECK(*a.targets[0].intensity == 100);
    CHECK(a.targets[0].reflections == 3);
}

TEST_CASE("the intensity search agrees with a brute-force enumeration of branches",
          "[intensity][property]") {
    std::mt19937_64 rng(1616);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 50;
    shape.one_sided_percent = 20;
    shape.max_rays = 3;
    shape.max_targets = 4;
    shape.scene.max_elements = 8;
    const int cases = test::case_count(1200);
    int lit = 0, unlit = 0, dimmed = 0;
    for (int i = 0; i < cases; ++i) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        shape.scene.max_denominator = i % 4 < 2 ? 1 : 3;
        Scene s = test::random_optics_scene(rng, shape);
        test::add_random_attenuation(rng, s, 400);
        const Integer eps = test::pick(rng, 0, 40);
        INFO("case " << i << " eps " << eps << "\n" << write_scene(s));
        const std::vector<std::vector<Integer>> best = brute_force(s, eps);
        SolveOptions options;
        options.min_intensity = eps;
        const Answer a = engine::solve_intensity(s, options);
        const Answer scan = engine::solve_intensity(s, options, engine::ReferenceStepper(s));
        for (const Answer& b : {a, scan}) {
            REQUIRE(b.targets.size() == s.targets.size());
            for (std::size_t t = 0; t < s.targets.size(); ++t) {
                Integer most = 0;
                for (const Integer& x : best[t]) most = std::max(most, x);
                INFO("target " << t + 1 << " brute force " << most);
                if (most > eps) {
                    REQUIRE(b.targets[t].status == Status::lit);
                    CHECK(*b.targets[t].intensity == most);
                    // The ray named has a branch that intense.
                    CHECK(best[t][b.targets[t].ray] == most);
                } else {
                    CHECK(b.targets[t].status == Status::unlit);
                }
            }
        }
        // Without --min-intensity the attributes change nothing.
        if (i < cases / 6) {
            Scene plain = s;
            for (Element& e : plain.elements) e.reflectance = e.transmittance = std::nullopt;
            for (Ray& r : plain.rays) r.intensity.reset();
            const Answer with = solve(s), without = solve(plain);
            CHECK(with.reason == without.reason);
            CHECK(with.reflections == without.reflections);
            for (std::size_t t = 0; t < with.targets.size(); ++t) {
                CHECK(with.targets[t].status == without.targets[t].status);
                CHECK(with.targets[t].reflections == without.targets[t].reflections);
            }
        }
        for (std::size_t t = 0; t < s.targets.size(); ++t) {
            const bool on = a.targets[t].status == Status::lit;
            (on ? lit : unlit) += 1;
            if (on && *a.targets[t].intensity < *s.rays[a.targets[t].ray - 1].intensity) ++dimmed;
        }
        // A step cap: lit targets lit, exact when proven and no more intense
        // otherwise; the rest unknown, never unlit.
        options.max_steps = static_cast<std::uint64_t>(test::pick(rng, 0, 20));
        const Answer capped = engine::solve_intensity(s, options);
        for (std::size_t t = 0; t < s.targets.size(); ++t) {
            if (capped.reason == Reason::limit) CHECK(capped.targets[t].status != Status::unlit);
            if (capped.reason != Reason::limit)
                CHECK(capped.targets[t].status == a.targets[t].status);
            if (capped.targets[t].status != Status::lit) continue;
            CHECK(a.targets[t].status == Status::lit);
            if (capped.targets[t].best_proven)
                CHECK(*capped.targets[t].intensity == *a.targets[t].intensity);
            else
                CHECK(*capped.targets[t].intensity <= *a.targets[t].intensity);
        }
    }
    // The cases exercise both answers and intensities below the start.
    CHECK(lit > cases / 4);
    CHECK(unlit > cases / 4);
    CHECK(dimmed > cases / 10);
}

TEST_CASE("reflectance, transmittance and intensity are read, written and refused",
          "[intensity][reader]") {
    const std::string text = "dim 2\nmirror x 3 y 0 5 reflectance 9/10\n"
                             "splitter y 2 x 0 4 transmittance 1/3 reflectance 1/2\n"
                             "mirror / 0 0 3 3 reflectance 0.5\n"
                             "ray 0 0 1 1 intensity 1000\nray 1 1 1 0\ntarget 1 1\n";
    const Scene s = read_scene(text);
    CHECK(*s.elements[0].reflectance == Rational(9, 10));
    CHECK(!s.elements[0].transmittance);
    CHECK(*s.elements[1].transmittance == Rational(1, 3));
    CHECK(*s.elements[2].reflectance == Rational(1, 2));
    CHECK(*s.rays[0].intensity == 1000);
    CHECK(!s.rays[1].intensity);
    // Both formats give the same scene back, attributes included.
    const std::string written = write_scene(s);
    CHECK(written.find("mirror x 3 y 0 5 reflectance 9/10\n") != std::string::npos);
    CHECK(written.find("reflectance 1/2 transmittance 1/3\n") != std::string::npos);
    CHECK(written.find("ray 0 0 1 1 intensity 1000\n") != std::string::npos);
    CHECK(write_scene(read_scene(written)) == written);
    CHECK(write_scene(read_scene_json(write_scene_json(s))) == written);
    // Scenes without them are written as before.
    const std::string plain = "dim 2\nmirror x 3 y 0 5\nray 0 0 1 1\ntarget 1 1\n";
    CHECK(write_scene(read_scene(plain)) == plain);
    CHECK(write_scene_json(read_scene(plain)).find("intensity") == std::string::npos);

    const std::pair<std::string, std::string> bad[] = {
        {"dim 2\nmirror x 3 y 0 5 reflectance 3/2\nray 0 0 1 1\ntarget 1 1\n",
         "<input>:2:30: found '3/2' as the reflectance, expected a rational in [0, 1]"},
        {"dim 2\nmirror x 3 y 0 5 reflectance half\nray 0 0 1 1\ntarget 1 1\n",
         "<input>:2:30: found 'half', expected the reflectance (a rational in [0, 1]): a number "
         "(integer, fraction like 7/2, or decimal like 0.125)"},
        {"dim 2\nmirror x 3 y 0 5 transmittance 1/2\nray 0 0 1 1\ntarget 1 1\n",
         "<input>:2:18: found 'transmittance' on a mirror, expected end of line (only a "
         "splitter transmits)"},
        {"dim 2\nabsorber x 3 y 0 5 reflectance 1/2\nray 0 0 1 1\ntarget 1 1\n",
         "<input>:2:20: found 'reflectance' on an absorber, expected end of line (an absorber "
         "reflects nothing)"},
        {"dim 2\nsplitter x 3 y 0 5 reflectance 1 reflectance 1\nray 0 0 1 1\ntarget 1 1\n",
         "<input>:2:34: found a second 'reflectance' (the first is at column 20), expected each "
         "attribute once"},
        {"dim 2\nray 0 0 1 1 intensity -3\ntarget 1 1\n",
         "<input>:2:23: found '-3' as the intensity, expected a natural number (0, 1, 2, ...)"},
        {"dim 2\nray 0 0 1 1 intensity 2.5\ntarget 1 1\n",
         "<input>:2:23: found '2.5' as the intensity, expected a natural number (0, 1, 2, ...)"},
        {"dim 2\nray 0 0 1 1 intensity 2 intensity 3\ntarget 1 1\n",
         "<input>:2:25: found a second 'intensity' (the first is at column 13), expected each "
         "attribute once"},
        {"dim 2\nray 0 0 1 1 intensity\ntarget 1 1\n",
         "<input>:2:22: found end of line, expected the intensity (a natural number: 0, 1, 2, "
         "...)"},
    };
    for (const auto& [input, message] : bad) {
        INFO(input);
        try {
            read_scene(input, "<input>");
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(std::string(e.what()) == message);
        }
    }
    const std::pair<std::string, std::string> bad_json[] = {
        {R"({"dim": 2, "elements": [{"kind": "mirror", "axis": "x", "offset": 1,
 "extent": {"y": [0, 1]}, "transmittance": "1/2"}], "ray": {"start": [0, 0],
 "direction": [1, 0]}, "target": [0, 0]})",
         "<input>:2:27: found the key \"transmittance\" on a mirror, expected it on a splitter "
         "only"},
        {R"({"dim": 2, "elements": [], "ray": {"start": [0, 0], "direction": [1, 0],
 "intensity": -1}, "target": [0, 0]})",
         "<input>:2:15: found the number -1 as the intensity, expected a natural number "
         "(0, 1, 2, ...)"},
        {R"({"dim": 2, "elements": [{"kind": "splitter", "axis": "x", "offset": 1,
 "extent": {"y": [0, 1]}, "reflectance": "5/4"}], "ray": {"start": [0, 0],
 "direction": [1, 0]}, "target": [0, 0]})",
         "<input>:2:42: found the string \"5/4\", expected the reflectance (a rational in [0, "
         "1])"},
    };
    for (const auto& [input, message] : bad_json) {
        INFO(input);
        try {
            read_scene_json(input, "<input>");
            FAIL("no error");
        } catch (const InputError& e) {
            CHECK(std::string(e.what()) == message);
        }
    }
}

TEST_CASE("solve --min-intensity prints intensities and exits 0, 1, 2 or 3", "[intensity][cli]") {
    test::TempDir dir;
    const std::string file =
        dir.write("split.scene", "dim 2\nsplitter x 2 y -1 1 reflectance 1/2 transmittance 1/3\n"
                                 "ray 0 0 1 0 intensity 1000\ntarget 3 0\ntarget -1 0\n");
    const test::CliResult lit = test::run_cli("solve --min-intensity 300 " + test::quote(file));
    CHECK(lit.status == 0);
    CHECK(lit.out.find("target 1  lit after 0 reflections by ray 1 with intensity 333\n") !=
          std::string::npos);
    const test::CliResult json =
        test::run_cli("solve --json --min-intensity 333 " + test::quote(file));
    CHECK(json.status == 1);
    CHECK(json.out.find(R"({"target":1,"answer":"no"},{"target":2,"answer":"yes",)"
                        R"("reflections":1,"ray":1,"intensity":500})") != std::string::npos);
    // A limit before anything is final: unknown, never no.
    const test::CliResult capped =
        test::run_cli("solve --json --max-steps 0 --min-intensity 0 " + test::quote(file));
    CHECK(capped.status == 3);
    CHECK(capped.out.find(R"("answer":"unknown")") != std::string::npos);
    CHECK(capped.out.find(R"("answer":"no")") == std::string::npos);
    // Usage and input errors.
    const std::string plain = dir.write("plain.scene", "dim 2\nray 0 0 1 0\ntarget 1 0\n");
    const test::CliResult missing = test::run_cli("solve --min-intensity 0 " + test::quote(plain));
    CHECK(missing.status == 2);
    CHECK(missing.err == plain +
                             ":2:1: found a ray without an intensity, expected 'intensity N' on "
                             "every ray for --min-intensity\n");
    CHECK(missing.out.empty());
    // batch reports the same message as that instance's error.
    const test::CliResult batched = test::run_cli("batch --min-intensity 0 " + test::quote(plain));
    CHECK(batched.status == 1); // an instance not decided
    CHECK(batched.out.find(R"("error":")" + plain +
                           ":2:1: found a ray without an intensity, expected 'intensity N' on "
                           R"(every ray for --min-intensity","status":2})") != std::string::npos);
    CHECK(test::run_cli("solve --min-intensity 1/2 " + test::quote(file)).status == 2);
    CHECK(test::run_cli("solve --min-intensity 0 --engine graph " + test::quote(file)).status == 2);
    // A certificate, which verify accepts; batch takes the option too.
    const test::CliResult cert =
        test::run_cli("solve --min-intensity 300 --certificate " + test::quote(dir.path("c")) +
                      " " + test::quote(file));
    CHECK(cert.status == 0);
    const test::CliResult verified =
        test::run_cli("verify " + test::quote(file) + " " + test::quote(dir.path("c")));
    CHECK(verified.status == 0);
    CHECK(verified.out == "valid: lit above intensity 300, 1 reflections, 3 states\n");
    const test::CliResult batch =
        test::run_cli("batch --jobs 1 --min-intensity 333 -o " + test::quote(dir.path("r.jsonl")) +
                      " " + test::quote(file));
    CHECK(batch.status == 0); // every instance decided (docs/batch.md)
    CHECK(read_file(dir.path("r.jsonl")).find(R"("ray":1,"intensity":500})") != std::string::npos);
}
