// orthoray batch: every instance decided as `solve` decides it, bad files as
// results, nothing lost or torn when killed, --resume finishing the work
// (docs/batch.md).
#include "support/lazor_levels.hpp"
#include "support/portable_random.hpp"
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <poll.h>
#include <pty.h>
#include <random>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace orthoray;
using namespace orthoray::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The lines of a results file, each parsed; `torn` counts lines that are not
// complete JSON objects (only the last one may be, after a kill).
struct Results {
    std::vector<json> lines;
    int torn = 0;
};

Results read_results(const std::string& text) {
    Results results;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end == std::string::npos ? end : end - start);
        const json j = json::parse(line, nullptr, false);
        if (end == std::string::npos || !j.is_object())
            ++results.torn;
        else
            results.lines.push_back(j);
        start = end == std::string::npos ? text.size() : end + 1;
    }
    return results;
}

// What a result says about the answer, without timings.
std::string answer_of(const json& j) {
    json copy = j;
    for (const char* timing : {"seconds", "setup_seconds", "induction_seconds", "path", "hash"})
        copy.erase(timing);
    return copy.dump();
}

// `count` boxes m x (m + 1), m from 10^5 up: the ray from a corner reaches
// the far corner after 2m - 1 reflections, a few milliseconds of stepping
// each with --engine lattice.
std::vector<std::string> write_boxes(const TempDir& dir, int count) {
    std::vector<std::string> paths;
    for (int i = 0; i < count; ++i) {
        BoxFamily box;
        box.sides = {Integer(100000 + i), Integer(100001 + i)};
        paths.push_back(dir.write("box-" + std::to_string(100000 + i) + ".scene",
                                  write_generated(generate_box(box))));
    }
    return paths;
}

} // namespace

TEST_CASE("batch decides every curated instance as solve --json does", "[batch][cli]") {
    const TempDir dir;
    const std::string out = dir.path("results.jsonl");
    const CliResult run =
        run_cli("batch " + quote(source_path("instances/2d")) + ' ' +
                quote(source_path("instances/3d")) + " --jobs 2 -o " + quote(out));
    CHECK(run.status == 0);
    CHECK(run.out.empty());
    const Results results = read_results(slurp(out));
    CHECK(results.torn == 0);
    REQUIRE(results.lines.size() == instance_files().size());
    std::set<std::string> paths;
    for (const json& line : results.lines) {
        const std::string path = line["path"];
        CAPTURE(path);
        paths.insert(path);
        const CliResult solve = run_cli("solve --json " + quote(path));
        json expected = json::parse(solve.out);
        expected["status"] = solve.status;
        CHECK(answer_of(line) == answer_of(expected));
        CHECK(line["hash"].get<std::string>().size() == 16);
    }
    CHECK(paths.size() == results.lines.size());
}

TEST_CASE("a complete batch leaves its lines in input order, whatever the threads",
          "[batch][cli]") {
    const TempDir dir;
    const std::vector<std::string> boxes = write_boxes(dir, 30);
    std::string timings_removed[2];
    for (const int jobs : {1, 2}) {
        const std::string out = dir.path("r" + std::to_string(jobs) + ".jsonl");
        REQUIRE(run_cli("batch " + quote(dir.path("")) + " --engine lattice --jobs " +
                        std::to_string(jobs) + " -o " + quote(out))
                    .status == 0);
        const Results results = read_results(slurp(out));
        REQUIRE(results.lines.size() == boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) {
            CHECK(results.lines[i]["path"] == boxes[i]);
            timings_removed[jobs - 1] +=
                results.lines[i]["path"].get<std::string>() + answer_of(results.lines[i]) + '\n';
        }
    }
    CHECK(timings_removed[0] == timings_removed[1]);
}

TEST_CASE("batch records a bad file as a result and goes on", "[batch][cli]") {
    const TempDir dir;
    const std::string good = dir.write("good.scene", slurp(instance("2d/box-corner-3x5.scene")));
    const std::string bad = dir.write("bad.scene", "dim 2\nmirror q 0 y 0 1\n");
    const std::string manifest = dir.write("list.txt", "# the instances\n" + bad + "\n\n" + good +
                                                           "\n" + dir.path("missing.scene") + "\n");
    const CliResult run = run_cli("batch --jobs 1 " + quote(manifest));
    CHECK(run.status == 1); // every instance has a result, two of them errors
    const Results results = read_results(run.out);
    REQUIRE(results.lines.size() == 3);
    std::map<std::string, json> by_path;
    for (const json& line : results.lines) by_path[line["path"]] = line;
    CHECK(by_path[bad]["error"] ==
          bad + ":2:8: found 'q', expected the normal axis (x or y) of a 2D scene");
    CHECK(by_path[bad]["status"] == 2);
    CHECK(by_path[good]["answer"] == "yes");
    CHECK(by_path[good]["status"] == 0);
    CHECK(by_path[dir.path("missing.scene")]["status"] == 2);
    CHECK(by_path[dir.path("missing.scene")]["hash"] == "unreadable");
}

TEST_CASE("batch decides a path named twice once, fresh or resumed", "[batch][cli]") {
    const TempDir dir;
    const std::string good = dir.write("good.scene", slurp(instance("2d/box-corner-3x5.scene")));
    const std::string bad = dir.write("bad.scene", "dim 2\nmirror q 0 y 0 1\n");
    const std::string manifest = dir.write("list.txt", good + "\n" + bad + "\n" + good + "\n");
    const std::string out = dir.path("r.jsonl");
    const CliResult run =
        run_cli("batch --jobs 2 " + quote(manifest) + ' ' + quote(good) + " -o " + quote(out));
    CHECK(run.status == 1);
    const Results results = read_results(slurp(out));
    REQUIRE(results.lines.size() == 2);
    CHECK(results.lines[0]["path"] == good);
    CHECK(results.lines[1]["path"] == bad);
    // Resumed, the kept bad-input line still makes the batch's status 1.
    const CliResult again = run_cli("batch " + quote(manifest) + " -o " + quote(out) + " --resume");
    CHECK(again.status == 1);
    CHECK(again.err.find("2 already in the results (1 of them bad input or at a limit)") !=
          std::string::npos);
    CHECK(read_results(slurp(out)).lines.size() == 2);
    // A manifest of the good one alone resumes with status 0.
    const std::string only = dir.write("only.txt", good + "\n");
    CHECK(run_cli("batch " + quote(only) + " -o " + quote(out) + " --resume").status == 0);
}

#ifndef ORTHORAY_SANITIZE // sanitizers reserve terabytes of address space and abort on failure
TEST_CASE("batch --max-memory leaves room for its threads and answers as solve does",
          "[batch][cli]") {
    // Each thread's malloc arena alone would take 64 MiB of address space,
    // and its stack 8: a small budget once aborted the process when a
    // thread could not start, or sent every search to the slow scan.
    const TempDir dir;
    const std::string scene = source_path("instances/2d/box-corner-3x5.scene");
    const std::string splitters =
        dir.write("split.scene", "dim 2\nsplitter x 2 y 1 3\nmirror x 0 y 0 5\nmirror y 6 x 0 4\n"
                                 "ray 1 0 1 1\ntarget 4 4\ntarget 0 3\n");
    for (const char* jobs : {"1", "2", "8"}) {
        INFO("--jobs " << jobs);
        const CliResult run = run_cli("batch --jobs " + std::string(jobs) + " --max-memory 10 " +
                                      quote(scene) + ' ' + quote(splitters));
        const Results results = read_results(run.out);
        REQUIRE(results.lines.size() == 2);
        for (const json& line : results.lines) {
            INFO(line.dump());
            const CliResult alone =
                run_cli("solve --json --max-memory 10 " + quote(line["path"].get<std::string>()));
            const json expected = json::parse(alone.out);
            CHECK(line["answer"] == expected["answer"]);
            CHECK(line["reflections"] == expected["reflections"]);
            CHECK(line["status"] == alone.status);
        }
    }
}
#endif

TEST_CASE("batch reads a manifest from standard input", "[batch][cli]") {
    const TempDir dir;
    const std::string scene = instance("2d/box-corner-3x5.scene");
    const ShellResult run = run_shell("echo " + quote(scene) + " | \"$ORTHORAY\" batch - -o " +
                                      quote(dir.path("r.jsonl")));
    CHECK(run.status == 0);
    const Results results = read_results(slurp(dir.path("r.jsonl")));
    REQUIRE(results.lines.size() == 1);
    CHECK(results.lines[0]["path"] == scene);
    CHECK(results.lines[0]["reflections"] == 6);
}

TEST_CASE("batch --resume decides only what is missing, and again what was edited",
          "[batch][cli]") {
    const TempDir dir;
    const std::vector<std::string> boxes = write_boxes(dir, 4);
    const std::string out = dir.path("r.jsonl");
    const std::string command =
        "batch " + quote(dir.path("")) + " --engine lattice -o " + quote(out);
    REQUIRE(run_cli(command).status == 0);
    const std::string first = slurp(out);
    CHECK(read_results(first).lines.size() == 4);

    const CliResult again = run_cli(command + " --resume");
    CHECK(again.status == 0);
    CHECK(again.err.find("0 yes, 0 no, 0 bad input, 0 at a limit, 4 already in the results") !=
          std::string::npos);
    CHECK(slurp(out) == first);

    // An edited file has a new hash: it is decided again and its new line
    // appended; the old line stays, keyed by the old content.
    BoxFamily box;
    box.sides = {Integer(3), Integer(5)};
    dir.write(fs::path(boxes[0]).filename().string(), write_generated(generate_box(box)));
    CHECK(run_cli(command + " --resume").status == 0);
    const Results results = read_results(slurp(out));
    REQUIRE(results.lines.size() == 5);
    // Sorted in input order, the old line first (the sort is stable).
    CHECK(results.lines[0]["path"] == boxes[0]);
    CHECK(results.lines[0]["reflections"] == 2 * 100000 - 1);
    CHECK(results.lines[1]["path"] == boxes[0]);
    CHECK(results.lines[1]["reflections"] == 6);

    // Without --resume the file starts afresh.
    CHECK(run_cli(command).status == 0);
    CHECK(read_results(slurp(out)).lines.size() == 4);
}

TEST_CASE("batch killed at random moments never leaves a line --resume misreads",
          "[batch][cli][slow]") {
    const TempDir dir;
    const int count = 300;
    const std::vector<std::string> boxes = write_boxes(dir, count);
    const std::string out = dir.path("r.jsonl");
    std::mt19937_64 rng(20261124);
    int kills = 0;
    for (int round = 0; round < 40; ++round) {
        const pid_t child = spawn_cli({"batch", dir.path(""), "--engine", "lattice", "--jobs", "2",
                                       "--resume", "-o", out, "--quiet"},
                                      dir.path("out"), dir.path("err"));
        REQUIRE(child > 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(pick(rng, 5, 60)));
        const bool killed = kill(child, SIGKILL) == 0;
        const int status = wait_for(child);
        if (status == 0) break; // it finished before the kill
        REQUIRE(killed);
        REQUIRE(status == -SIGKILL);
        ++kills;
        // At most the last line is torn, and each complete line is a result.
        const Results partial = read_results(slurp(out));
        CHECK(partial.torn <= 1);
        for (const json& line : partial.lines) CHECK(line.contains("answer"));
    }
    CHECK(kills > 0);
    REQUIRE(run_cli("batch " + quote(dir.path("")) + " --engine lattice --resume -o " + quote(out))
                .status == 0);
    const Results results = read_results(slurp(out));
    CHECK(results.torn == 0);
    REQUIRE(results.lines.size() == static_cast<std::size_t>(count));
    std::set<std::string> seen;
    for (const json& line : results.lines) {
        const std::string path = line["path"];
        CHECK(seen.insert(path).second); // no instance twice
        const int m = std::stoi(fs::path(path).stem().string().substr(4));
        CHECK(line["reason"] == "hit");
        CHECK(line["reflections"] == 2 * m - 1);
    }
}

TEST_CASE("batch stopped by SIGINT keeps what it decided and exits 3", "[batch][cli][slow]") {
    const TempDir dir, boxes;
    write_boxes(boxes, 200);
    // First in the list, a FIFO that never gets a writer: one worker waits
    // on it until the signal, so the batch cannot finish before it.
    const std::string fifo = dir.path("waits.scene");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string out = dir.path("r.jsonl");
    const pid_t child = spawn_cli(
        {"batch", fifo, boxes.path(""), "--engine", "lattice", "--jobs", "2", "-o", out, "--quiet"},
        dir.path("out"), dir.path("err"));
    // Signal it once it is deciding (its first line is written), not
    // before it has set up its handlers: a SIGINT then ends it as any
    // program, with nothing written.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (slurp(out).empty() && std::chrono::steady_clock::now() < give_up)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    REQUIRE(kill(child, SIGINT) == 0);
    const std::optional<int> status = wait_at_most(child, 60); // the FIFO waits forever else
    REQUIRE(status);
    CHECK(*status == 3);
    CHECK(slurp(dir.path("err")).find("orthoray: stopped: interrupted") != std::string::npos);
    const Results partial = read_results(slurp(out));
    CHECK(partial.torn == 0);
    CHECK(!partial.lines.empty());
    for (const json& line : partial.lines) CHECK(line["path"] != fifo); // it was never decided
    CHECK(run_cli("batch " + quote(boxes.path("")) + " --resume -o " + quote(out)).status == 0);
    std::set<std::string> seen;
    for (const json& line : read_results(slurp(out)).lines) {
        CHECK(line["reason"] == "hit");
        CHECK(seen.insert(line["path"].get<std::string>()).second); // none twice
    }
    CHECK(seen.size() == 200);
}

TEST_CASE("batch --certificates writes one certificate an instance, each valid", "[batch][cli]") {
    const TempDir dir;
    fs::create_directory(dir.path("certs"));
    const CliResult run = run_cli("batch " + quote(source_path("instances/2d")) +
                                  " --certificates " + quote(dir.path("certs")));
    CHECK(run.status == 0);
    const Results results = read_results(run.out);
    REQUIRE(!results.lines.empty());
    for (const json& line : results.lines) {
        const std::string path = line["path"];
        CAPTURE(path);
        const std::string cert = dir.path("certs/" + fs::path(path).filename().string() + '.' +
                                          line["hash"].get<std::string>() + ".cert");
        std::istringstream in(slurp(cert));
        CHECK(verify_certificate(load_scene(path), in, cert).valid);
    }
}

TEST_CASE("batch stops with exit 5 at a certificate it cannot write, and --resume goes on",
          "[batch][cli]") {
    const TempDir dir, boxes;
    write_boxes(boxes, 4);
    // The certificates' names, from a run that writes them all.
    fs::create_directory(dir.path("names"));
    REQUIRE(
        run_cli("batch " + quote(boxes.path("")) + " --certificates " + quote(dir.path("names")))
            .status == 0);
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.path("names")))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    REQUIRE(names.size() == 4);
    // A directory where the third certificate goes: it cannot be created.
    fs::create_directories(dir.path("certs/" + names[2]));
    const std::string out = dir.path("r.jsonl");
    const std::string command = "batch " + quote(boxes.path("")) + " --jobs 1 -o " + quote(out) +
                                " --certificates " + quote(dir.path("certs"));
    const CliResult stopped = run_cli(command);
    CHECK(stopped.status == 5);
    CHECK(stopped.err.find("found a directory for the certificate") != std::string::npos);
    // The two instances before it keep their lines and certificates.
    CHECK(read_results(slurp(out)).lines.size() == 2);
    fs::remove(dir.path("certs/" + names[2]));
    CHECK(run_cli(command + " --resume").status == 0);
    const Results results = read_results(slurp(out));
    CHECK(results.lines.size() == 4);
    for (const std::string& name : names) {
        CAPTURE(name);
        CHECK(slurp(dir.path("certs/" + name)) == slurp(dir.path("names/" + name)));
    }
}

TEST_CASE("batch decides Lazor levels as puzzle solve --json does, bad ones as errors",
          "[batch][cli][puzzle]") {
    const auto folder = lazor_folder_or_skip();
    if (!folder) return;
    const TempDir dir;
    fs::create_directories(dir.path("levels/public"));
    fs::create_directory(dir.path("certs"));
    const std::vector<std::string> levels{
        dir.write("levels/public/braid_1.bff", slurp((*folder / "braid_1.bff").string())),
        dir.write("levels/public/unit_test_3x3.bff",
                  slurp((*folder / "cganley2-unit_test_3x3.bff").string())),
        dir.write("levels/unsolvable.bff",
                  slurp((*folder / "unsolvable/404NotFound25fall-mini_test.bff").string())),
        dir.write("levels/malformed.bff", slurp((*folder / "malformed/grid_1.bff").string()))};
    // A grid maze beside them is still read as its scene.
    const std::string maze = dir.write("levels/maze.grid", slurp(instance("grid/example.grid")));
    const std::string out = dir.path("r.jsonl");
    const std::string command = "batch " + quote(dir.path("levels")) + " --jobs 2 -o " +
                                quote(out) + " --certificates " + quote(dir.path("certs"));
    const CliResult run = run_cli(command);
    CHECK(run.status == 1); // every instance has its line, one of them an error
    CHECK(run.err.find("2 yes, 2 no, 1 bad input, 0 at a limit") != std::string::npos);
    const Results results = read_results(slurp(out));
    CHECK(results.torn == 0);
    REQUIRE(results.lines.size() == 5);
    std::map<std::string, json> by_path;
    for (const json& line : results.lines) by_path[line["path"]] = line;
    CHECK(by_path[maze].contains("reason"));
    for (const std::string& level : levels) {
        CAPTURE(level);
        const json& line = by_path[level];
        CHECK(line["hash"].get<std::string>().size() == 16);
        const CliResult solve = run_cli("puzzle solve --json --jobs 1 " + quote(level));
        if (solve.status == 2) {
            CHECK(line["error"].get<std::string>() + '\n' == solve.err);
            CHECK(line["status"] == 2);
            continue;
        }
        json expected = json::parse(solve.out);
        expected["status"] = solve.status;
        CHECK(answer_of(line) == answer_of(expected));
    }
    CHECK(by_path[levels[0]]["answer"] == "solved");
    CHECK(by_path[levels[2]]["status"] == 1);
    // A level has no certificate; only the maze's was written.
    CHECK(std::distance(fs::directory_iterator(dir.path("certs")), fs::directory_iterator()) == 1);

    const std::string first = slurp(out);
    const CliResult again = run_cli(command + " --resume");
    CHECK(again.status == 1); // the malformed level's kept line
    CHECK(again.err.find("5 already in the results (1 of them bad input or at a limit)") !=
          std::string::npos);
    CHECK(slurp(out) == first);

    // --max-steps caps a level's search nodes, as puzzle solve --max-nodes does.
    const CliResult capped = run_cli("batch " + quote(levels[0]) + " --max-steps 1");
    CHECK(capped.status == 1);
    const Results capped_lines = read_results(capped.out);
    REQUIRE(capped_lines.lines.size() == 1);
    const CliResult nodes =
        run_cli("puzzle solve --json --jobs 1 --max-nodes 1 " + quote(levels[0]));
    json expected = json::parse(nodes.out);
    expected["status"] = nodes.status;
    CHECK(answer_of(capped_lines.lines[0]) == answer_of(expected));
    CHECK(capped_lines.lines[0]["limit"] == "nodes");
}

TEST_CASE("batch stopped by a write error leaves whole lines only", "[batch][cli]") {
    // A file size limit (the shell's ulimit -f, in 512-byte blocks) cuts the
    // results file in the middle of a line; the line's written part is taken
    // back, so the file ends at a newline and --resume drops nothing.
    const TempDir dir;
    const std::string out = dir.path("cut.jsonl");
    const std::string sweep = " batch --generate 'random --dim 2 --mirrors 30 --box' "
                              "--seeds 1..400 --jobs 1 -o " +
                              quote(out);
    const int raw = std::system(
        ("ulimit -f 20; '" + std::string(ORTHORAY_CLI) + "'" + sweep + " 2>/dev/null").c_str());
    REQUIRE(WIFEXITED(raw));
    CHECK(WEXITSTATUS(raw) == 5);
    const std::string cut = slurp(out);
    REQUIRE(cut.size() > 1000);
    CHECK(cut.size() <= 20 * 512);
    CHECK(cut.back() == '\n');
    const CliResult resumed = run_cli(sweep.substr(1) + " --resume");
    CHECK(resumed.status == 0);
    CHECK(resumed.err.find("dropped") == std::string::npos);
    CHECK(read_results(slurp(out)).lines.size() == 400);
}

TEST_CASE("batch refuses what it cannot do, before deciding anything", "[batch][cli]") {
    const TempDir dir;
    const std::string scenes = quote(source_path("instances/2d"));
    CHECK(run_cli("batch " + scenes + " --resume").status == 2);
    CHECK(run_cli("batch " + quote(dir.path("nothing-here"))).err ==
          "orthoray: found the input '" + dir.path("nothing-here") +
              "', expected an existing instance file, directory or manifest\n");
    const CliResult graph =
        run_cli("batch " + scenes + " --engine graph --certificates " + quote(dir.path("")));
    CHECK(graph.status == 2);
    CHECK(graph.out.empty());
    CHECK(run_cli("batch " + scenes + " --jobs 0").status == 2);
}

TEST_CASE("batch refuses a results file that is one of its inputs, and leaves it whole",
          "[batch][cli]") {
    // The results file is emptied when opened: an instance, a manifest, an
    // instance found in a directory or a hard link to one must be refused
    // before that, as every other command refuses its input as output.
    const TempDir dir;
    const std::string text = slurp(instance("2d/box-corner-3x5.scene"));
    std::filesystem::create_directory(dir.path("scenes"));
    const std::string scene = dir.write("scenes/a.scene", text);
    const std::string manifest = dir.write("list.txt", scene + "\n");
    const std::string link = dir.path("link.jsonl");
    std::filesystem::create_hard_link(scene, link);
    const std::vector<std::pair<std::string, std::string>> cases{
        {quote(scene), scene},
        {quote(manifest), manifest},
        {quote(dir.path("scenes")), scene},
        {quote(manifest), link},
        {quote(scene) + " --resume", scene}};
    for (const auto& [inputs, output] : cases) {
        INFO(inputs << " -o " << output);
        const CliResult run = run_cli("batch " + inputs + " -o " + quote(output));
        CHECK(run.status == 2);
        CHECK(run.out.empty());
        CHECK(run.err.find("naming the input") != std::string::npos);
        CHECK(run.err.find("expected another file (it would be overwritten)") != std::string::npos);
    }
    CHECK(slurp(scene) == text);
    CHECK(slurp(manifest) == scene + "\n");
}

TEST_CASE("batch shows done, rate, ETA and failures on a terminal, and erases the line",
          "[batch][cli][slow]") {
    const TempDir dir;
    write_boxes(dir, 150);
    dir.write("bad.scene", "dim 5\n");
    int terminal = -1, child_side = -1;
    REQUIRE(openpty(&terminal, &child_side, nullptr, nullptr, nullptr) == 0);
    const pid_t child = fork();
    if (child == 0) {
        dup2(child_side, STDERR_FILENO);
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        closefrom(3);
        const std::string scenes = dir.path("");
        execl(ORTHORAY_CLI, ORTHORAY_CLI, "batch", scenes.c_str(), "--engine", "lattice", "--jobs",
              "1", static_cast<char*>(nullptr));
        _exit(127);
    }
    close(child_side);
    std::string seen;
    char buffer[4096];
    for (;;) {
        pollfd ready{terminal, POLLIN, 0};
        if (poll(&ready, 1, 60'000) <= 0) break; // the guard against a hang
        const ssize_t n = read(terminal, buffer, sizeof buffer);
        if (n <= 0) break; // the child closed the terminal
        seen.append(buffer, static_cast<std::size_t>(n));
    }
    close(terminal);
    CHECK(wait_for(child) == 1); // one bad file
    CAPTURE(seen);
    CHECK(seen.find("/151 done, ") != std::string::npos);
    CHECK(seen.find("/s, ETA ") != std::string::npos);
    CHECK(seen.find(" failed") != std::string::npos);
    // The line is erased before the summary, which stands alone.
    CHECK(seen.find("\r\033[Kbatch: 151 of 151 instances") != std::string::npos);
}

#ifdef ORTHORAY_MPI
TEST_CASE("batch --mpi on two ranks writes the lines a local batch writes", "[batch][cli][mpi]") {
    const TempDir dir;
    write_boxes(dir, 40);
    dir.write("bad.scene", "dim 2\nray 0 0 1 1\n");
    const std::string scenes = quote(dir.path("")) + ' ' + quote(source_path("instances/2d"));
    // Open MPI refuses root unless told; CI runs as root.
    const ShellResult mpi =
        run_shell("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MPIEXEC
                  " -n 2 --oversubscribe \"$ORTHORAY\" batch " +
                  scenes + " --engine lattice --mpi -o " + quote(dir.path("mpi.jsonl")));
    CHECK(run_cli("batch " + scenes + " --engine lattice -o " + quote(dir.path("local.jsonl")))
              .status == 1); // the bad file
    CHECK(mpi.status == 1);
    auto answers = [](const std::string& text) {
        std::multiset<std::string> out;
        for (const json& line : read_results(text).lines)
            out.insert(line["path"].get<std::string>() + ' ' + answer_of(line));
        return out;
    };
    const std::multiset<std::string> local = answers(slurp(dir.path("local.jsonl")));
    const auto curated = std::distance(fs::directory_iterator(source_path("instances/2d")),
                                       fs::directory_iterator());
    CHECK(local.size() == 41 + static_cast<std::size_t>(curated));
    CHECK(answers(slurp(dir.path("mpi.jsonl"))) == local);
    // Generated instances spread over the ranks: the same lines too.
    // Double quotes: run_shell puts the whole script in single quotes.
    const std::string words = "\"random --mirrors 8 --box\"";
    const ShellResult generated_on_ranks =
        run_shell("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MPIEXEC
                  " -n 2 --oversubscribe \"$ORTHORAY\" batch --generate " +
                  words + " --seeds 1..60 --mpi -o " + quote(dir.path("g-mpi.jsonl")));
    CAPTURE(generated_on_ranks.err);
    CHECK(generated_on_ranks.status == 0);
    run_cli("batch --generate " + words + " --seeds 1..60 -o " + quote(dir.path("g.jsonl")));
    auto generated = [](const std::string& text) {
        std::string out;
        for (const json& line : read_results(text).lines)
            out += line["seed"].dump() + ' ' + answer_of(line) + '\n';
        return out;
    };
    CHECK(generated(slurp(dir.path("g-mpi.jsonl"))) == generated(slurp(dir.path("g.jsonl"))));
    CHECK(read_results(slurp(dir.path("g.jsonl"))).lines.size() == 60);
    // Resumed on the ranks, a complete file stays as it is.
    const std::string before = slurp(dir.path("mpi.jsonl"));
    run_shell("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " MPIEXEC
              " -n 2 --oversubscribe \"$ORTHORAY\" batch " +
              scenes + " --mpi --resume -o " + quote(dir.path("mpi.jsonl")));
    CHECK(slurp(dir.path("mpi.jsonl")) == before);
}
#endif

TEST_CASE("batch --generate decides each seed's scene as generate then solve would",
          "[batch][cli]") {
    const TempDir dir;
    const std::string words = "random --dim 2 --mirrors 12 --box --absorbers 1/10";
    const std::string out = dir.path("g.jsonl");
    const std::string command =
        "batch --generate " + quote(words) + " --seeds 40..69 --jobs 2 -o " + quote(out);
    REQUIRE(run_cli(command).status == 0);
    const Results results = read_results(slurp(out));
    REQUIRE(results.lines.size() == 30);
    for (std::size_t i = 0; i < results.lines.size(); ++i) {
        const json& line = results.lines[i];
        const std::uint64_t seed = 40 + i; // sorted in seed order
        CHECK(line["seed"] == seed);
        CHECK(line["generate"] == words);
        const std::string scene = dir.write(
            "s.scene", run_cli("generate " + words + " --seed " + std::to_string(seed)).out);
        const CliResult solve = run_cli("solve --json " + quote(scene));
        json expected = json::parse(solve.out);
        expected["status"] = solve.status;
        json got = line;
        got.erase("generate");
        got.erase("seed");
        CHECK(answer_of(got) == answer_of(expected));
    }
    // Resumed over more seeds, only the new ones are decided.
    const CliResult more =
        run_cli("batch --generate " + quote(words) + " --seeds 40..74 --resume -o " + quote(out));
    CHECK(more.err.find(", 30 already in the results") != std::string::npos);
    CHECK(read_results(slurp(out)).lines.size() == 35);
    CHECK(run_cli("batch --generate " + quote(words) + " --seeds 3..2").status == 2);
    CHECK(run_cli("batch --generate 'random --seed 4' --seeds 1").status == 2);
    CHECK(run_cli("batch --generate 'random --frobnicate' --seeds 1").status == 2);
    // Words refused by the family's own checks leave an existing results
    // file as it was: they are refused before it is opened.
    const std::string kept = dir.write("kept.jsonl", "keep\n");
    for (const char* bad : {"random --dim 9 --mirrors 10", "random --mirrors 10 --seed 3"}) {
        INFO(bad);
        const CliResult refused =
            run_cli("batch --generate " + quote(bad) + " --seeds 1..10 -o " + quote(kept));
        CHECK(refused.status == 2);
        CHECK(slurp(kept) == "keep\n");
    }
}
