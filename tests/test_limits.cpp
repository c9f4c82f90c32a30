// Limits (docs/limits.md): a RunMonitor stops every engine with an exact
// count of the reflections performed and a certificate that verifies as
// partial; on the command line --timeout, --max-memory, SIGINT and SIGTERM
// end a long run with answer unknown, the limit named, and exit status 3.
#include "support/run_cli.hpp"

#include "orthoray/certificate.hpp"
#include "orthoray/exchange.hpp"
#include "orthoray/generate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/scene.hpp"
#include "orthoray/solve.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <cstdint>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <optional>
#include <poll.h>
#include <pty.h>
#include <regex>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using namespace orthoray;
using orthoray::test::run_cli;
namespace fs = std::filesystem;

// Stops the run at the `stop_at`-th poll and remembers what it was told.
class StopAfterPolls : public RunMonitor {
public:
    explicit StopAfterPolls(int stop_at) : stop_at_(stop_at) {}
    std::optional<Limit> poll(std::uint64_t reflections) override {
        CHECK(reflections >= last_); // the count never goes back
        last_ = reflections;
        return ++polls_ == stop_at_ ? std::optional<Limit>(Limit::interrupt) : std::nullopt;
    }
    int polls() const { return polls_; }
    std::uint64_t last() const { return last_; }

private:
    int stop_at_, polls_ = 0;
    std::uint64_t last_ = 0;
};

// About 3 * 2^k reflections: far more than a test can wait for when k = 40.
Scene long_orbit(unsigned k) {
    return generate_coprime_cuboid(k, BoxFamily::Target::far).scene;
}

std::string scene_file(const fs::path& dir, const Scene& scene) {
    const std::string path = (dir / "long.scene").string();
    std::ofstream(path) << write_generated({scene, std::nullopt, {}});
    return path;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("orthoray-test-limits-" + std::to_string(::getpid()) + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Polls `ready` until it holds. The minute is a guard that turns a hang into
// a failure, not a measurement: on any machine the events awaited here come
// within a few seconds.
template <class Ready>
bool wait_until(Ready ready) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!ready()) {
        if (std::chrono::steady_clock::now() > give_up) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return true;
}

// A `solve` of `scene` that runs for hours unless stopped, writing its
// certificate to `cert`, stdout to /dev/null or `out`, and stderr to the
// file `err` or to the descriptor `err_fd`.
pid_t start_solve(const std::string& scene, const std::string& cert, const std::string& out,
                  const std::string& err, int err_fd = -1, const char* extra = nullptr) {
    const pid_t child = fork();
    if (child != 0) return child;
    const int out_fd =
        open(out.empty() ? "/dev/null" : out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err_fd < 0) err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out_fd, STDOUT_FILENO);
    dup2(err_fd, STDERR_FILENO);
    closefrom(3); // no other test's terminal stays open in this child
    execl(ORTHORAY_CLI, ORTHORAY_CLI, "solve", "--json", scene.c_str(), "--certificate",
          cert.c_str(), extra, static_cast<char*>(nullptr));
    _exit(127);
}

// The child is stepping: its certificate holds more than a buffer's worth
// of points (the file stays empty until the stream's first flush).
// The certificate is written to a temporary file beside it (".NAME.partial-
// XXXXXX", docs/limits.md) and renamed into place at the end, so the child
// is stepping once either has content.
bool stepping(const std::string& cert) {
    const fs::path path(cert);
    // Appended, not concatenated: GCC 12 warns falsely (-Wrestrict) on
    // "." + string + "...".
    std::string partial = ".";
    partial.append(path.filename().string()).append(".partial");
    return wait_until([&] {
        std::error_code ignored;
        for (const auto& entry : fs::directory_iterator(path.parent_path(), ignored)) {
            const std::string name = entry.path().filename().string();
            if ((entry.path() == path || name.starts_with(partial)) &&
                fs::file_size(entry.path(), ignored) > 0 && !ignored)
                return true;
        }
        return false;
    });
}

// Waits for the child to end (killing it if it does not within the guard)
// and returns its exit status, or -1 if it did not exit normally.
int exit_status(pid_t child) {
    int status = 0;
    if (!wait_until([&] { return waitpid(child, &status, WNOHANG) == child; })) {
        kill(child, SIGKILL);
        waitpid(child, &status, 0);
        FAIL_CHECK("the child did not end within a minute");
        return -1;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

TEST_CASE("a monitor stops each simulation engine with the reflections it performed", "[limits]") {
    const Scene scene = long_orbit(40);
    for (const Engine engine : {Engine::lattice, Engine::reference}) {
        for (const Shooter shooter : {Shooter::automatic, Shooter::grid, Shooter::bvh}) {
            CAPTURE(static_cast<int>(engine), static_cast<int>(shooter));
            StopAfterPolls monitor(5);
            std::ostringstream text;
            CertificateWriter writer(text, scene);
            SolveOptions options;
            options.engine = engine;
            options.shooter = shooter;
            options.monitor = &monitor;
            writer.attach(options);
            const Answer answer = solve(scene, options);
            writer.finish(answer);
            CHECK(monitor.polls() == 5);
            REQUIRE(answer.reason == Reason::limit);
            CHECK(answer.limit == Limit::interrupt);
            CHECK(answer.reflections == Integer(static_cast<unsigned long>(monitor.last())));
            // The certificate holds exactly those steps, each one checked.
            std::istringstream in(text.str());
            const Verdict verdict = verify_certificate(scene, in);
            CHECK_FALSE(verdict.valid);
            CHECK(verdict.message.find("partial") != std::string::npos);
            CHECK(verdict.message.find(answer.reflections.get_str()) != std::string::npos);
        }
    }
}

TEST_CASE("a stop while a certificate lists the exchange leaves no exchange cut short",
          "[limits]") {
    // A box with 20,000-digit sides: its exchange's listing (every number
    // in decimal) runs to some 260 kB; at 10^6 digits it takes seconds.
    const std::string side = "1" + std::string(20000, '0');
    const Scene scene = read_scene("dim 2\nmirror x 0 y 0 " + side + "\nmirror x " + side +
                                   " y 0 " + side + "\nmirror y 0 x 0 " + side + "\nmirror y " +
                                   side + " x 0 " + side + "\nray 1 0 1 1\ntarget 0 1\n");
    const std::optional<IntervalExchange> exchange = exchange_of(scene);
    REQUIRE(exchange);
    for (const bool stop : {false, true}) {
        CAPTURE(stop);
        std::ostringstream text;
        CertificateWriter writer(text, scene);
        SolveOptions options;
        writer.attach(options);
        REQUIRE(options.induction_observer);
        int asked = 0;
        const bool whole = options.induction_observer->begin(*exchange, [&] {
            ++asked;
            return stop;
        });
        // Asked while it lists, at the first 64 KiB: the stop lands inside.
        CHECK(asked >= 1);
        CHECK(whole == !stop);
        // Stopped, nothing of the exchange is written, not even its method:
        // the certificate stays a path prefix, which verify reads as partial.
        CHECK((text.str().find("method induction\n") != std::string::npos) == !stop);
        CHECK((text.str().find("\npiece ") != std::string::npos) == !stop);
        if (!stop) CHECK(text.str().size() > 200'000);
    }
}

TEST_CASE("a monitor stops the graph engine", "[limits][slow]") {
    // Some 2^12 points a face: about 2 * 10^5 states, polled every 1024.
    const Scene scene = long_orbit(6);
    StopAfterPolls monitor(1);
    SolveOptions options;
    options.engine = Engine::graph;
    options.monitor = &monitor;
    const Answer answer = solve(scene, options);
    CHECK(answer.reason == Reason::limit);
    CHECK(answer.limit == Limit::interrupt);
    CHECK(answer.reflections == 0);
}

TEST_CASE("a monitor that never stops changes no answer", "[limits]") {
    // Long enough (a period of 97536) that the run is cut into chunks.
    const Scene scene = long_orbit(7);
    StopAfterPolls never(-1);
    SolveOptions watched;
    watched.monitor = &never;
    const Answer plain = solve(scene), with_monitor = solve(scene, watched);
    CHECK(never.polls() > 1);
    CHECK(with_monitor.reason == Reason::cycle);
    CHECK(with_monitor.reflections == plain.reflections);
    // A step cap inside a chunk is still exact.
    StopAfterPolls never_again(-1);
    watched.monitor = &never_again;
    watched.max_steps = 12345;
    const Answer capped = solve(scene, watched);
    CHECK(capped.reason == Reason::limit);
    CHECK(capped.limit == Limit::steps);
    CHECK(capped.reflections == 12345);
}

TEST_CASE("solve --timeout stops a long run with limit time", "[limits][cli][slow]") {
    const fs::path dir = fresh_dir("timeout");
    const std::string scene = scene_file(dir, long_orbit(40));
    const auto r = run_cli("solve --json --timeout 0.5 '" + scene + "' --certificate '" +
                           (dir / "c.cert").string() + "'");
    CHECK(r.status == 3);
    CHECK(r.err.empty());
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["answer"] == "unknown");
    CHECK(j["reason"] == "limit");
    CHECK(j["limit"] == "time");
    REQUIRE(j["reflections"].is_number_unsigned());
    CHECK(j["reflections"].get<std::uint64_t>() > 0);
    const auto v = run_cli("verify '" + scene + "' '" + (dir / "c.cert").string() + "'");
    CHECK(v.status == 1);
    CHECK(v.out.find("partial") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("SIGTERM and SIGINT stop solve with the usual output and a complete certificate",
          "[limits][cli]") {
    for (const int signal : {SIGTERM, SIGINT}) {
        CAPTURE(signal);
        const fs::path dir = fresh_dir("signal" + std::to_string(signal));
        const std::string scene = scene_file(dir, long_orbit(40));
        const std::string cert = (dir / "c.cert").string(), out = (dir / "out").string(),
                          err = (dir / "err").string();
        const pid_t child = start_solve(scene, cert, out, err);
        REQUIRE(child > 0);
        // Ask it to stop once it is well into stepping.
        REQUIRE(stepping(cert));
        REQUIRE(kill(child, signal) == 0);
        CHECK(exit_status(child) == 3);
        CHECK(slurp(err).empty());
        const nlohmann::json j = nlohmann::json::parse(slurp(out));
        CHECK(j["answer"] == "unknown");
        CHECK(j["limit"] == "interrupt");
        CHECK(j["reflections"].get<std::uint64_t>() > 0);
        const std::string text = slurp(cert);
        CHECK(text.size() > 10);
        CHECK(text.substr(text.size() - 13) == "\npartial\nend\n");
        const auto v = run_cli("verify '" + scene + "' '" + cert + "'");
        CHECK(v.status == 1);
        CHECK(v.out.find("partial certificate: " + j["reflections"].dump()) != std::string::npos);
        fs::remove_all(dir);
    }
}

#ifndef ORTHORAY_SANITIZE // sanitizers reserve terabytes of address space and abort on failure
TEST_CASE("solve --max-memory turns running out of memory into limit memory",
          "[limits][cli][slow]") {
    // The state graph of this box has 4 * 2 * (120000 + 120001) states, just
    // under the graph engine's cap, in map entries of some 100 bytes: far
    // beyond 20 MB.
    const fs::path dir = fresh_dir("memory");
    BoxFamily box;
    box.sides = {120000, 119999};
    box.target = BoxFamily::Target::far;
    const std::string scene = scene_file(dir, generate_box(box).scene);
    const auto r = run_cli("solve --json --engine graph --max-memory 20 '" + scene + "'");
    CHECK(r.status == 3);
    CHECK(r.err.empty());
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["answer"] == "unknown");
    CHECK(j["limit"] == "memory");
    fs::remove_all(dir);
}
#endif

TEST_CASE("limit options reject what is not a limit", "[limits][cli][slow]") {
    for (const std::string bad : {"--timeout 0", "--timeout -1", "--timeout x", "--timeout 1e300",
                                  "--max-memory 0", "--max-memory lots"}) {
        CAPTURE(bad);
        const auto r =
            run_cli("solve " + bad + " '" +
                    orthoray::test::source_path("instances/2d/box-corner-3x5.scene") + "'");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK_FALSE(r.err.empty());
    }
}

namespace {

// Reads what the terminal `terminal` receives until the child side closes
// (read fails with EIO then), or, with `until`, until that text has come.
std::string read_terminal(int terminal, const std::string& until = {}) {
    std::string seen;
    char buffer[4096];
    while (until.empty() || seen.find(until) == std::string::npos) {
        pollfd ready{terminal, POLLIN, 0};
        if (poll(&ready, 1, 60'000) <= 0) { // the guard against a hang
            FAIL_CHECK("the terminal stayed silent for a minute");
            break;
        }
        const ssize_t n = read(terminal, buffer, sizeof buffer);
        if (n <= 0) break;
        seen.append(buffer, static_cast<std::size_t>(n));
    }
    return seen;
}

} // namespace

TEST_CASE("a long run shows a progress line on a terminal only, and erases it",
          "[limits][cli][slow]") {
    // Three runs: stderr to a file, to a terminal with --quiet, and to a
    // terminal. The first two are stepping before the third starts, so when
    // the third draws its line (after its first second) both are past the
    // moment they would have drawn theirs; then all three are interrupted.
    const fs::path dir = fresh_dir("progress");
    const std::string scene = scene_file(dir, long_orbit(40));
    int quiet_terminal = -1, quiet_side = -1, terminal = -1, child_side = -1;
    REQUIRE(openpty(&quiet_terminal, &quiet_side, nullptr, nullptr, nullptr) == 0);
    REQUIRE(openpty(&terminal, &child_side, nullptr, nullptr, nullptr) == 0);
    const std::string err = (dir / "err").string();
    const pid_t to_file = start_solve(scene, (dir / "file.cert").string(), "", err);
    const pid_t quiet =
        start_solve(scene, (dir / "quiet.cert").string(), "", "", quiet_side, "--quiet");
    REQUIRE(to_file > 0);
    REQUIRE(quiet > 0);
    close(quiet_side);
    CHECK(stepping((dir / "file.cert").string()));
    CHECK(stepping((dir / "quiet.cert").string()));
    const pid_t shown = start_solve(scene, (dir / "shown.cert").string(), "", "", child_side);
    REQUIRE(shown > 0);
    close(child_side);

    std::string seen = read_terminal(terminal, "states bound");
    for (const pid_t child : {to_file, quiet, shown}) kill(child, SIGINT);
    seen += read_terminal(terminal);
    const std::string quiet_seen = read_terminal(quiet_terminal);
    close(terminal);
    close(quiet_terminal);
    for (const pid_t child : {to_file, quiet, shown}) CHECK(exit_status(child) == 3);

    CHECK(seen.find(" reflections, ") != std::string::npos);
    CHECK(seen.find("/s, ") != std::string::npos);
    CHECK(seen.find("states bound") != std::string::npos);
    // The share of the bound as a percentage with one decimal, or <0.1%.
    CHECK(std::regex_search(
        seen, std::regex(R"(, (<0\.1|[0-9]+\.[0-9])% of the [0-9^+]+ states bound)")));
    // The last thing written returns to the line's start and clears it.
    REQUIRE(seen.size() >= 4);
    CHECK(seen.substr(seen.size() - 4) == "\r\033[K");
    CHECK(quiet_seen.empty());
    CHECK(slurp(err).empty());
    fs::remove_all(dir);
}

namespace {

// `orthoray ARGS...` with stdout to `out` and stderr to the descriptor
// `err_fd` or else the file `err`.
pid_t start_command(const std::vector<std::string>& args, const std::string& out,
                    const std::string& err, int err_fd = -1) {
    const pid_t child = fork();
    if (child != 0) return child;
    const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (err_fd < 0) err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out_fd, STDOUT_FILENO);
    dup2(err_fd, STDERR_FILENO);
    closefrom(3);
    std::vector<char*> argv{const_cast<char*>(ORTHORAY_CLI)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(ORTHORAY_CLI, argv.data());
    _exit(127);
}

// Writes `text` into the FIFO `path` once its reader has opened it.
void feed(const fs::path& path, const std::string& text) {
    const int fd = open(path.c_str(), O_WRONLY);
    REQUIRE(fd >= 0);
    CHECK(write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()));
    close(fd);
}

} // namespace

TEST_CASE("bounds and convert show a progress line on a terminal only, and erase it",
          "[limits][cli][slow]") {
    // Each reads a FIFO that gets its writer only once the terminal shows
    // the line (after the first second), so the run is long enough without
    // a large scene. Per command: stderr to a file, to a terminal with
    // --quiet, and to a terminal; the first two start first, so they are
    // past their first second too when the line shows.
    const fs::path dir = fresh_dir("phase-progress");
    const std::string scene =
        slurp(orthoray::test::source_path("instances/2d/box-corner-3x5.scene"));
    for (const std::string command : {"bounds", "convert"}) {
        INFO(command);
        std::vector<fs::path> fifos;
        for (const char* name : {"file", "quiet", "shown"}) {
            fifos.push_back(dir / (command + "-" + name + ".scene"));
            REQUIRE(mkfifo(fifos.back().c_str(), 0600) == 0);
        }
        auto args = [&](std::size_t i, bool quiet) {
            std::vector<std::string> a{command, fifos[i].string()};
            if (command == "convert")
                a.push_back((dir / (command + std::to_string(i) + ".json")).string());
            if (quiet) a.push_back("--quiet");
            return a;
        };
        int quiet_terminal = -1, quiet_side = -1, terminal = -1, child_side = -1;
        REQUIRE(openpty(&quiet_terminal, &quiet_side, nullptr, nullptr, nullptr) == 0);
        REQUIRE(openpty(&terminal, &child_side, nullptr, nullptr, nullptr) == 0);
        const std::string out = (dir / "out").string(), err = (dir / "err").string();
        const pid_t to_file = start_command(args(0, false), out + "0", err);
        const pid_t quiet = start_command(args(1, true), out + "1", "", quiet_side);
        close(quiet_side);
        const pid_t shown = start_command(args(2, false), out + "2", "", child_side);
        close(child_side);
        std::string seen = read_terminal(terminal, " s");
        CHECK(seen.find("orthoray " + command + ": reading ") != std::string::npos);
        for (const fs::path& fifo : fifos) feed(fifo, scene);
        seen += read_terminal(terminal);
        const std::string quiet_seen = read_terminal(quiet_terminal);
        close(terminal);
        close(quiet_terminal);
        for (const pid_t child : {to_file, quiet, shown}) CHECK(exit_status(child) == 0);
        // The last thing written to the terminal erases the line.
        REQUIRE(seen.size() >= 4);
        CHECK(seen.substr(seen.size() - 4) == "\r\033[K");
        CHECK(quiet_seen.empty());
        CHECK(slurp(err).empty());
        if (command == "bounds")
            for (const char* n : {"0", "1", "2"})
                CHECK(slurp(out + n).find("refined states   32") != std::string::npos);
        else
            for (std::size_t i = 0; i < 3; ++i)
                CHECK(slurp(dir / ("convert" + std::to_string(i) + ".json")).find("\"dim\"") !=
                      std::string::npos);
    }
    fs::remove_all(dir);
}

TEST_CASE("puzzle solve shows its search nodes on a terminal, and erases the line",
          "[limits][cli][puzzle][slow]") {
    // An open 10 x 10 grid whose points lie on the laser's first path: --all
    // has millions of placements to count, and --timeout ends it after the
    // line has shown (exit 3, nothing proven).
    const fs::path dir = fresh_dir("puzzle-progress");
    std::string level = "GRID START\n";
    for (int row = 0; row < 10; ++row) level += "o o o o o o o o o o\n";
    level += "GRID STOP\nA 6\nC 2\nL 0 1 1 1\nP 2 3\nP 4 5\n";
    const fs::path file = dir / "open.bff";
    { std::ofstream(file) << level; }
    int terminal = -1, child_side = -1;
    REQUIRE(openpty(&terminal, &child_side, nullptr, nullptr, nullptr) == 0);
    const std::string out = (dir / "out").string();
    const pid_t child =
        start_command({"puzzle", "solve", file.string(), "--all", "--jobs", "1", "--timeout", "2"},
                      out, "", child_side);
    close(child_side);
    const std::string seen = read_terminal(terminal);
    close(terminal);
    CHECK(exit_status(child) == 3);
    CHECK(seen.find("orthoray puzzle solve: searching " + file.string() + ", ") !=
          std::string::npos);
    CHECK(seen.find(" nodes, ") != std::string::npos);
    REQUIRE(seen.size() >= 4);
    CHECK(seen.substr(seen.size() - 4) == "\r\033[K");
    CHECK(slurp(out).find("reason       limit (--timeout reached)") != std::string::npos);
    fs::remove_all(dir);
}
