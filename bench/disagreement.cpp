// Float against exact: how often the float tracer answers wrongly on random
// scenes, and the constructed instance where it does (bench/README.md).
#include "bench_util.hpp"
#include "float_grid_tracer.hpp"
#include "measurement.hpp"
#include "orthoray_bench.hpp"
#include "scenes.hpp"

#include "orthoray/generate.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace orthoray::bench {
namespace {

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
            scene.target()[j] = Rational(Integer(static_cast<long>(uniform(rng, 0, side))));
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
        scene.target() = path.points[1];
    } else {
        for (int j = 0; j < 3; ++j) {
            scene.target()[j] = (path.points[0][j] + path.points[1][j]) / 2;
            scene.target()[j].canonicalize();
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

} // namespace

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
            std::string quoted_name = "\"";
            quoted_name += family.name;
            quoted_name += '"';
            csv.row({quoted_name, sci(epsilons[e]), n(per_family), n(c.differ), n(c.by_dim[0]),
                     n(c.by_dim[1]), n(c.false_yes), n(c.missed_yes), n(c.other),
                     std::to_string(c.first), n(exact_reasons[0]), n(exact_reasons[1]),
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

} // namespace orthoray::bench
