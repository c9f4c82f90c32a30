// The realistic model derived from a mirror scene (docs/realistic-scenes.md,
// "From mirror scenes"): where the dynamic program agrees with the exact
// branch search, and the corridor where it over-approximates, since a chain
// of locally feasible triples need not be one ray.
#include "orthoray/parse.hpp"
#include "orthoray/realistic.hpp"
#include "orthoray/solve.hpp"
#include "support/case_count.hpp"
#include "support/portable_random.hpp"
#include "support/random_optics.hpp"
#include "support/run_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace orthoray;

namespace {

Integer exact_best(const Scene& scene, long eps) {
    SolveOptions options;
    options.min_intensity = Integer(eps);
    const Answer a = solve(scene, options);
    const TargetAnswer& t = a.targets.front();
    return t.status == TargetAnswer::Status::lit ? *t.intensity : Integer(-1);
}

std::string path_of(const RealisticModel& model, const RealisticAnswer& answer) {
    std::string path;
    for (const std::size_t object : answer.path)
        path += (path.empty() ? "" : " ") + model.objects[object];
    return path;
}

} // namespace

TEST_CASE("the model of a scene whose legs are each one ray agrees with the branch search",
          "[realistic][intensity]") {
    // Through the dim splitter e1 (10), or turned by it and the mirrors e2
    // and e3 (100): each leg is met by one state only.
    const Scene s = read_scene("dim 2\nsplitter x 2 y 1 3 transmittance 1/10\n"
                               "mirror x 0 y 3 5\nmirror y 6 x 1 3\n"
                               "ray 0 0 1 1 intensity 100\ntarget 4 4\n");
    const RealisticModel model = realistic_model_of_scene(s, 0, Integer(0));
    CHECK(model.objects.size() == 5);
    const RealisticAnswer dp = solve_realistic(model);
    CHECK(dp.yes);
    CHECK(dp.best == 100);
    CHECK(dp.best == exact_best(s, 0));
    CHECK(path_of(model, dp) == "S e1 e2 e3 R");
    // Above eps 100 neither lights it.
    const RealisticAnswer above = solve_realistic(realistic_model_of_scene(s, 0, Integer(100)));
    CHECK(!above.yes);
    CHECK(exact_best(s, 100) == -1);
}

TEST_CASE("the model of a mirror corridor over-approximates: triples forget the bounces",
          "[realistic][intensity]") {
    // The ray zigzags between walls e1 (x = 0) and e2 (x = 1) of reflectance
    // 2/3 and passes the target after 4 reflections: 1000 -> 666 -> 444 ->
    // 296 -> 197. The model has the triple (e2, e1, R), and the pair
    // (e2, e1) is reached with 666 after one reflection, so the program
    // passes 444 to R: a chain of feasible triples that no ray follows.
    const Scene s = read_scene("dim 2\nmirror x 0 y 0 100 reflectance 2/3\n"
                               "mirror x 1 y 0 100 reflectance 2/3\n"
                               "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    CHECK(exact_best(s, 0) == 197);
    const RealisticModel model = realistic_model_of_scene(s, 0, Integer(300));
    const RealisticAnswer dp = solve_realistic(model);
    CHECK(dp.best == 444);
    CHECK(path_of(model, dp) == "S e2 e1 R");
    // With eps 300 the program says yes where no branch is bright enough.
    CHECK(dp.yes);
    CHECK(exact_best(s, 300) == -1);
    // Written out and read back, the model gives the same answer.
    const RealisticModel again = read_realistic(write_realistic(model));
    CHECK(write_realistic(again) == write_realistic(model));
    CHECK(solve_realistic(again).best == 444);
}

TEST_CASE("the derived model never delivers less than the scene", "[realistic][intensity]") {
    // Every branch is a path of the model with the same floor chain, so the
    // program's best is at least the branch search's on random scenes.
    std::mt19937_64 rng(1617);
    test::RandomOpticsShape shape;
    shape.splitter_percent = 50;
    shape.max_rays = 1;
    shape.max_targets = 1;
    shape.scene.max_elements = 8;
    const Rational factors[] = {Rational(1), Rational(1, 2), Rational(2, 3), Rational(0)};
    // Under sanitizers a quarter of the cases run, unless no scene has shown
    // the over-approximation yet: then the full 600 may run to find one.
    const int cases = test::case_count(600);
    int lit = 0, over = 0, ran = 0;
    for (int i = 0; i < 600 && (i < cases || over == 0); ++i, ++ran) {
        shape.scene.dim = i % 3 == 0 ? 3 : 2;
        Scene s = test::random_optics_scene(rng, shape);
        for (Element& e : s.elements) {
            if (e.kind == ElementKind::absorber) continue;
            e.reflectance = factors[test::pick_index(rng, 0, 3)];
            if (e.kind == ElementKind::splitter)
                e.transmittance = factors[test::pick_index(rng, 0, 3)];
        }
        s.ray().intensity = Integer(test::pick(rng, 1, 300));
        INFO("case " << i << "\n" << write_scene(s));
        const Integer exact = exact_best(s, 0);
        const RealisticAnswer dp = solve_realistic(realistic_model_of_scene(s, 0, Integer(0)));
        CHECK(dp.best >= exact);
        if (exact > 0) ++lit;
        if (dp.best > exact && exact > 0) ++over;
    }
    CHECK(lit > ran / 10);
    CHECK(over > 0);
}

TEST_CASE("realistic --from-scene runs the program on a scene", "[realistic][cli]") {
    test::TempDir dir;
    const std::string file =
        dir.write("corridor.scene", "dim 2\nmirror x 0 y 0 100 reflectance 2/3\n"
                                    "mirror x 1 y 0 100 reflectance 2/3\n"
                                    "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    const test::CliResult r =
        test::run_cli("realistic --from-scene --min-intensity 300 " + test::quote(file));
    CHECK(r.status == 0);
    CHECK(r.out.find("best         444 (eps 300)\n") != std::string::npos);
    CHECK(r.out.find("path         S e2 e1 R\n") != std::string::npos);
    const test::CliResult exact = test::run_cli("solve --min-intensity 300 " + test::quote(file));
    CHECK(exact.status == 1);
    // The derived model written out, and a certificate verify accepts.
    const std::string model = dir.path("corridor.realistic"), cert = dir.path("c.txt");
    const test::CliResult written = test::run_cli(
        "realistic --from-scene --min-intensity 300 --write-model " + test::quote(model) +
        " --certificate " + test::quote(cert) + " " + test::quote(file));
    CHECK(written.status == 0);
    CHECK(test::slurp(model).starts_with("realistic 1\nobject S R e1 e2\nsource S 1000\n"));
    const test::CliResult verified =
        test::run_cli("verify " + test::quote(model) + " " + test::quote(cert));
    INFO(verified.out << verified.err);
    CHECK(verified.status == 0);
    // One ray with an intensity, and a certificate only beside a model.
    const std::string two = dir.write("two.scene", "dim 2\nray 0 0 1 0 intensity 5\n"
                                                   "ray 0 1 1 0 intensity 5\ntarget 1 0\n");
    const test::CliResult second = test::run_cli("realistic --from-scene " + test::quote(two));
    CHECK(second.status == 2);
    CHECK(second.err.find("two.scene:3:1: found a second ray, expected one ray") !=
          std::string::npos);
    const std::string dark = dir.write("dark.scene", "dim 2\nray 0 0 1 0\ntarget 1 0\n");
    const test::CliResult unlit = test::run_cli("realistic --from-scene " + test::quote(dark));
    CHECK(unlit.status == 2);
    CHECK(unlit.err.find("dark.scene:2:1: found a ray without an intensity") != std::string::npos);
    CHECK(test::run_cli("realistic --from-scene --certificate x " + test::quote(file)).status == 2);
}

TEST_CASE("realistic --from-scene stops at --max-states as a limit, writing nothing",
          "[realistic][cli]") {
    test::TempDir dir;
    // The corridor's ray reaches 101 states: its start and one a reflection,
    // at heights 1/2, 3/2, ..., 199/2, then it escapes. 101 fit, 100 do not.
    const std::string file =
        dir.write("corridor.scene", "dim 2\nmirror x 0 y 0 100 reflectance 2/3\n"
                                    "mirror x 1 y 0 100 reflectance 2/3\n"
                                    "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    constexpr int states = 101;
    const std::string model = dir.path("m.realistic");
    auto run = [&](int cap) {
        return test::run_cli("realistic --from-scene --max-states " + std::to_string(cap) +
                             " --write-model " + test::quote(model) + ' ' + test::quote(file));
    };
    const test::CliResult capped = run(states - 1);
    CHECK(capped.status == 3);
    CHECK(capped.out.empty());
    CHECK(capped.err.find("orthoray: stopped: the scene's ray reaches more than " +
                          std::to_string(states - 1) + " states") != std::string::npos);
    CHECK(!std::filesystem::exists(model));
    CHECK(run(states).status == 0);
    CHECK(std::filesystem::exists(model));
}
