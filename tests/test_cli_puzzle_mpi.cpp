// puzzle solve --mpi and puzzle generate --mpi (docs/puzzles.md, "On many
// machines"): on two ranks, the bytes one process prints, apart from the
// time and the jobs count; limits end with exit 3 and nothing claimed; bad
// input ends every rank with exit 2. Only built with MPI; all [slow], as
// each mpirun takes about half a second to start.
#ifdef ORTHORAY_MPI
#include "support/lazor_levels.hpp"
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <regex>

using namespace orthoray::test;

namespace {

// Two ranks on this machine; Open MPI refuses root unless told (CI runs as
// root).
const std::string on_two_ranks =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MPIEXEC
    " -n 2 --oversubscribe \"$ORTHORAY\" ";

struct Printed {
    int status = -1;
    std::string out;
};

Printed on_ranks(const TempDir& dir, const std::string& args) {
    const std::string out = dir.path("mpi.out");
    const ShellResult r = run_shell(on_two_ranks + args + " > " + quote(out));
    CAPTURE(args, r.err);
    return {r.status, slurp(out)};
}

// The report without what differs between runs of the same search: the
// time, and in JSON the seconds and the jobs (threads or ranks).
std::string without_timings(const std::string& text) {
    static const std::regex time_line("time +[0-9.]+ ms\n");
    static const std::regex seconds("\"seconds\": *[0-9.e+-]+");
    static const std::regex jobs("\"jobs\": *[0-9]+");
    return std::regex_replace(
        std::regex_replace(std::regex_replace(text, time_line, ""), seconds, ""), jobs, "");
}

} // namespace

TEST_CASE("puzzle solve --mpi on two ranks prints what one process prints",
          "[puzzle][cli][mpi][slow]") {
    // Each with the options it tests: a first solution, counts (text and
    // JSON), public levels. (The unsolvable one is with the limits below.)
    std::vector<std::pair<std::string, std::string>> runs;
    for (const auto& [name, options] :
         std::vector<std::pair<const char*, const char*>>{{"reflect-10x10", ""},
                                                          {"reflect-8x8-hard", " --all"},
                                                          {"several-5x5", " --all --json"}})
        runs.emplace_back(source_path(std::string("instances/puzzles/") + name + ".bff"), options);
    if (const auto folder = lazor_folder_or_warn()) {
        runs.emplace_back((*folder / "braid_5.bff").string(), " --all");
        runs.emplace_back((*folder / "dark_1.bff").string(), " --json");
    }
    const TempDir dir;
    for (const auto& [level, options] : runs) {
        const std::string args = "puzzle solve " + quote(level) + options;
        CAPTURE(args);
        const CliResult local = run_cli(args + " --jobs 1");
        const Printed mpi = on_ranks(dir, args + " --mpi");
        CHECK(mpi.status == local.status);
        CHECK(without_timings(mpi.out) == without_timings(local.out));
        CHECK(local.out.find("answer") != std::string::npos);
    }
}

// Each run here costs mpirun's start (about half a second) and two seconds
// more, since Open MPI 4.1 aborts a job whose rank 0 exits nonzero.
TEST_CASE("puzzle solve --mpi proves unsolvable, and stops at its limits with nothing claimed",
          "[puzzle][cli][mpi][limits][slow]") {
    const TempDir dir;
    const std::string unsolvable = quote(source_path("instances/puzzles/unsolvable-5x5.bff"));
    const CliResult proven = run_cli("puzzle solve --all --jobs 1 " + unsolvable);
    const Printed proven_on_ranks = on_ranks(dir, "puzzle solve --all --mpi " + unsolvable);
    CHECK(proven.status == 1);
    CHECK(proven_on_ranks.status == 1);
    CHECK(without_timings(proven_on_ranks.out) == without_timings(proven.out));
    const std::string level = quote(source_path("instances/puzzles/reflect-10x10.bff"));
    // --max-nodes is the one-process budget: the same verdict either side of it.
    const CliResult counted = run_cli("puzzle solve --all --json --jobs 1 " + level);
    const std::regex nodes_field("\"nodes\": *([0-9]+)");
    std::smatch m;
    REQUIRE(std::regex_search(counted.out, m, nodes_field));
    const std::string needed = m[1];
    const Printed enough =
        on_ranks(dir, "puzzle solve --all --mpi --max-nodes " + needed + ' ' + level);
    CHECK(enough.status == 0);
    const Printed short_of_it =
        on_ranks(dir, "puzzle solve --all --mpi --max-nodes " +
                          std::to_string(std::stoull(needed) - 1) + ' ' + level);
    CHECK(short_of_it.status == 3);
    CHECK(
        short_of_it.out.find("answer       unknown\nreason       limit (--max-nodes reached)\n") !=
        std::string::npos);
    CHECK(short_of_it.out.find("GRID") == std::string::npos);
    const Printed timed = on_ranks(dir, "puzzle solve --all --mpi --timeout 0.001 " + level);
    CHECK(timed.status == 3);
    CHECK(timed.out.find("reason       limit (--timeout reached)\n") != std::string::npos);
    // Bad input: rank 0's message, exit 2, and no rank left waiting.
    const ShellResult bad =
        run_shell(on_two_ranks + "puzzle solve --mpi " + quote(dir.path("missing.bff")));
    CHECK(bad.status == 2);
    CHECK(bad.err.find("missing.bff:1:1: found ") != std::string::npos);
}

TEST_CASE("puzzle generate --mpi on two ranks writes the level one process writes",
          "[puzzle][cli][mpi][generate][slow]") {
    const TempDir dir;
    for (const std::string args :
         {"--size 7x7 --blocks A4,C1 --lasers 1 --points 8 --seed 7",
          "--size 6x6 --blocks A4,C1 --points 5 --difficulty medium --seed 3"}) {
        CAPTURE(args);
        const CliResult local = run_cli("puzzle generate " + args);
        const Printed mpi = on_ranks(dir, "puzzle generate --mpi " + args);
        CHECK(mpi.status == local.status);
        CHECK(mpi.out == local.out);
        CHECK(local.out.find("GRID START") != std::string::npos);
    }
}
#endif
