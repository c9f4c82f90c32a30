// bounds_bench: how long real orbits are next to the state-count bounds of
// docs/bounds.md. For each instance family over growing sizes it solves the
// scene (reflections until the answer, distinct states visited), computes
// the lattice and refined bounds, and times the solve; every instance runs
// in a forked child so that its peak resident memory (ru_maxrss from wait4)
// is its own. Writes one CSV row per instance; bench/plot_bounds.gp draws it.
// Floating point appears only in the timing and in the printed ratios.
#include "child_process.hpp"

#include "orthoray/bounds.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include "parse_options.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace orthoray;

struct Instance {
    std::string family;
    unsigned size = 0;      // k (coprime-box, coprime-cuboid, square, hallway) or bits (random)
    std::uint64_t seed = 0; // random only
    std::function<Scene()> build;
    // 3D steps about ten times slower than 2D (no piece tables): a quarter
    // of the step cap keeps each run within seconds.
    bool capped = false;
};

// Runs `work` in a child process (child_process.hpp); returns its one line
// of output and the child's peak resident set size in KiB.
std::pair<std::string, long> in_child(const std::function<std::string()>& work) {
    const bench::ChildOutput out = bench::run_in_child([&] {
        try {
            return work();
        } catch (const std::exception& e) {
            return std::string("error: ") + e.what();
        }
    });
    return {out.bytes, out.max_rss_kb};
}

// visited / bound as a decimal (for the CSV and the plots only).
std::string ratio(const Integer& visited, const Integer& bound) {
    if (bound == 0) return "";
    Rational r(visited, bound);
    r.canonicalize();
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", r.get_d());
    return text;
}

// The CSV fields after family and parameter, computed in the child.
std::string measure(const Instance& instance, std::uint64_t max_steps) {
    const Scene scene = instance.build();
    SolveOptions options;
    options.max_steps = max_steps;
    const auto begin = std::chrono::steady_clock::now();
    const Answer a = solve(scene, options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    const StateBounds b = compute_bounds(scene);
    const std::optional<Integer> visited = states_visited(a);
    char time[32];
    std::snprintf(time, sizeof time, "%.6g", seconds);
    return std::to_string(b.dim) + "," + std::to_string(b.elements) + "," +
           std::to_string(b.input_bits) + "," + to_string(a.reason) + "," +
           a.reflections.get_str() + "," + (visited ? visited->get_str() : "") + "," +
           b.lattice_states.get_str() + "," + b.refined_states.get_str() + "," +
           (b.pieces ? std::to_string(*b.pieces) : "") + "," +
           (visited ? ratio(*visited, b.lattice_states) : "") + "," +
           (visited ? ratio(*visited, b.refined_states) : "") + "," + time;
}

Integer power_of_two(unsigned k) {
    return Integer(1) << k;
}

std::vector<Instance> instances(bool quick) {
    std::vector<Instance> out;
    const unsigned top = quick ? 10 : 26;
    for (unsigned k = 2; k <= top; k += 2)
        out.push_back({"coprime-box", k, 0,
                       [k] { return generate_coprime_box(k, BoxFamily::Target::far).scene; }});
    // The plain box family with sides 3^k x 2^k from the corner and the
    // generic target: coprime sides of unequal bit sizes.
    for (unsigned k = 1; k <= (quick ? 8u : 16u); ++k)
        out.push_back({"box", k, 0, [k] {
                           BoxFamily f;
                           Integer three_k;
                           mpz_ui_pow_ui(three_k.get_mpz_t(), 3, k);
                           f.sides = {three_k, power_of_two(k)};
                           f.target = BoxFamily::Target::generic;
                           return generate_box(f).scene;
                       }});
    for (unsigned k = 2; k <= (quick ? 5u : 11u); ++k)
        out.push_back({"coprime-cuboid", k, 0,
                       [k] { return generate_coprime_cuboid(k, BoxFamily::Target::far).scene; },
                       true});
    for (unsigned k = 2; k <= top; k += 2)
        out.push_back({"square", k, 0, [k] {
                           return generate_square(power_of_two(k) + 1, power_of_two(k)).scene;
                       }});
    for (unsigned k = 2; k <= top + 4; k += 2)
        out.push_back({"hallway", k, 0, [k] {
                           return generate_hallway(Rational(power_of_two(k)), Rational(1, 3)).scene;
                       }});
    // Random boxed scenes whose orbits close: the target is moved outside the
    // box, so the answer is a cycle (or an escape from a start on the box).
    for (int dim : {2, 3})
        for (unsigned bits = 4; bits <= (quick ? 6u : (dim == 2 ? 22u : 12u)); bits += 2)
            for (std::uint64_t seed = 1; seed <= 3; ++seed)
                out.push_back({"random-" + std::to_string(dim) + "d", bits, seed,
                               [dim, bits, seed] {
                                   RandomFamily f;
                                   f.dim = dim;
                                   f.mirrors = 12;
                                   f.range = std::int64_t{1} << bits;
                                   f.box = true;
                                   f.direction_size = 3;
                                   f.seed = seed;
                                   Scene scene = generate_random(f).scene;
                                   scene.target() = Vector{-1, -1, dim == 3 ? -1 : 0};
                                   return scene;
                               },
                               dim == 3});
    return out;
}

} // namespace

int main(int argc, char** argv) {
    std::string csv = "bench/results/bounds.csv";
    bool quick = false;
    std::uint64_t max_steps = 400'000'000;
    CLI::App app{"bounds_bench: the proven state bounds against the states a solve visits"};
    app.add_flag("--quick", quick, "small instances only");
    app.add_option("--csv", csv, "where the rows go")->capture_default_str();
    app.add_option("--max-steps", max_steps, "step limit of each solve")->capture_default_str();
    orthoray::bench::parse_options(app, "bounds_bench", argc, argv);
    std::ofstream out(csv);
    if (!out) {
        std::cerr << "bounds_bench: cannot write " << csv << '\n';
        return 2;
    }
    out << "family,size,seed,dim,elements,input_bits,reason,reflections,visited,lattice_states,"
           "refined_states,pieces,visited_over_lattice,visited_over_refined,seconds,peak_rss_kb\n";
    for (const Instance& instance : instances(quick)) {
        const auto [fields, rss] = in_child(
            [&] { return measure(instance, instance.capped ? max_steps / 4 : max_steps); });
        const std::string row = instance.family + "," + std::to_string(instance.size) + "," +
                                std::to_string(instance.seed) + "," + fields + "," +
                                std::to_string(rss);
        out << row << '\n' << std::flush;
        std::cerr << row << '\n';
    }
    return 0;
}
