// Limits (docs/limits.md): a RunMonitor stops every engine with an exact
// count of the reflections performed and a certificate that verifies as
// partial; on the command line --timeout, --max-memory, SIGINT and SIGTERM
// end a long run with answer unknown, the limit named, and exit status 3.
#include "support/run_cli.hpp"

#include "orthoray/certificate.hpp"
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
#include <pty.h>
#include <sstream>
#include <string>
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

TEST_CASE("a monitor stops the graph engine", "[limits]") {
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

TEST_CASE("solve --timeout stops a long run with limit time", "[limits][cli]") {
    const fs::path dir = fresh_dir("timeout");
    const std::string scene = scene_file(dir, long_orbit(40));
    const auto begin = std::chrono::steady_clock::now();
    // Past the second after which a terminal would get a progress line:
    // stderr here is a file, so it must stay empty.
    const auto r = run_cli("solve --json --timeout 1.3 '" + scene + "' --certificate '" +
                           (dir / "c.cert").string() + "'");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    CHECK(r.status == 3);
    CHECK(r.err.empty());
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["answer"] == "unknown");
    CHECK(j["reason"] == "limit");
    CHECK(j["limit"] == "time");
    REQUIRE(j["reflections"].is_number_unsigned());
    CHECK(j["reflections"].get<std::uint64_t>() > 0);
    CHECK(seconds < 10); // generous: the run alone would take hours
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
        const pid_t child = fork();
        REQUIRE(child >= 0);
        if (child == 0) {
            const int out_fd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            dup2(out_fd, STDOUT_FILENO);
            dup2(err_fd, STDERR_FILENO);
            execl(ORTHORAY_CLI, ORTHORAY_CLI, "solve", "--json", scene.c_str(), "--certificate",
                  cert.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        // Let it get well into stepping, then ask it to stop.
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        const auto sent = std::chrono::steady_clock::now();
        REQUIRE(kill(child, signal) == 0);
        int status = 0;
        REQUIRE(waitpid(child, &status, 0) == child);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
        INFO("stopped " << seconds * 1e3 << " ms after the signal");
        REQUIRE(WIFEXITED(status));
        CHECK(WEXITSTATUS(status) == 3);
        CHECK(seconds < 2); // the promise is 100 ms; loaded test machines get slack
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
TEST_CASE("solve --max-memory turns running out of memory into limit memory", "[limits][cli]") {
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

TEST_CASE("limit options reject what is not a limit", "[limits][cli]") {
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

// Runs `solve --timeout 1.6 SCENE [extra]` with stderr on a pseudo-terminal
// and returns what the terminal received.
std::string terminal_stderr(const std::string& scene, const char* extra) {
    int terminal = -1, child_side = -1;
    REQUIRE(openpty(&terminal, &child_side, nullptr, nullptr, nullptr) == 0);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, STDOUT_FILENO);
        dup2(child_side, STDERR_FILENO);
        close(terminal);
        execl(ORTHORAY_CLI, ORTHORAY_CLI, "solve", scene.c_str(), "--timeout", "1.6", extra,
              static_cast<char*>(nullptr));
        _exit(127);
    }
    close(child_side);
    std::string seen;
    char buffer[4096];
    for (ssize_t n; (n = read(terminal, buffer, sizeof buffer)) > 0;) seen.append(buffer, n);
    close(terminal);
    int status = 0;
    waitpid(child, &status, 0);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 3);
    return seen;
}

} // namespace

TEST_CASE("a long run on a terminal shows a progress line and erases it", "[limits][cli]") {
    const fs::path dir = fresh_dir("progress");
    const std::string scene = scene_file(dir, long_orbit(40));
    const std::string shown = terminal_stderr(scene, "--json");
    CHECK(shown.find(" reflections, ") != std::string::npos);
    CHECK(shown.find("/s, ") != std::string::npos);
    CHECK(shown.find("states bound") != std::string::npos);
    // The last thing written returns to the line's start and clears it.
    REQUIRE(shown.size() >= 4);
    CHECK(shown.substr(shown.size() - 4) == "\r\033[K");
    CHECK(terminal_stderr(scene, "--quiet").empty());
    fs::remove_all(dir);
}
