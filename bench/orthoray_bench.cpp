// orthoray_bench: the exact lattice engine against the naive exact reference
// tracer and a double-precision uniform-grid tracer (an inexact comparison
// baseline, bench/float_grid_tracer.hpp), on the same scenes in one run.
// How to run it and what every column means: bench/README.md. The figures of
// a full run are in bench/RESULTS.md.
//
// Every measurement runs in a forked child process that builds the scene
// itself, so the peak resident set size (ru_maxrss from wait4) is that of one
// scene and one engine, and runs do not pollute each other's memory.
#include "bench_util.hpp"
#include "float_grid_tracer.hpp"
#include "scenes.hpp"

#include "orthoray/solve.hpp"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#ifndef ORTHORAY_BENCH_DIR
#define ORTHORAY_BENCH_DIR "bench"
#endif

namespace orthoray::bench {
namespace {

// ---------------------------------------------------------------------------
// Options

struct Options {
    bool quick = false, smoke = false;
    std::string mode = "all"; // all, throughput, disagree, billion
    std::string csv;          // throughput table; -disagreement / -billion next to it
    std::string write_scenes; // a directory to write the benchmark scenes to, as .scene files
    std::string wrong_scene = std::string(ORTHORAY_BENCH_DIR) + "/float-wrong.scene";
    int runs = 5;
    std::uint64_t steps = 0;          // exact and float steps per run (0: by mode)
    std::uint64_t scenes = 0;         // disagreement scenes (0: by mode)
    std::uint64_t billion = 0;        // steps of the long run (0: by mode)
    std::uint64_t reference_work = 0; // reference steps * elements per run (0: by mode)
};

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(
        stderr,
        "orthoray_bench: %s\n"
        "usage: orthoray_bench [--quick] [--smoke] [--mode all|throughput|disagree|billion]\n"
        "                      [--csv FILE] [--runs N] [--steps N] [--scenes N]\n"
        "                      [--billion N] [--wrong-scene FILE] [--write-scenes DIR]\n"
        "see bench/README.md\n",
        problem.c_str());
    std::exit(2);
}

std::uint64_t parse_count(const std::string& text) {
    // Accepts 1000000, 1e6 and 10^6.
    try {
        for (const char* sep : {"^", "e"}) {
            const std::size_t at = text.find(sep);
            if (at == std::string::npos) continue;
            const std::uint64_t base = std::stoull(text.substr(0, at));
            const int exponent = std::stoi(text.substr(at + 1));
            std::uint64_t value = sep[0] == '^' ? 1 : base;
            for (int i = 0; i < exponent; ++i) value *= sep[0] == '^' ? base : 10;
            return value;
        }
        std::size_t used = 0;
        const std::uint64_t value = std::stoull(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    usage("found '" + text + "', expected a whole number such as 1000000, 1e6 or 10^6");
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage("option " + a + " needs a value");
            return argv[++i];
        };
        if (a == "--quick")
            o.quick = true;
        else if (a == "--smoke")
            o.smoke = true;
        else if (a == "--mode") {
            o.mode = value();
            if (o.mode != "all" && o.mode != "throughput" && o.mode != "disagree" &&
                o.mode != "billion")
                usage("found mode '" + o.mode + "', expected all, throughput, disagree or billion");
        } else if (a == "--csv")
            o.csv = value();
        else if (a == "--write-scenes")
            o.write_scenes = value();
        else if (a == "--wrong-scene")
            o.wrong_scene = value();
        else if (a == "--runs")
            o.runs = static_cast<int>(std::max<std::uint64_t>(1, parse_count(value())));
        else if (a == "--steps")
            o.steps = parse_count(value());
        else if (a == "--scenes")
            o.scenes = parse_count(value());
        else if (a == "--billion")
            o.billion = parse_count(value());
        else if (a == "--help" || a == "-h")
            usage("help");
        else
            usage("unknown option '" + a + "'");
    }
    if (o.quick && !o.steps) o.steps = 2'000'000;
    if (!o.steps) o.steps = 30'000'000;
    if (!o.scenes) o.scenes = o.quick ? 300 : 3000;
    if (!o.billion) o.billion = o.quick ? 100'000'000 : 1'000'000'000;
    if (!o.reference_work) o.reference_work = o.quick ? 1'000'000 : 10'000'000;
    if (o.quick && o.runs == 5) o.runs = 3;
    return o;
}

// ---------------------------------------------------------------------------
// Measuring in a child process

struct ChildResult {
    bool ok = false;
    char error[160] = {};
    Reason reason = Reason::limit;
    std::uint64_t reflections = 0; // as in Answer
    std::uint64_t performed = 0;   // reflections actually computed
    double wall = 0;               // seconds of the solve / trace call
    double setup = 0;              // the part of it spent building grids and tables
    std::uint64_t pieces = 0, cells = 0;
    char shooter[16] = {}, arithmetic[16] = {};
};

struct Measured {
    ChildResult result;
    long max_rss_kb = 0;
};

Measured in_child(const std::function<ChildResult()>& work) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        close(fds[0]);
        ChildResult r;
        try {
            r = work();
            r.ok = true;
        } catch (const std::exception& e) {
            r.ok = false;
            std::snprintf(r.error, sizeof r.error, "%s", e.what());
        }
        const char* bytes = reinterpret_cast<const char*>(&r);
        std::size_t left = sizeof r;
        while (left > 0) {
            const ssize_t w = write(fds[1], bytes, left);
            if (w <= 0) break;
            bytes += w;
            left -= static_cast<std::size_t>(w);
        }
        _exit(0);
    }
    close(fds[1]);
    Measured m;
    char* bytes = reinterpret_cast<char*>(&m.result);
    std::size_t got = 0;
    while (got < sizeof m.result) {
        const ssize_t r = read(fds[0], bytes + got, sizeof m.result - got);
        if (r <= 0) break;
        got += static_cast<std::size_t>(r);
    }
    close(fds[0]);
    int status = 0;
    struct rusage ru {};
    wait4(pid, &status, 0, &ru);
    m.max_rss_kb = ru.ru_maxrss;
    if (got != sizeof m.result) {
        m.result = ChildResult{};
        std::snprintf(m.result.error, sizeof m.result.error, "child died (status %d)", status);
    }
    return m;
}

std::uint64_t to_u64(const Integer& x) {
    return x.get_ui();
}

// Reflections an answer says were computed: a cycle of period L is seen at
// reflection L + 1.
std::uint64_t performed(Reason reason, std::uint64_t reflections) {
    return reason == Reason::cycle ? reflections + 1 : reflections;
}

void copy(char (&out)[16], const std::string& s) {
    std::snprintf(out, sizeof out, "%s", s.c_str());
}

ChildResult run_exact(const Scene& scene, std::uint64_t steps, Engine engine) {
    SolveOptions options;
    options.engine = engine;
    options.shooter = Shooter::pieces; // 2D tables from the start; the cross-section grid in 3D
    options.max_steps = steps;
    const auto begin = std::chrono::steady_clock::now();
    const Answer a = solve(scene, options);
    ChildResult r;
    r.wall = seconds_since(begin);
    r.reason = a.reason;
    r.reflections = to_u64(a.reflections);
    r.performed = performed(a.reason, r.reflections);
    r.setup = a.stats.setup.seconds;
    r.pieces = a.stats.setup.pieces;
    r.cells = a.stats.setup.cells;
    copy(r.shooter, to_string(a.shooter));
    copy(r.arithmetic, to_string(a.arithmetic));
    return r;
}

ChildResult run_float(const Scene& scene, std::uint64_t steps) {
    const auto begin = std::chrono::steady_clock::now();
    const FloatGridTracer tracer(scene);
    const FloatAnswer a = tracer.trace(steps);
    ChildResult r;
    r.wall = seconds_since(begin);
    r.reason = a.reason;
    r.reflections = a.reflections;
    r.performed = performed(a.reason, a.reflections);
    r.setup = tracer.setup_seconds();
    r.cells = tracer.cells();
    copy(r.shooter, "grid");
    copy(r.arithmetic, "double");
    return r;
}

// ---------------------------------------------------------------------------
// Statistics and formatting

std::string fixed(double x, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
    return buffer;
}

// 3 significant digits, without exponents: 123, 12.3, 1.23, 0.0123.
std::string sig3(double x) {
    if (x == 0) return "0";
    const double a = std::fabs(x);
    int digits = a >= 100  ? 0
                 : a >= 10 ? 1
                 : a >= 1  ? 2
                           : 2 - static_cast<int>(std::floor(std::log10(a)));
    return fixed(x, std::min(digits, 9));
}

std::string rate_text(double per_second) {
    if (per_second >= 1e6) return sig3(per_second / 1e6) + " M";
    if (per_second >= 1e3) return sig3(per_second / 1e3) + " k";
    return sig3(per_second);
}

std::string mb(long kb) {
    return fixed(static_cast<double>(kb) / 1024.0, 1);
}

std::string power_of_ten(std::uint64_t n) {
    int e = 0;
    std::uint64_t x = n;
    while (x >= 10 && x % 10 == 0) x /= 10, ++e;
    if (x == 1 && e >= 3) return "10^" + std::to_string(e);
    if (e >= 6) return std::to_string(x) + "*10^" + std::to_string(e);
    return std::to_string(n);
}

std::string sibling(const std::string& csv, const std::string& suffix) {
    if (csv.empty()) return "";
    const std::size_t dot = csv.rfind(".csv");
    const std::string stem =
        dot != std::string::npos && dot + 4 == csv.size() ? csv.substr(0, dot) : csv;
    return stem + "-" + suffix + ".csv";
}

std::string sci(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", x);
    return buffer;
}

// ---------------------------------------------------------------------------
// Throughput, preprocessing and memory

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
    s += " " + power_of_ten(r.reflections);
    return s;
}

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

// ---------------------------------------------------------------------------
// The long run: peak memory does not grow with the number of reflections

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

// ---------------------------------------------------------------------------
// Float against exact: how often the float tracer answers wrongly

// Records the points of the exact trajectory with indices first .. last
// (0 is the start, i the i-th reflection point).
class PathWindow : public PathSink {
public:
    PathWindow(std::uint64_t first, std::uint64_t last) : first_(first), last_(last) {}
    std::vector<Vector> points;
    void visit(const Vector& p, const Vector&) override {
        if (index_ >= first_ && index_ <= last_) points.push_back(p);
        ++index_;
    }

private:
    std::uint64_t first_, last_, index_ = 0;
};

struct Verdict {
    Reason reason = Reason::limit;
    std::uint64_t reflections = 0;
    bool operator==(const Verdict&) const = default;
};

std::string verdict_text(const Verdict& v) {
    const char* answer = v.reason == Reason::hit     ? "yes"
                         : v.reason == Reason::limit ? "unknown"
                                                     : "no";
    std::string text = std::string(answer) + ", " + to_string(v.reason) + ", ";
    if (v.reason == Reason::cycle) return text + "period " + std::to_string(v.reflections);
    return text + std::to_string(v.reflections) +
           (v.reflections == 1 ? " reflection" : " reflections");
}

Verdict exact_verdict(const Scene& scene, std::uint64_t cap, Engine engine = Engine::lattice) {
    SolveOptions options;
    options.engine = engine;
    options.max_steps = cap;
    const Answer a = solve(scene, options);
    return {a.reason, to_u64(a.reflections)};
}

Verdict float_verdict(const Scene& scene, std::uint64_t cap, double epsilon) {
    FloatOptions options;
    options.epsilon = epsilon;
    options.max_steps = cap;
    const FloatAnswer a = float_trace(scene, options);
    return {a.reason, a.reflections};
}

struct Family {
    const char* name;
    SmallShape shape;
    std::uint64_t seed;
    std::int64_t path_steps; // the target is on the first path_steps reflections of the path
};
const std::array<Family, 3> families = {{
    {"small (side 2^4..2^10, |v_j| <= 10)", {4, 10, 10, 2, 30, false, true}, 7'000'000, 200},
    {"large (side 2^17..2^20, |v_j| <= 10^4)",
     {17, 20, 10'000, 2, 30, false, true},
     8'000'000,
     200},
    {"long (closed box 2^20, 10..100 mirrors, |v_j| <= 10^4, target up to 2*10^4 reflections "
     "away)",
     {20, 20, 10'000, 10, 100, true, false},
     9'000'000,
     20'000},
}};

// A random scene of a family with its target: a random integer point (1/3
// of the time), a point where the exact ray reflects (1/3), or the midpoint
// of a segment of the exact trajectory (1/3), up to path_steps reflections
// from the start.
Scene disagreement_scene(const Family& family, std::uint64_t index) {
    std::mt19937_64 rng(family.seed + index);
    Scene scene = random_small(rng, 2 + static_cast<int>(index % 2), family.shape);
    const std::int64_t kind = uniform(rng, 0, 2);
    if (kind == 0) {
        const std::int64_t side = std::int64_t{1} << family.shape.side_log_hi;
        for (int j = 0; j < scene.dim; ++j)
            scene.target[j] = Rational(Integer(static_cast<long>(uniform(rng, 0, side))));
        return scene;
    }
    const std::uint64_t k = static_cast<std::uint64_t>(uniform(rng, 1, family.path_steps));
    PathWindow path(k - 1, k);
    SolveOptions options;
    options.max_steps = k;
    options.path = &path;
    (void)solve(scene, options);
    if (path.points.size() < 2) return scene; // ended before: the target stays at the start
    if (kind == 1) {
        scene.target = path.points[1];
    } else {
        for (int j = 0; j < 3; ++j) {
            scene.target[j] = (path.points[0][j] + path.points[1][j]) / 2;
            scene.target[j].canonicalize();
        }
    }
    return scene;
}

constexpr std::array<double, 4> epsilons = {1e-15, 1e-12, 1e-9, 1e-6};
constexpr std::size_t default_epsilon = 2; // 1e-9, FloatOptions' default

void write_wrong_scene(const std::string& path, const Scene& scene, const Verdict& exact,
                       const Verdict& reference, const Verdict& flt) {
    std::ofstream out(path);
    if (!out) {
        std::fprintf(stderr, "[bench] cannot write %s\n", path.c_str());
        return;
    }
    out << "# Written by orthoray_bench (bench/README.md): an instance where the\n"
           "# double-precision grid tracer (bench/float_grid_tracer.hpp, epsilon 1e-9\n"
           "# times the scene size) answers wrongly.\n"
           "# The ray has slope 999999/1000000. At x = 999999 it is at y = 999998.000001,\n"
           "# 10^-6 above the top end (999998) of the mirror, so it passes the mirror and\n"
           "# reaches the target (10^6, 999999) without reflecting. 10^-6 is less than the\n"
           "# float tracer's epsilon (10^-3 here), so it reflects off the mirror's end.\n"
        << "#   exact lattice engine: " << verdict_text(exact) << "\n"
        << "#   reference tracer:     " << verdict_text(reference) << "\n"
        << "#   float grid tracer:    " << verdict_text(flt) << "\n"
        << write_scene(scene);
}

int disagreements(const Options& o) {
    const std::uint64_t per_family = std::max<std::uint64_t>(1, o.scenes / families.size()),
                        cap = 100'000;
    std::printf("## Float against exact on random scenes\n\n");
    std::printf("Scenes: random_small (bench/scenes.hpp), %llu of each family, 2D and 3D "
                "alternately; both tracers run to an answer or %s reflections; answer, reason and "
                "reflections must agree.\n\n",
                static_cast<unsigned long long>(per_family), power_of_ten(cap).c_str());
    struct Count {
        std::uint64_t differ = 0, false_yes = 0, missed_yes = 0, other = 0;
        std::array<std::uint64_t, 2> by_dim{};
        std::int64_t first = -1;
        Verdict first_exact, first_float;
    };
    Table table({"family", "float epsilon (x scene size)", "answers that differ", "2D", "3D",
                 "false yes", "missed yes", "other (reason or count)", "first scene"});
    Csv csv(sibling(o.csv, "disagreement"));
    csv.row({"family", "epsilon", "scenes", "differ", "differ_2d", "differ_3d", "false_yes",
             "missed_yes", "other", "first_index", "exact_hit", "exact_escape", "exact_absorbed",
             "exact_cycle", "exact_limit"});
    std::vector<std::string> examples;
    for (const Family& family : families) {
        std::fprintf(stderr, "[bench] disagreements: %s\n", family.name);
        std::array<std::uint64_t, 5> exact_reasons{};
        std::array<Count, epsilons.size()> counts{};
        for (std::uint64_t i = 0; i < per_family; ++i) {
            const Scene scene = disagreement_scene(family, i);
            const Verdict exact = exact_verdict(scene, cap);
            ++exact_reasons[static_cast<std::size_t>(exact.reason)];
            for (std::size_t e = 0; e < epsilons.size(); ++e) {
                const Verdict f = float_verdict(scene, cap, epsilons[e]);
                if (f == exact) continue;
                Count& c = counts[e];
                ++c.differ;
                ++c.by_dim[i % 2];
                if (f.reason == Reason::hit && exact.reason != Reason::hit)
                    ++c.false_yes;
                else if (exact.reason == Reason::hit && f.reason != Reason::hit)
                    ++c.missed_yes;
                else
                    ++c.other;
                if (c.first < 0) {
                    c.first = static_cast<std::int64_t>(i);
                    c.first_exact = exact;
                    c.first_float = f;
                }
            }
        }
        auto n = [](std::uint64_t x) { return std::to_string(x); };
        std::printf("%s: exact answers %s hit, %s escape, %s absorbed, %s cycle, %s limit.\n\n",
                    family.name, n(exact_reasons[0]).c_str(), n(exact_reasons[1]).c_str(),
                    n(exact_reasons[2]).c_str(), n(exact_reasons[3]).c_str(),
                    n(exact_reasons[4]).c_str());
        for (std::size_t e = 0; e < epsilons.size(); ++e) {
            const Count& c = counts[e];
            char eps[32];
            std::snprintf(eps, sizeof eps, "%g%s", epsilons[e],
                          e == default_epsilon ? " (default)" : "");
            table.add({family.name, eps, n(c.differ) + " of " + n(per_family), n(c.by_dim[0]),
                       n(c.by_dim[1]), n(c.false_yes), n(c.missed_yes), n(c.other),
                       c.first < 0 ? "-" : n(static_cast<std::uint64_t>(c.first))});
            csv.row({"\"" + std::string(family.name) + "\"", sci(epsilons[e]), n(per_family),
                     n(c.differ), n(c.by_dim[0]), n(c.by_dim[1]), n(c.false_yes), n(c.missed_yes),
                     n(c.other), std::to_string(c.first), n(exact_reasons[0]), n(exact_reasons[1]),
                     n(exact_reasons[2]), n(exact_reasons[3]), n(exact_reasons[4])});
            if (c.first >= 0) {
                const Scene scene = disagreement_scene(family, static_cast<std::uint64_t>(c.first));
                char head[400];
                std::snprintf(head, sizeof head,
                              "- %s, scene %lld (%zu elements), float epsilon %g: exact %s; "
                              "float %s.\n",
                              family.name, static_cast<long long>(c.first), scene.elements.size(),
                              epsilons[e], verdict_text(c.first_exact).c_str(),
                              verdict_text(c.first_float).c_str());
                std::string text = head;
                if (scene.elements.size() <= 16) text += "\n```\n" + write_scene(scene) + "```\n\n";
                examples.push_back(text);
            }
        }
    }
    table.print();
    if (!examples.empty()) {
        std::printf("The first random scene of each row where the float tracer is wrong "
                    "(scenes with more than 16 elements are not printed; disagreement_scene() "
                    "rebuilds any of them from its index):\n\n");
        for (const std::string& x : examples) std::printf("%s", x.c_str());
        std::printf("\n");
    }

    // The constructed instance.
    const Scene wrong = float_wrong_near_miss();
    const Verdict exact = exact_verdict(wrong, cap),
                  reference = exact_verdict(wrong, cap, Engine::reference),
                  flt = float_verdict(wrong, cap, epsilons[default_epsilon]);
    std::printf("### One instance where float gives the wrong answer\n\n```\n%s```\n\n",
                write_scene(wrong).c_str());
    std::printf("- exact lattice engine: %s\n- reference tracer: %s\n- float grid tracer "
                "(epsilon 1e-9 x size): %s\n",
                verdict_text(exact).c_str(), verdict_text(reference).c_str(),
                verdict_text(flt).c_str());
    for (std::size_t e = 0; e < epsilons.size(); ++e)
        if (e != default_epsilon)
            std::printf("- float grid tracer, epsilon %g x size: %s\n", epsilons[e],
                        verdict_text(float_verdict(wrong, cap, epsilons[e])).c_str());
    std::printf("\n");
    if (!o.wrong_scene.empty()) write_wrong_scene(o.wrong_scene, wrong, exact, reference, flt);
    return exact == reference && !(flt == exact) ? 0 : 1;
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

// ---------------------------------------------------------------------------
// Smoke test (ctest bench_smoke): quick, and fails on a real problem

// FNV-1a over the scene's numbers, in text.
std::uint64_t scene_checksum(const Scene& scene) {
    std::uint64_t h = 0xcbf29ce484222325u;
    auto add = [&](const Rational& x) {
        for (char c : to_string(x) + ' ') h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3u;
    };
    for (const Element& e : scene.elements)
        for (int j = 0; j < scene.dim; ++j) add(e.lo[j]), add(e.hi[j]);
    for (int j = 0; j < scene.dim; ++j)
        add(scene.start[j]), add(scene.direction[j]), add(scene.target[j]);
    return h;
}
constexpr std::uint64_t expected_checksum_2d = 0xceac008fd3a2c256u,
                        expected_checksum_3d = 0xc3cfa51feec8ea1cu;

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
    const double seconds = seconds_since(begin);
    std::printf("bench smoke: %llu scenes compared, %d failures, %.2f s\n",
                static_cast<unsigned long long>(compared), failures, seconds);
    return failures == 0 ? 0 : 1;
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

void print_machine() {
    std::ifstream cpu("/proc/cpuinfo");
    std::string line, model;
    while (std::getline(cpu, line))
        if (line.rfind("model name", 0) == 0) {
            model = line.substr(line.find(':') + 2);
            break;
        }
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    std::printf("Machine: %ld cores online, %s, %.1f GB memory; load average %s.\n\n",
                sysconf(_SC_NPROCESSORS_ONLN), model.empty() ? "unknown CPU" : model.c_str(),
                static_cast<double>(pages) * static_cast<double>(page) / 1e9,
                load_average().c_str());
}

} // namespace
} // namespace orthoray::bench

int main(int argc, char** argv) {
    using namespace orthoray::bench;
    try {
        const Options o = parse(argc, argv);
        if (o.smoke) return smoke();
        if (!o.write_scenes.empty()) return write_scenes(o.write_scenes);
        std::printf("# orthoray_bench%s\n\n", o.quick ? " --quick" : "");
        print_machine();
        int failures = 0;
        const bool all = o.mode == "all";
        if (all || o.mode == "throughput") failures += throughput(o);
        if (all || o.mode == "billion") failures += billion(o);
        if (all || o.mode == "disagree") failures += disagreements(o);
        std::printf("Load average at the end: %s.\n", load_average().c_str());
        return failures == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "orthoray_bench: %s\n", e.what());
        return 4;
    }
}
