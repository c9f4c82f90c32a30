// Stop requests are honoured in setup on huge numbers too, and the commands
// that only write at the end (render, bounds, convert) stop at once on
// SIGINT, SIGTERM or --timeout with exit 3 and nothing written
// (docs/limits.md). The time bounds here are failure guards, generous for a
// loaded machine; the latencies themselves are measured in docs/limits.md.
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <vector>

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

// The same box built directly (generate_box's notes take seconds at 10^6
// digits), with its answer: the sides a, b are coprime, so the 45-degree
// ray from the corner 0 is periodic with period 2 (a + b - 1) and misses a
// target on no line x +- y = integer (docs/generate.md).
struct BigBox {
    Scene scene;
    Integer period;
};
BigBox big_box_scene(unsigned digits) {
    Integer b;
    mpz_ui_pow_ui(b.get_mpz_t(), 10, digits);
    const Integer a = b + 1;
    BigBox box;
    box.scene.add_mirror(0, 0, {{0, b}});
    box.scene.add_mirror(0, a, {{0, b}});
    box.scene.add_mirror(1, 0, {{0, a}});
    box.scene.add_mirror(1, b, {{0, a}});
    box.scene.ray().direction = Vector{1, 1, 0};
    box.scene.target() = Vector{Rational(1, 2), Rational(1, 3), 0};
    box.period = 2 * (a + b - 1);
    return box;
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

// Answers interrupt from its `stop_at`-th poll on (never with 0), counting
// the polls and keeping the reflections reported at the stopping one.
class StopAtPoll : public RunMonitor {
public:
    explicit StopAtPoll(std::uint64_t stop_at) : stop_at_(stop_at) {}
    std::optional<Limit> poll(std::uint64_t reflections) override {
        if (++polls != stop_at_) return std::nullopt;
        reported = reflections;
        return Limit::interrupt;
    }
    std::uint64_t polls = 0, reported = 0;

private:
    std::uint64_t stop_at_;
};

// Solves `scene` again with a monitor that stops it at its k-th poll, for
// each k up to `polls` (what an unstopped run made; at most 40). The polls
// are paced by the clock, so a run may poll fewer times than that one did:
// one that never reaches its k-th poll must give the unstopped answer.
void check_stops_at_each_poll(const Scene& scene, SolveOptions options, const Answer& whole,
                              std::uint64_t polls) {
    for (std::uint64_t k = 1; k <= std::min<std::uint64_t>(polls, 40); ++k) {
        CAPTURE(k);
        StopAtPoll monitor(k);
        options.monitor = &monitor;
        const Answer stopped = solve(scene, options);
        if (monitor.polls < k) {
            CHECK(stopped.reason == whole.reason);
            CHECK(stopped.limit == whole.limit);
            CHECK(stopped.reflections == whole.reflections);
            continue;
        }
        CHECK(stopped.reason == Reason::limit);
        CHECK(stopped.limit == Limit::interrupt);
        CHECK(stopped.reflections == monitor.reported);
        // The first poll is in the scaling, before an arithmetic is chosen.
        if (k == 1) CHECK(stopped.arithmetic == ArithmeticUsed::none);
    }
}

// The calling thread's CPU time in seconds: what the run itself spent,
// whatever else the machine is doing.
double thread_cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Records the longest stretch of the run's CPU time without a poll.
class LongestSilence : public RunMonitor {
public:
    LongestSilence() : last_(thread_cpu_seconds()) {}
    std::optional<Limit> poll(std::uint64_t) override {
        note();
        return std::nullopt;
    }
    // The stretch since the last poll counts too (call at the end).
    void note() {
        const double now = thread_cpu_seconds();
        longest = std::max(longest, now - last_);
        last_ = now;
    }
    double longest = 0;

private:
    double last_;
};

} // namespace

TEST_CASE("SIGTERM while 10^6-digit sides are read or set up: exit 3, interrupt",
          "[stop_requests][cli]") {
    const TempDir dir;
    const std::string scene = big_box(dir, 1'000'000);
    // --engine lattice never finishes on this box, so the signal finds it
    // running whenever it comes; 0.4 s after its handler is set, it is
    // reading the numbers or scaling them, depending on the machine.
    const pid_t child = spawn_cli({"solve", "--json", "--engine", "lattice", scene},
                                  dir.path("out"), dir.path("err"));
    REQUIRE(child > 0);
    REQUIRE(wait_until_catching(child, SIGTERM));
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    REQUIRE(kill(child, SIGTERM) == 0);
    const std::optional<int> status = wait_at_most(child, 60);
    REQUIRE(status);
    CHECK(*status == 3);
    const nlohmann::json j = nlohmann::json::parse(slurp(dir.path("out")));
    CHECK(j["answer"] == "unknown");
    CHECK(j["limit"] == "interrupt");
}

TEST_CASE("a stop at any poll of the setup on huge numbers ends the run cleanly",
          "[stop_requests]") {
    // Scaling, the grid, the tables and the exchange poll the monitor from
    // inside (lattice/setup_poll.hpp); a stop there abandons the phase and
    // reports the reflections taken. Each phase's first unit polls, so every
    // phase is stopped in one of these runs, whatever the machine's speed.
    const BigBox box = big_box_scene(100'000);
    SolveOptions options;
    options.engine = Engine::induction;
    StopAtPoll never(0);
    options.monitor = &never;
    const Answer whole = solve(box.scene, options);
    CHECK(whole.reason == Reason::cycle);
    CHECK(whole.reflections == box.period);
    CHECK(never.polls >= 5); // scaling, grid, tables, exchange, induction
    check_stops_at_each_poll(box.scene, options, whole, never.polls);
}

TEST_CASE("a stop among the induction's steps names the induction and how far it got",
          "[stop_requests][induction]") {
    // 1,000 mirrors with coordinates to 10^12: some 10^6 steps, a poll
    // every 4096 of them, so the last few polls of a run are steps, however
    // the setup's polls fall (they follow the clock).
    RandomFamily family;
    family.mirrors = 1000;
    family.range = 1'000'000'000'000;
    family.box = true;
    family.seed = 17;
    const Scene scene = generate_random(family).scene;
    SolveOptions options;
    options.engine = Engine::induction;
    StopAtPoll never(0);
    options.monitor = &never;
    const Answer whole = solve(scene, options);
    REQUIRE(whole.engine == EngineUsed::induction);
    REQUIRE(whole.stats.induction.steps > 50 * 4096);
    StopAtPoll late(never.polls - 10);
    options.monitor = &late;
    const Answer stopped = solve(scene, options);
    CHECK(stopped.reason == Reason::limit);
    CHECK(stopped.limit == Limit::interrupt);
    CHECK(stopped.engine == EngineUsed::induction);
    CHECK(stopped.stats.induction.pieces == whole.stats.induction.pieces);
    CHECK(stopped.stats.induction.states == whole.stats.induction.states);
    CHECK(stopped.stats.induction.steps > 0);
    CHECK(stopped.stats.induction.steps < whole.stats.induction.steps);
}

TEST_CASE("the illumination search polls while it builds its lattices on huge numbers",
          "[stop_requests]") {
    // A second target, on the first segment, makes it the illumination
    // question; the lattice stepper's scaling and grid poll once an element.
    BigBox box = big_box_scene(100'000);
    box.scene.targets.push_back(Vector{1, 1, 0});
    SolveOptions options;
    options.max_steps = 1;
    StopAtPoll never(0);
    options.monitor = &never;
    const Answer whole = solve(box.scene, options);
    REQUIRE(whole.illumination());
    CHECK(whole.limit == Limit::steps);
    CHECK(whole.targets[1].status == TargetAnswer::Status::lit);
    CHECK(never.polls >= 2);
    // Stopped at its first poll, inside the setup: nothing is proven yet.
    StopAtPoll first(1);
    options.monitor = &first;
    const Answer stopped = solve(box.scene, options);
    CHECK(stopped.reason == Reason::limit);
    CHECK(stopped.limit == Limit::interrupt);
    for (const TargetAnswer& t : stopped.targets) CHECK(t.status == TargetAnswer::Status::unknown);
}

TEST_CASE("a stop while the lattices are built still reports a target at a ray's start",
          "[stop_requests]") {
    // Target 2 is the ray's start: lit with 0 reflections before any event,
    // as under --max-steps 0, whatever stops the setup.
    BigBox box = big_box_scene(100'000);
    box.scene.targets.push_back(box.scene.ray().start);
    box.scene.ray().intensity = Integer(7);
    for (const bool intensity : {false, true}) {
        INFO((intensity ? "the intensity search" : "the illumination search"));
        SolveOptions options;
        if (intensity) options.min_intensity = Integer(1);
        StopAtPoll first(1);
        options.monitor = &first;
        const Answer stopped = solve(box.scene, options);
        CHECK(first.polls >= 1);
        CHECK(stopped.reason == Reason::limit);
        CHECK(stopped.limit == Limit::interrupt);
        REQUIRE(stopped.targets.size() == 2);
        CHECK(stopped.targets[0].status == TargetAnswer::Status::unknown);
        CHECK(stopped.targets[1].status == TargetAnswer::Status::lit);
        CHECK(stopped.targets[1].reflections == 0);
        CHECK(stopped.targets[1].ray == 1u);
    }
}

TEST_CASE("the octagonal engine polls while it scales and builds its hierarchy",
          "[stop_requests][octagonal]") {
    // A box with 10^100000-digit sides and one diagonal mirror: scaling
    // and the hierarchy poll once an element.
    std::string b(100'001, '0');
    b[0] = '1';
    std::string a = b;
    a.back() = '1';
    const Scene scene = read_scene("dim 2\nmirror x 0 y 0 " + b + "\nmirror x " + a + " y 0 " + b +
                                   "\nmirror y 0 x 0 " + a + "\nmirror y " + b + " x 0 " + a +
                                   "\nmirror / 1 2 3 4\nray 0 0 2 1\ntarget 1/2 1/3\n");
    REQUIRE(scene.has_diagonal());
    SolveOptions options;
    options.max_steps = 1;
    StopAtPoll never(0);
    options.monitor = &never;
    const Answer whole = solve(scene, options);
    CHECK(whole.limit == Limit::steps);
    CHECK(never.polls >= 2);
    StopAtPoll first(1);
    options.monitor = &first;
    const Answer stopped = solve(scene, options);
    CHECK(stopped.reason == Reason::limit);
    CHECK(stopped.limit == Limit::interrupt);
    CHECK(stopped.reflections == 0);
    CHECK(stopped.arithmetic == ArithmeticUsed::none); // stopped while scaling
}

TEST_CASE("in 3D too a stop at any poll of the setup on huge numbers ends the run cleanly",
          "[stop_requests][slow]") {
    // The cross-section grid polls from inside as well. It also used to
    // find each cell side's shift by counting up from 0, one shift of a
    // number that long per bit: this box's setup took seconds (324 s at
    // 10^6 digits), now a round or two.
    Integer side;
    mpz_ui_pow_ui(side.get_mpz_t(), 10, 100'000);
    Scene box;
    box.dim = 3;
    const std::vector<Rational> sides = {side + 1, side, side - 1};
    for (int axis = 0; axis < 3; ++axis)
        for (const Rational& offset : {Rational(0), sides[static_cast<std::size_t>(axis)]}) {
            std::vector<std::pair<Rational, Rational>> extent;
            for (int j = 0; j < 3; ++j)
                if (j != axis) extent.emplace_back(0, sides[static_cast<std::size_t>(j)]);
            box.add_mirror(axis, offset, extent);
        }
    box.ray().direction = Vector{1, 1, 1};
    box.target() = Vector{Rational(1, 2), Rational(1, 3), Rational(1, 5)};
    SolveOptions options;
    options.max_steps = 1000; // the answer needs about 10^200000 reflections
    StopAtPoll never(0);
    options.monitor = &never;
    const Answer whole = solve(box, options);
    CHECK(whole.limit == Limit::steps);
    CHECK(whole.reflections == 1000);
    CHECK(whole.shooter == ShooterUsed::section);
    check_stops_at_each_poll(box, options, whole, never.polls);
}

TEST_CASE("setup on 10^6-digit sides never runs long without a poll", "[stop_requests][slow]") {
    // Before the setup phases polled from inside, building the tables or
    // the exchange was over half of this run's CPU time without a poll, so a
    // stop request waited up to a few hundred milliseconds. Measured in CPU
    // time of this thread and relative to the whole run, so that neither a
    // loaded machine nor a sanitizer's slowdown moves it much: the longest
    // stretch is now some 5% of the run (docs/limits.md has the latencies).
    const BigBox box = big_box_scene(1'000'000);
    SolveOptions options;
    options.engine = Engine::induction;
    LongestSilence monitor;
    options.monitor = &monitor;
    const double begin = thread_cpu_seconds();
    const Answer answer = solve(box.scene, options);
    monitor.note();
    const double run = thread_cpu_seconds() - begin;
    CHECK(answer.reason == Reason::cycle);
    CHECK(answer.reflections == box.period);
    CAPTURE(run, monitor.longest);
    CHECK(monitor.longest < run / 4);
}

TEST_CASE("a --timeout while the scene's huge numbers are parsed stops the parse",
          "[stop_requests][cli]") {
    // Converting the twelve 10^6-digit numbers takes about 0.3 s; a deadline
    // at 10 ms falls inside, even on a machine twenty times faster, so the
    // run stops before any engine is chosen (arithmetic none). Polling only
    // after the read would report gmp.
    const TempDir dir;
    const std::string scene = big_box(dir, 1'000'000);
    const CliResult run = run_cli("solve --json --timeout 0.01 " + quote(scene));
    CHECK(run.status == 3);
    const nlohmann::json j = nlohmann::json::parse(run.out);
    CHECK(j["limit"] == "time");
    CHECK(j["reflections"] == 0);
    CHECK(j["arithmetic"] == "none");
    // The time spent reading, which the deadline ended: at least 0.01 s.
    CHECK(j["seconds"].get<double>() >= 0.01);
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
        REQUIRE(wait_until_catching(child, signal));
        std::this_thread::sleep_for(std::chrono::milliseconds(300)); // into the walk
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

TEST_CASE("verify, pieces, exchange, realistic and batch stop on a signal while input waits",
          "[stop_requests][cli]") {
    // Each reads a FIFO that never gets a writer (verify: as its
    // certificate; batch: as a manifest): SIGINT or SIGTERM ends it with
    // exit 3 and one line, not a death by the signal.
    const TempDir dir;
    const std::string scene = source_path("instances/2d/box-corner-3x5.scene");
    const std::string fifo = dir.path("waits");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::vector<std::pair<std::vector<std::string>, std::string>> commands{
        {{"verify", scene, fifo}, "orthoray: stopped: interrupted\n"},
        {{"pieces", fifo}, "orthoray: stopped: interrupted\n"},
        {{"exchange", fifo}, "orthoray: stopped: interrupted\n"},
        {{"realistic", fifo}, "orthoray: stopped: interrupted\n"},
        {{"batch", fifo, "-o", dir.path("r.jsonl")},
         "orthoray: interrupted while reading '" + fifo + "'\n"}};
    for (const auto& [args, message] : commands)
        for (const int signal : {SIGINT, SIGTERM}) {
            INFO(args[0] << ", signal " << signal);
            const pid_t child = spawn_cli(args, dir.path("out"), dir.path("err"));
            REQUIRE(wait_until_open(child, fifo));
            REQUIRE(kill(child, signal) == 0);
            const std::optional<int> status = wait_at_most(child, 30);
            REQUIRE(status);
            CHECK(*status == 3);
            CHECK(slurp(dir.path("out")).empty());
            CHECK(slurp(dir.path("err")) == message);
        }
    CHECK_FALSE(fs::exists(dir.path("r.jsonl")));
}

TEST_CASE("a FIFO instance that never gets a writer ends at --timeout or a signal",
          "[stop_requests][cli]") {
    // batch reads instances on its worker threads, where the signal's
    // handler does not run, and solve's --timeout is a deadline polled, not
    // a signal: each waits for the writer in slices that ask to stop.
    const TempDir dir;
    const std::string scene = source_path("instances/2d/box-corner-3x5.scene");
    const std::string fifo = dir.path("waits.scene");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    {
        INFO("batch --timeout: the FIFO's line records the limit, the batch goes on");
        const pid_t child = spawn_cli(
            {"batch", "--jobs", "1", "--timeout", "0.3", fifo, scene, "-o", dir.path("r.jsonl")},
            dir.path("out"), dir.path("err"));
        const std::optional<int> status = wait_at_most(child, 30);
        REQUIRE(status);
        CHECK(*status == 1);
        const std::string results = slurp(dir.path("r.jsonl"));
        CHECK(results.find(R"("path":")" + fifo +
                           R"(","hash":"unreadable","answer":"unknown",)"
                           R"("reason":"limit","limit":"time")") != std::string::npos);
        CHECK(results.find(R"("answer":"yes")") != std::string::npos);
    }
    for (const int signal : {SIGINT, SIGTERM}) {
        INFO("batch, signal " << signal);
        const pid_t child = spawn_cli({"batch", "--jobs", "2", fifo, "-o", dir.path("s.jsonl")},
                                      dir.path("out"), dir.path("err"));
        REQUIRE(wait_until_open(child, fifo));
        REQUIRE(kill(child, signal) == 0);
        const std::optional<int> status = wait_at_most(child, 30);
        REQUIRE(status);
        CHECK(*status == 3);
        CHECK(slurp(dir.path("s.jsonl")).empty());
    }
    {
        INFO("solve --timeout");
        const pid_t child = spawn_cli({"solve", "--json", "--timeout", "0.3", fifo},
                                      dir.path("out"), dir.path("err"));
        const std::optional<int> status = wait_at_most(child, 30);
        REQUIRE(status);
        CHECK(*status == 3);
        CHECK(slurp(dir.path("out")).find(R"("limit":"time")") != std::string::npos);
    }
}

TEST_CASE("verify --timeout ends a check whose stretch is long", "[stop_requests][cli]") {
    // A true but costly branch line: a state inside a closed 2^40 box,
    // whose stretch the checker walks for some 2^41 reflections.
    const TempDir dir;
    const std::string side = "1099511627776", wide = "1099511627777";
    const std::string scene = dir.write(
        "box.scene", "dim 2\nmirror x 0 y 0 " + side + "\nmirror x " + wide + " y 0 " + side +
                         "\nmirror y 0 x 0 " + wide + "\nmirror y " + side + " x 0 " + wide +
                         "\nsplitter x -5 y -10 -8\nray -10 -9 1 0\ntarget -20 -9\n"
                         "target 0 -9\n");
    const std::string certificate = dir.path("c.cert");
    REQUIRE(run_cli("solve " + quote(scene) + " --certificate " + quote(certificate)).status == 0);
    CHECK(run_cli("verify " + quote(scene) + " " + quote(certificate) + " --timeout 60").status ==
          0);
    std::string text = slurp(certificate);
    const std::size_t states = text.find("states 3");
    REQUIRE(states != std::string::npos);
    text.replace(states, 8, "states 4");
    text.insert(text.find("branch"), "branch 1/2 0 1 1 ray 1 reflections 9\n");
    const std::string longer = dir.write("longer.cert", text);
    const auto timed = run_cli("verify " + quote(scene) + " " + quote(longer) + " --timeout 0.3");
    CHECK(timed.status == 3);
    CHECK(timed.out.empty());
    CHECK(timed.err == "orthoray: stopped: --timeout reached\n");
}
