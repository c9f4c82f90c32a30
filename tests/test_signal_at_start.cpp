// Every command handles SIGINT and SIGTERM from main()'s first line
// (docs/limits.md): until a command sets up its own handling, a signal stops
// it at once with exit 3 and nothing written, never by the default action
// (exit 130 or 143, a temporary file left behind); once its result is
// decided, a signal waits for it to be written whole.
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

using namespace orthoray::test;
namespace fs = std::filesystem;

TEST_CASE("generate stops at once on a signal while it builds and writes nothing",
          "[stop_requests][cli]") {
    const TempDir dir;
    const std::string scene = dir.path("big.scene");
    for (const int signal : {SIGINT, SIGTERM}) {
        CAPTURE(signal);
        // A million 3D mirrors take seconds to build; the signal comes as
        // soon as the process handles it, long before.
        const pid_t child = spawn_cli({"generate", "random", "--dim", "3", "--mirrors", "1000000",
                                       "--bits", "40", "-o", scene},
                                      dir.path("out"), dir.path("err"));
        REQUIRE(wait_until_catching(child, signal));
        REQUIRE(kill(child, signal) == 0);
        const std::optional<int> status = wait_at_most(child, 60);
        REQUIRE(status);
        CHECK(*status == 3);
        CHECK(slurp(dir.path("err")) == "orthoray: stopped: interrupted\n");
        CHECK(slurp(dir.path("out")).empty());
    }
    // Nothing but the two captured streams: no scene, no temporary file.
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path(""))) {
        CAPTURE(entry.path());
        CHECK((entry.path().filename() == "out" || entry.path().filename() == "err"));
        ++files;
    }
    CHECK(files == 2);
}

TEST_CASE("a signal while decided help text waits in a full pipe lets it finish whole",
          "[stop_requests][cli]") {
    const TempDir dir;
    const std::string expected = run_cli("generate --help").out;
    // The pipe holds one page, less than the help text, so the child blocks
    // in write() with the text half out when the signal comes.
    REQUIRE(expected.size() > 4096);
    const std::string fifo = dir.path("help.fifo");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const int reader = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
    REQUIRE(reader >= 0);
    REQUIRE(fcntl(reader, F_SETPIPE_SZ, 4096) == 4096);
    const pid_t child = spawn_cli({"generate", "--help"}, fifo, dir.path("err"));
    REQUIRE(wait_until_catching(child, SIGTERM));
    REQUIRE(wait_until_queued(child, reader, 4096));
    REQUIRE(kill(child, SIGTERM) == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(50)); // let it land, if it would
    // From here reads wait for the child: they end when it closes its end,
    // by exiting or by dying.
    REQUIRE(fcntl(reader, F_SETFL, 0) == 0);
    std::string got;
    char buffer[4096];
    for (ssize_t n; (n = read(reader, buffer, sizeof buffer)) > 0;)
        got.append(buffer, static_cast<std::size_t>(n));
    close(reader);
    const std::optional<int> status = wait_at_most(child, 60);
    REQUIRE(status);
    CHECK(*status == 0);
    CHECK(got == expected);
    CHECK(slurp(dir.path("err")).empty());
}
