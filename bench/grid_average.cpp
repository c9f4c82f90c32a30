// grid_average: how many elements orthoray's exact grid shooters test per
// shot on random mirror scenes, against the average-case model of
// docs/average-case.md (grid_average_model.hpp), and which grid resolution
// that model recommends against the one orthoray picks.
//
// The shots are orthoray's exact shooters (shoot/uniform_grid.hpp,
// shoot/cross_section_grid.hpp) in int64 lattice arithmetic, counted through
// their Counting policy (shoot/shot_counter.hpp); timings use the plain,
// uncounted structures. The statistics, the model and the cost fit are
// FLOATING POINT: a statistical experiment that decides nothing.
//
// Scenes: bench/scenes.hpp's random_box (2D and 3D, n = 10^3, 10^4, 10^5
// mirrors in a closed mirror box). Shots: the states of the scene's own
// trajectory (each reflection point with the direction leaving it), the
// engine's workload. How to run it: bench/README.md.
#include "bench_util.hpp"
#include "grid_average_model.hpp"
#include "parse_options.hpp"
#include "scenes.hpp"

#include "lattice/lattice_int.hpp"
#include "lattice/lattice_scene.hpp"
#include "shoot/cross_section_grid.hpp"
#include "shoot/uniform_grid.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace {

using namespace orthoray;
using namespace orthoray::bench;
using Int = std::int64_t;

template <int M>
struct State {
    Int p[M];
    unsigned negative;
};

// The first `shots` states after the start of the scene's trajectory: each
// a reflection point and the direction the ray leaves it in.
template <int M>
std::vector<State<M>> trajectory(const lattice::LatticeScene& ls, std::size_t shots) {
    const shoot::UniformGrid<Int, M> grid(ls);
    State<M> s;
    for (int j = 0; j < M; ++j) s.p[j] = lattice::from_integer<Int>(ls.start[j]);
    s.negative = ls.start_direction;
    std::vector<State<M>> states;
    while (states.size() < shots) {
        const shoot::Shot<Int> hit = grid.shoot(s.p, s.negative);
        if (hit.escape || hit.absorber) break;
        for (int j = 0; j < M; ++j) s.p[j] += ((s.negative >> j) & 1u) ? -hit.t : hit.t;
        s.negative ^= hit.flip;
        states.push_back(s);
    }
    return states;
}

struct Row {
    int dim = 0;
    std::size_t n = 0;
    std::string structure;
    double cells_per_element = 0; // asked for
    double grid_cells = 0;        // cells built
    double h_over_length = 0;     // cell side / mean element side
    double cells = 0, tests = 0, box_tests = 0, free_path = 0, free_path_model = 0;
    std::array<double, 5> quantiles{}; // tests: p10, p50, p90, p99, max
    double cells_p90 = 0;
    Prediction predicted;
    double ns = 0; // median time a shot, plain structure
};

// CPU time of this process: on the shared 2-core machine, time spent
// descheduled would otherwise land in the shots' cost.
double cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double quantile(const std::vector<std::uint32_t>& sorted, double q) {
    return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

// Counts every shot through `counted` and times the same shots through
// `plain` (median of `runs` passes).
template <int M, class Counted, class Plain>
void measure(const std::vector<State<M>>& states, const Counted& counted, const Plain& plain,
             int runs, Row& row) {
    std::vector<std::uint32_t> tests, cells;
    tests.reserve(states.size());
    cells.reserve(states.size());
    double box_tests = 0, path = 0;
    for (const State<M>& s : states) {
        const shoot::Shot<Int> hit = counted.shoot(s.p, s.negative);
        const shoot::ShotCounts c = counted.counter().take();
        tests.push_back(static_cast<std::uint32_t>(c.members));
        cells.push_back(static_cast<std::uint32_t>(c.cells));
        box_tests += static_cast<double>(c.box_tests);
        path += static_cast<double>(hit.t);
    }
    const double count = static_cast<double>(states.size());
    for (std::size_t i = 0; i < states.size(); ++i) row.tests += tests[i], row.cells += cells[i];
    row.tests /= count;
    row.cells /= count;
    row.box_tests = box_tests / count;
    row.free_path = path / count;
    std::sort(tests.begin(), tests.end());
    std::sort(cells.begin(), cells.end());
    row.quantiles = {quantile(tests, 0.1), quantile(tests, 0.5), quantile(tests, 0.9),
                     quantile(tests, 0.99), static_cast<double>(tests.back())};
    row.cells_p90 = quantile(cells, 0.9);
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        Int sink = 0;
        const double begin = cpu_seconds();
        for (const State<M>& s : states) sink += plain.shoot(s.p, s.negative).t;
        times.push_back((cpu_seconds() - begin) * 1e9 / count);
        if (sink == -1) std::printf(" "); // keeps the loop
    }
    row.ns = median(times);
}

template <int M>
void run_scene(std::size_t n, std::size_t shots, int runs, std::vector<Row>& rows,
               std::vector<double>& recommended) {
    const Scene scene = random_box(M, static_cast<std::int64_t>(n), 1);
    const lattice::LatticeScene ls = lattice::make_lattice(scene);
    const ModelScene model(ls);
    const std::vector<State<M>> states = trajectory<M>(ls, shots);
    const std::size_t elements = ls.elements.size();
    std::fprintf(stderr, "%dD n = %zu: %zu shots\n", M, n, states.size());

    // The uniform grid: cells_per_element / per_elements cells an element.
    const std::pair<int, int> sweep[] = {{1, 8}, {1, 4}, {1, 2},  {1, 1},  {2, 1},
                                         {4, 1}, {8, 1}, {16, 1}, {32, 1}, {64, 1}};
    std::vector<std::array<double, 3>> fit_rows;
    for (const auto& [cells, per] : sweep) {
        const shoot::UniformGrid<Int, M> plain(ls, cells, {}, per);
        const shoot::UniformGrid<Int, M, shoot::Counting> counted(ls, cells, {}, per);
        Row row;
        row.dim = M;
        row.n = n;
        row.structure = "uniform";
        row.cells_per_element = static_cast<double>(cells) / per;
        row.grid_cells = static_cast<double>(plain.cell_count());
        std::array<double, 3> h{};
        for (int j = 0; j < M; ++j) h[j] = static_cast<double>(plain.cell_side(j));
        row.h_over_length = h[0] / model.mean_length;
        row.predicted = predict_uniform(model, h);
        row.free_path_model = model.free_path();
        measure<M>(states, counted, plain, runs, row);
        fit_rows.push_back({row.cells, row.tests, row.ns});
        rows.push_back(row);
    }
    recommended.push_back(recommended_cells_per_element(model, elements, fit_cost(fit_rows)));

    // The cross-section grid at its default density.
    {
        const shoot::CrossSectionGrid<Int, M> plain(ls);
        const shoot::CrossSectionGrid<Int, M, shoot::Counting> counted(ls);
        Row row;
        row.dim = M;
        row.n = n;
        row.structure = "section";
        row.cells_per_element = 1;
        row.grid_cells = static_cast<double>(plain.cell_count());
        // The prediction of each direction, averaged over the shots.
        std::array<Prediction, (1u << M)> by_direction;
        for (unsigned d = 0; d < (1u << M); ++d) {
            std::array<double, 3> h{};
            for (int j = 0; j + 1 < M; ++j) h[j] = static_cast<double>(plain.cell_side(d, j));
            by_direction[d] = predict_section(model, h);
        }
        for (const State<M>& s : states) {
            row.predicted.cells += by_direction[s.negative].cells / states.size();
            row.predicted.tests += by_direction[s.negative].tests / states.size();
        }
        row.h_over_length = static_cast<double>(plain.cell_side(0, 0)) / model.mean_length;
        row.free_path_model = model.free_path();
        measure<M>(states, counted, plain, runs, row);
        rows.push_back(row);
    }
}

std::string fixed(double x, int digits = 2) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
    return buffer;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"grid_average: element tests per shot of orthoray's grids against the "
                 "average-case model (floating-point statistics)"};
    std::size_t shots = 100'000, max_n = 100'000;
    int runs = 5;
    bool quick = false;
    std::string csv_path = "bench/results/grid-average.csv";
    app.add_option("--shots", shots, "trajectory states shot from, a scene")
        ->check(CLI::Range(std::size_t{100}, std::size_t{100'000'000}));
    app.add_option("--max-n", max_n, "largest mirror count (10^3, 10^4, 10^5 up to it)")
        ->check(CLI::Range(std::size_t{1000}, std::size_t{1'000'000}));
    app.add_option("--runs", runs, "timed passes a structure (median)")->check(CLI::Range(1, 99));
    app.add_option("--csv", csv_path, "raw rows (empty: none)");
    app.add_flag("--quick", quick, "n up to 10^4, 10^4 shots, 1 run: seconds");
    parse_options(app, "grid_average", argc, argv);
    if (quick) shots = std::min<std::size_t>(shots, 10'000), max_n = 10'000, runs = 1;

    std::vector<Row> rows;
    std::vector<std::pair<std::string, double>> recommended_by_scene;
    for (int dim : {2, 3})
        for (std::size_t n = 1000; n <= max_n; n *= 10) {
            std::vector<double> recommended;
            if (dim == 2)
                run_scene<2>(n, shots, runs, rows, recommended);
            else
                run_scene<3>(n, shots, runs, rows, recommended);
            recommended_by_scene.emplace_back(std::to_string(dim) + "D n = " + std::to_string(n),
                                              recommended.front());
        }

    Table table({"dim", "mirrors", "structure", "cells/element", "h / mean side", "cells",
                 "cells (model)", "cells p90", "tests", "tests (model)",
                 "tests p10/p50/p90/p99/max", "box tests", "ns/shot"});
    Csv csv(csv_path);
    csv.row({"dim",           "mirrors",   "structure",   "cells_per_element", "grid_cells",
             "h_over_length", "cells",     "cells_model", "cells_p90",         "tests",
             "tests_model",   "tests_p10", "tests_p50",   "tests_p90",         "tests_p99",
             "tests_max",     "box_tests", "free_path",   "free_path_model",   "ns_per_shot"});
    for (const Row& r : rows) {
        const auto& q = r.quantiles;
        table.add({std::to_string(r.dim), std::to_string(r.n), r.structure,
                   fixed(r.cells_per_element, 3), fixed(r.h_over_length), fixed(r.cells),
                   fixed(r.predicted.cells), fixed(r.cells_p90, 0), fixed(r.tests),
                   fixed(r.predicted.tests),
                   fixed(q[0], 0) + " / " + fixed(q[1], 0) + " / " + fixed(q[2], 0) + " / " +
                       fixed(q[3], 0) + " / " + fixed(q[4], 0),
                   fixed(r.box_tests), fixed(r.ns, 1)});
        csv.row({std::to_string(r.dim),
                 std::to_string(r.n),
                 r.structure,
                 fixed(r.cells_per_element, 4),
                 fixed(r.grid_cells, 0),
                 fixed(r.h_over_length, 4),
                 fixed(r.cells, 4),
                 fixed(r.predicted.cells, 4),
                 fixed(r.cells_p90, 0),
                 fixed(r.tests, 4),
                 fixed(r.predicted.tests, 4),
                 fixed(q[0], 0),
                 fixed(q[1], 0),
                 fixed(q[2], 0),
                 fixed(q[3], 0),
                 fixed(q[4], 0),
                 fixed(r.box_tests, 4),
                 fixed(r.free_path, 1),
                 fixed(r.free_path_model, 1),
                 fixed(r.ns, 2)});
    }
    table.print();

    // The cost model fitted to each scene's sweep, and the resolution it
    // recommends against orthoray's (2 in 2D, 32 in 3D) and the fastest
    // measured.
    Table choice({"scene", "c0 ns", "c_cell ns", "c_test ns", "orthoray's cells/element",
                  "model's best", "fastest measured"});
    std::size_t scene = 0;
    for (std::size_t begin = 0; begin < rows.size(); ++scene) {
        std::vector<std::array<double, 3>> fit_rows;
        const Row* fastest = &rows[begin];
        std::size_t end = begin;
        for (;
             end < rows.size() && rows[end].dim == rows[begin].dim && rows[end].n == rows[begin].n;
             ++end)
            if (rows[end].structure == "uniform") {
                fit_rows.push_back({rows[end].cells, rows[end].tests, rows[end].ns});
                if (rows[end].ns < fastest->ns) fastest = &rows[end];
            }
        const CostModel cost = fit_cost(fit_rows);
        choice.add({recommended_by_scene[scene].first, fixed(cost.c0, 1), fixed(cost.c_cell, 2),
                    fixed(cost.c_test, 2), rows[begin].dim == 2 ? "2" : "32",
                    fixed(recommended_by_scene[scene].second, 2),
                    fixed(fastest->cells_per_element, 3)});
        begin = end;
    }
    choice.print();
    return 0;
}
