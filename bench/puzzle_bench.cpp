// puzzle_bench: the placement search of `orthoray puzzle solve` on every
// public Lazor level (../shared/puzzles/lazor beside the source tree), on
// one thread and on all, against a brute-force baseline measured in the same
// run: every placement of the blocks on the open cells in row-major order,
// each checked with the search's own walk (puzzle/beam_walk.hpp), until the
// first that lights every point. The baseline shares the walk so that the
// ratio measures the search alone. Prints a markdown table; --csv writes
// the raw numbers. How to run it: bench/README.md.
#include "orthoray/puzzle.hpp"
#include "puzzle/beam_walk.hpp"

#include "parse_options.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;
using orthoray::LazorCell;
using orthoray::LazorLevel;

double seconds_since(Clock::time_point begin) {
    return std::chrono::duration<double>(Clock::now() - begin).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// The brute-force baseline: placements in row-major order of the open cells
// (reflect, opaque, refract, then none at each cell), each walked, until one
// lights every point or the time runs out.
struct BruteForce {
    const LazorLevel& level;
    orthoray::puzzle::BeamWalk walk;
    std::vector<orthoray::puzzle::Content> cells;
    std::array<int, 3> left;
    std::uint64_t checked = 0;
    Clock::time_point deadline;
    bool found = false, out_of_time = false;

    BruteForce(const LazorLevel& l, double cap_seconds)
        : level(l), walk(l), left(l.blocks),
          deadline(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(cap_seconds))) {
        for (const LazorCell c : l.cells)
            cells.push_back(c == LazorCell::open ? orthoray::puzzle::empty
                                                 : orthoray::puzzle::content_of(c));
    }

    void place(std::size_t cell) {
        if (found || out_of_time) return;
        if (left[0] + left[1] + left[2] == 0) {
            if (++checked % 4096 == 0 && Clock::now() >= deadline) out_of_time = true;
            walk.walk(cells);
            found = walk.all_lit();
            return;
        }
        if (cell == cells.size()) return;
        if (level.cells[cell] != LazorCell::open) return place(cell + 1);
        for (int k = 0; k < 3; ++k) {
            if (left[k] == 0) continue;
            --left[k];
            cells[cell] = static_cast<orthoray::puzzle::Content>(k + 1);
            place(cell + 1);
            cells[cell] = orthoray::puzzle::empty;
            ++left[k];
        }
        place(cell + 1);
    }
};

struct Row {
    std::string name;
    double one = 0, all = 0, brute = 0;
    std::uint64_t nodes = 0, brute_checked = 0;
    bool brute_capped = false;
    std::string answer;
};

} // namespace

int main(int argc, char** argv) {
    int runs = 5;
    double cap = 10;
    std::string csv;
    CLI::App app{"puzzle_bench: the Lazor placement search against brute force"};
    app.add_option("--runs", runs, "timed runs per level")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000000));
    app.add_option("--brute-cap", cap, "seconds before brute force gives up")
        ->capture_default_str();
    app.add_option("--csv", csv, "also write the rows to this CSV file");
    fs::path folder = fs::path(ORTHORAY_BENCH_DIR) / ".." / ".." / "shared" / "puzzles" / "lazor";
    app.add_option("--levels", folder,
                   "the .bff levels to time (and those in its unsolvable/, if any); "
                   "default: the public levels")
        ->capture_default_str();
    orthoray::bench::parse_options(app, "puzzle_bench", argc, argv);
    if (!fs::is_directory(folder)) {
        std::fprintf(stderr, "puzzle_bench: %s is absent\n", folder.string().c_str());
        return 2;
    }
    std::vector<fs::path> files;
    for (const auto& sub : {folder, folder / "unsolvable"})
        if (fs::is_directory(sub))
            for (const auto& e : fs::directory_iterator(sub))
                if (e.path().extension() == ".bff") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());

    std::vector<Row> rows;
    for (const fs::path& file : files) {
        const LazorLevel level = orthoray::load_lazor_level(file.string());
        Row row;
        row.name = file.stem().string();
        std::vector<double> one, all;
        for (int r = 0; r < runs; ++r) {
            for (const unsigned jobs : {1u, cores}) {
                orthoray::LazorSolveOptions options;
                options.jobs = jobs;
                const Clock::time_point begin = Clock::now();
                const orthoray::LazorSolution s = orthoray::solve_lazor(level, options);
                (jobs == 1 ? one : all).push_back(seconds_since(begin));
                row.nodes = s.nodes;
                row.answer = s.status == orthoray::LazorSolution::Status::solved ? "solved"
                             : s.status == orthoray::LazorSolution::Status::unsolvable
                                 ? "unsolvable"
                                 : "limit";
            }
        }
        row.one = median(one);
        row.all = median(all);
        BruteForce brute(level, cap);
        const Clock::time_point begin = Clock::now();
        brute.place(0);
        row.brute = seconds_since(begin);
        row.brute_checked = brute.checked;
        row.brute_capped = brute.out_of_time;
        rows.push_back(row);
        std::fprintf(stderr, "%-28s %9.3f ms %9.3f ms  brute %9.3f s%s\n", row.name.c_str(),
                     row.one * 1e3, row.all * 1e3, row.brute, row.brute_capped ? " (cap)" : "");
    }

    std::printf("| level | answer | nodes | 1 thread (ms) | %u threads (ms) | brute force (ms) | "
                "placements checked | brute / 1 thread |\n|---|---|---|---|---|---|---|---|\n",
                cores);
    for (const Row& r : rows)
        std::printf("| %s | %s | %llu | %.3f | %.3f | %s%.1f | %llu | %s%.0f |\n", r.name.c_str(),
                    r.answer.c_str(), static_cast<unsigned long long>(r.nodes), r.one * 1e3,
                    r.all * 1e3, r.brute_capped ? "> " : "", r.brute * 1e3,
                    static_cast<unsigned long long>(r.brute_checked), r.brute_capped ? "> " : "",
                    r.brute / r.one);
    if (!csv.empty()) {
        std::ofstream out(csv);
        out << "level,answer,nodes,one_thread_s,all_threads_s,threads,brute_s,brute_checked,"
               "brute_capped\n";
        for (const Row& r : rows)
            out << r.name << ',' << r.answer << ',' << r.nodes << ',' << r.one << ',' << r.all
                << ',' << cores << ',' << r.brute << ',' << r.brute_checked << ','
                << (r.brute_capped ? 1 : 0) << '\n';
    }
    return 0;
}
