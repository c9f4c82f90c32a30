// Stop requests are honoured in setup on huge numbers too, and the commands
// that only write at the end (render, bounds, convert) stop at once on
// SIGINT, SIGTERM or --timeout with exit 3 and nothing written
// (docs/limits.md). The time bounds here are failure guards, generous for a
// loaded machine; the latencies themselves are measured in docs/limits.md.
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/generate.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <thread>

using namespace orthoray;
using namespace orthoray::test;
namespace fs = std::filesystem;

namespace {

// The box with sides 10^digits + 1 and 10^digits, shot from a corner.
std::string big_box(const TempDir& dir, unsigned digits) {
    BoxFamily box;
    Integer side;
    mpz_ui_pow_ui(side.get_mpz_t(), 10, digits);
    box.sides = {side + 1, side};
    box.target = BoxFamily::Target::generic;
    return dir.write("big.scene", write_generated(generate_box(box)));
}

// Waits for `child` at most `seconds`; kills it (and fails) past that.
std::optional<int> wait_at_most(pid_t child, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        int status = 0;
        if (waitpid(child, &status, WNOHANG) == child)
            return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill(child, SIGKILL);
    wait_for(child);
    return std::nullopt;
}

// Records the largest reflection count the engine reports when polled.
class HighestPoll : public RunMonitor {
public:
    std::optional<Limit> poll(std::uint64_t reflections) override {
        highest = std::max(highest, reflections);
        return std::nullopt;
    }
    std::uint64_t highest = 0;
};

} // namespace

TEST_CASE("SIGTERM during setup on 10^6-digit sides: exit 3, interrupt", "[stop_requests][cli]") {
    const TempDir dir;
    const std::string scene = big_box(dir, 1'000'000);
    // --engine lattice never finishes on this box, so the signal finds it
    // running whenever it comes; 0.4 s in is scaling, grids or tables.
    const pid_t child = spawn_cli({"solve", "--json", "--engine", "lattice", scene},
                                  dir.path("out"), dir.path("err"));
    REQUIRE(child > 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    REQUIRE(kill(child, SIGTERM) == 0);
    const std::optional<int> status = wait_at_most(child, 60);
    REQUIRE(status);
    CHECK(*status == 3);
    const nlohmann::json j = nlohmann::json::parse(slurp(dir.path("out")));
    CHECK(j["answer"] == "unknown");
    CHECK(j["limit"] == "interrupt");
}

TEST_CASE("a --timeout while the scene's huge numbers are parsed stops the parse",
          "[stop_requests][cli]") {
    // Converting the twelve 10^6-digit numbers takes about 0.3 s; a deadline
    // at 50 ms falls inside, so the run stops before any engine is chosen
    // (arithmetic none). Polling only after the read would report gmp.
    const TempDir dir;
    const std::string scene = big_box(dir, 1'000'000);
    const CliResult run = run_cli("solve --json --timeout 0.05 " + quote(scene));
    CHECK(run.status == 3);
    const nlohmann::json j = nlohmann::json::parse(run.out);
    CHECK(j["limit"] == "time");
    CHECK(j["reflections"] == 0);
    CHECK(j["arithmetic"] == "none");
}

TEST_CASE("the default engine on GMP-sized boxes switches to induction after steps of equal cost",
          "[stop_requests]") {
    // Before a step's cost counted, the 2^4000 box stepped 2 k (bits + 8),
    // some 250 000 reflections, on the tables before inducing; now the grid
    // phase and the budget shrink with the coordinates' bits.
    BoxFamily box;
    box.sides = {(Integer(1) << 4000) + 1, Integer(1) << 4000};
    HighestPoll monitor;
    SolveOptions options;
    options.monitor = &monitor;
    const Answer answer = solve(generate_box(box).scene, options);
    CHECK(answer.engine == EngineUsed::induction);
    CHECK(answer.reason == Reason::hit);
    CHECK(answer.reflections == (Integer(1) << 4001) - 1);
    // The old grid phase alone was 16384 reflections.
    CHECK(monitor.highest > 0);
    CHECK(monitor.highest < 16384);
}

TEST_CASE("render, bounds and convert stop at once on a signal or --timeout, writing nothing",
          "[stop_requests][cli]") {
    const TempDir dir;
    const std::string scene = dir.write(
        "long.scene", write_generated(generate_coprime_cuboid(40, BoxFamily::Target::far)));
    const std::string picture = dir.path("p.svg");
    // render --steps 10^12 would take hours.
    const auto timed = run_cli("render " + quote(scene) +
                               " --steps 1000000000000 --timeout 0.5 -o " + quote(picture));
    CHECK(timed.status == 3);
    CHECK(timed.out.empty());
    CHECK(timed.err == "orthoray: stopped: --timeout reached\n");
    for (const int signal : {SIGINT, SIGTERM}) {
        CAPTURE(signal);
        const pid_t child = spawn_cli({"render", scene, "--steps", "1000000000000", "-o", picture},
                                      dir.path("out"), dir.path("err"));
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        REQUIRE(kill(child, signal) == 0);
        const std::optional<int> status = wait_at_most(child, 30);
        REQUIRE(status);
        CHECK(*status == 3);
        CHECK(slurp(dir.path("err")) == "orthoray: stopped: interrupted\n");
    }
    CHECK_FALSE(fs::exists(picture));
    for (const auto& entry : fs::directory_iterator(dir.path("")))
        CHECK(entry.path().filename().string().find("partial") == std::string::npos);
    // The 10^6-digit box takes seconds to bound and to convert.
    const std::string big = big_box(dir, 1'000'000);
    CHECK(run_cli("bounds " + quote(big) + " --timeout 0.05").status == 3);
    CHECK(run_cli("convert " + quote(big) + " " + quote(dir.path("big.json")) + " --timeout 0.05")
              .status == 3);
    CHECK_FALSE(fs::exists(dir.path("big.json")));
}
