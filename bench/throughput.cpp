// Throughput, preprocessing and memory on the benchmark scenes, and the long
// run (bench/README.md): every measurement in its own forked child.
#include "bench_util.hpp"
#include "measurement.hpp"
#include "orthoray_bench.hpp"
#include "scenes.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace orthoray::bench {
namespace {

struct SceneSpec {
    std::string name; // "random 2D"
    std::string family;
    int dim = 2;
    std::int64_t n = 0; // random mirrors (besides the box), 0 for the fixed families
    std::function<Scene()> make;
};

std::vector<SceneSpec> benchmark_scenes() {
    std::vector<SceneSpec> specs;
    for (int dim : {2, 3})
        for (std::int64_t n : {100, 1000, 10'000, 100'000}) {
            const std::uint64_t seed = 1000 * static_cast<std::uint64_t>(dim) + 1;
            specs.push_back({"random " + std::to_string(dim) + "D", "random_box", dim, n,
                             [dim, n, seed] { return random_box(dim, n, seed); }});
        }
    specs.push_back({"box-corner (10^9+7) x 10^9", "box_corner", 2, 0,
                     [] { return box_corner(1'000'000'007, 1'000'000'000); }});
    specs.push_back({"box-corner 3D (10^6+3) x (10^6+1) x 10^6", "box_corner_3d", 3, 0,
                     [] { return box_corner_3d(1'000'003, 1'000'001, 1'000'000); }});
    specs.push_back({"unit-square slope 10^9/(10^9+7)", "unit_square", 2, 0,
                     [] { return unit_square(1'000'000'000, 1'000'000'007); }});
    return specs;
}

struct Series {
    std::vector<double> wall, setup, rate, gross;
    long max_rss_kb = 0;
    ChildResult last;
    bool ok = true;
    std::string error;

    void add(const Measured& m) {
        max_rss_kb = std::max(max_rss_kb, m.max_rss_kb);
        if (!m.result.ok) {
            ok = false;
            error = m.result.error;
            return;
        }
        last = m.result;
        wall.push_back(m.result.wall);
        setup.push_back(m.result.setup);
        const double steps = static_cast<double>(m.result.performed);
        const double net = m.result.wall - m.result.setup;
        rate.push_back(net > 0 ? steps / net : 0);
        gross.push_back(m.result.wall > 0 ? steps / m.result.wall : 0);
    }
};

std::string outcome(const ChildResult& r) {
    std::string s = to_string(r.reason);
    s += ' ';
    s += power_of_ten(r.reflections);
    return s;
}

} // namespace

int throughput(const Options& o) {
    const std::vector<SceneSpec> specs = benchmark_scenes();
    std::printf("## Throughput, preprocessing and memory\n\n");
    std::printf("exact and float: %s reflections a run; reference: about %s / elements "
                "reflections a run; median of %d runs, each in its own process.\n\n",
                power_of_ten(o.steps).c_str(), power_of_ten(o.reference_work).c_str(), o.runs);

    Table speed({"scene", "dim", "mirrors", "exact refl/s", "exact refl/s (incl. setup)",
                 "reference refl/s", "float refl/s", "exact / float", "exact / reference",
                 "outcome (exact; float)", "float = exact"});
    Table prep({"scene", "dim", "mirrors", "exact setup s", "exact 1-step solve s", "pieces",
                "grid cells", "float setup s", "RSS scene MB", "RSS exact MB", "exact - scene MB",
                "RSS reference MB", "RSS float MB"});
    Csv csv(o.csv);
    csv.row({"scene",
             "family",
             "dim",
             "random_mirrors",
             "elements",
             "steps",
             "reference_steps",
             "runs",
             "exact_rate",
             "exact_rate_gross",
             "exact_wall_s",
             "exact_setup_s",
             "exact_one_step_s",
             "exact_pieces",
             "exact_cells",
             "exact_shooter",
             "exact_arithmetic",
             "exact_outcome",
             "reference_rate",
             "reference_wall_s",
             "float_rate",
             "float_rate_gross",
             "float_wall_s",
             "float_setup_s",
             "float_cells",
             "float_outcome",
             "rss_scene_kb",
             "rss_exact_kb",
             "rss_reference_kb",
             "rss_float_kb",
             "exact_rate_runs",
             "float_rate_runs",
             "reference_rate_runs"});

    int failures = 0;
    for (const SceneSpec& spec : specs) {
        std::size_t elements = 0;
        {
            const Measured m = in_child([&] {
                const Scene s = spec.make();
                ChildResult r;
                r.performed = s.elements.size();
                return r;
            });
            elements = m.result.performed;
        }
        std::fprintf(stderr, "[bench] %s, n = %lld (%zu elements)\n", spec.name.c_str(),
                     static_cast<long long>(spec.n), elements);
        const Measured scene_only = in_child([&] {
            const Scene s = spec.make();
            ChildResult r;
            r.performed = s.elements.size();
            return r;
        });
        Series exact, one_step, reference, flt;
        const std::uint64_t reference_steps = std::clamp<std::uint64_t>(
            o.reference_work / std::max<std::size_t>(elements, 1), 20, 20'000);
        for (int run = 0; run < o.runs; ++run) {
            exact.add(in_child([&] { return run_exact(spec.make(), o.steps, Engine::lattice); }));
            one_step.add(in_child([&] { return run_exact(spec.make(), 1, Engine::lattice); }));
            reference.add(in_child(
                [&] { return run_exact(spec.make(), reference_steps, Engine::reference); }));
            flt.add(in_child([&] { return run_float(spec.make(), o.steps); }));
        }
        for (const Series* s : {&exact, &one_step, &reference, &flt})
            if (!s->ok) {
                std::fprintf(stderr, "[bench] %s: a run failed: %s\n", spec.name.c_str(),
                             s->error.c_str());
                ++failures;
            }
        const double exact_rate = median(exact.rate), float_rate = median(flt.rate),
                     reference_rate = median(reference.gross);
        const std::string mirrors = spec.n ? power_of_ten(static_cast<std::uint64_t>(spec.n)) +
                                                 " + " + std::to_string(2 * spec.dim) + " box"
                                           : std::to_string(elements);
        const std::string name = spec.n ? spec.name + " n=" + power_of_ten(spec.n) : spec.name;
        speed.add(
            {name, std::to_string(spec.dim), mirrors, rate_text(exact_rate),
             rate_text(median(exact.gross)), rate_text(reference_rate), rate_text(float_rate),
             sig3(float_rate > 0 ? exact_rate / float_rate : 0),
             sig3(reference_rate > 0 ? exact_rate / reference_rate : 0),
             outcome(exact.last) + "; " + outcome(flt.last),
             exact.last.reason == flt.last.reason && exact.last.reflections == flt.last.reflections
                 ? "yes"
                 : "**no**"});
        prep.add({name, std::to_string(spec.dim), mirrors, sig3(median(exact.setup)),
                  sig3(median(one_step.wall)), std::to_string(exact.last.pieces),
                  std::to_string(exact.last.cells), sig3(median(flt.setup)),
                  mb(scene_only.max_rss_kb), mb(exact.max_rss_kb),
                  mb(exact.max_rss_kb - scene_only.max_rss_kb), mb(reference.max_rss_kb),
                  mb(flt.max_rss_kb)});
        auto runs_text = [](const std::vector<double>& v) {
            std::string s;
            for (double x : v) {
                if (!s.empty()) s += ';';
                s += sci(x);
            }
            return s;
        };
        csv.row({"\"" + name + "\"",
                 spec.family,
                 std::to_string(spec.dim),
                 std::to_string(spec.n),
                 std::to_string(elements),
                 std::to_string(o.steps),
                 std::to_string(reference_steps),
                 std::to_string(o.runs),
                 sci(exact_rate),
                 sci(median(exact.gross)),
                 sci(median(exact.wall)),
                 sci(median(exact.setup)),
                 sci(median(one_step.wall)),
                 std::to_string(exact.last.pieces),
                 std::to_string(exact.last.cells),
                 exact.last.shooter,
                 exact.last.arithmetic,
                 outcome(exact.last),
                 sci(reference_rate),
                 sci(median(reference.wall)),
                 sci(float_rate),
                 sci(median(flt.gross)),
                 sci(median(flt.wall)),
                 sci(median(flt.setup)),
                 std::to_string(flt.last.cells),
                 outcome(flt.last),
                 std::to_string(scene_only.max_rss_kb),
                 std::to_string(exact.max_rss_kb),
                 std::to_string(reference.max_rss_kb),
                 std::to_string(flt.max_rss_kb),
                 runs_text(exact.rate),
                 runs_text(flt.rate),
                 runs_text(reference.gross)});
    }
    std::printf("### Reflections per second (median)\n\n");
    speed.print();
    std::printf("### Preprocessing (median) and peak memory (max over runs)\n\n");
    prep.print();
    return failures;
}

int billion(const Options& o) {
    const std::int64_t m = 1'000'000'007, n = 1'000'000'000;
    std::printf("## A run of %s reflections\n\n", power_of_ten(o.billion).c_str());
    std::printf("Scene: box-corner (10^9+7) x 10^9 (4 mirrors), 45 degrees from (0, 0), target "
                "(m, n). The ray first meets a corner, (0, n), after m + n - 2 (about 2 * 10^9) "
                "reflections and then retraces its path; the target is never reached (a cycle "
                "of period 2(m + n - 1)). Each row is a separate process.\n\n");
    Table table({"max steps", "outcome", "wall s", "refl/s", "peak RSS MB"});
    Csv csv(sibling(o.csv, "billion"));
    csv.row({"max_steps", "outcome", "wall_s", "rate", "rss_kb"});
    int failures = 0;
    const Measured scene_only = in_child([&] {
        const Scene s = box_corner(m, n);
        ChildResult r;
        r.performed = s.elements.size();
        return r;
    });
    table.add({"0 (scene only)", "-", "-", "-", mb(scene_only.max_rss_kb)});
    csv.row({"0", "scene-only", "0", "0", std::to_string(scene_only.max_rss_kb)});
    for (std::uint64_t steps : {std::uint64_t{1'000'000}, o.billion}) {
        std::fprintf(stderr, "[bench] long run: %s steps\n", power_of_ten(steps).c_str());
        const Measured r =
            in_child([&] { return run_exact(box_corner(m, n), steps, Engine::lattice); });
        if (!r.result.ok) {
            std::fprintf(stderr, "[bench] long run failed: %s\n", r.result.error);
            ++failures;
            continue;
        }
        const double rate = static_cast<double>(r.result.performed) / r.result.wall;
        table.add({power_of_ten(steps), outcome(r.result), fixed(r.result.wall, 2), rate_text(rate),
                   mb(r.max_rss_kb)});
        csv.row({std::to_string(steps), outcome(r.result), sci(r.result.wall), sci(rate),
                 std::to_string(r.max_rss_kb)});
    }
    table.print();
    return failures;
}

// The benchmark scenes as .scene files, for `orthoray solve` and profilers.
int write_scenes(const std::string& dir) {
    int failures = 0;
    for (const SceneSpec& spec : benchmark_scenes()) {
        std::string name = spec.family + "-" + std::to_string(spec.dim) + "d";
        if (spec.n) name += "-n" + std::to_string(spec.n);
        const std::string path = dir + "/" + name + ".scene";
        std::ofstream out(path);
        out << "# " << spec.name
            << (spec.n ? " n=" + power_of_ten(static_cast<std::uint64_t>(spec.n)) : "")
            << ", written by orthoray_bench --write-scenes\n"
            << write_scene(spec.make());
        if (!out) {
            std::fprintf(stderr, "orthoray_bench: cannot write %s\n", path.c_str());
            ++failures;
        } else {
            std::printf("%s\n", path.c_str());
        }
    }
    return failures == 0 ? 0 : 1;
}

} // namespace orthoray::bench
