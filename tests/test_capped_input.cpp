// Inputs that never end, directories and FIFOs (docs/limits.md): every
// reader goes through the capped reader of lib/src/io/input_file.cpp, so
// each ends with one FILE:LINE:COL message and exit 2, or, for a signal while
// a FIFO waits for its writer, as interrupted with exit 3.
#include "support/cli_checks.hpp"
#include "support/run_cli.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include "certify/certificate_reader.hpp"
#include "orthoray/parse.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <streambuf>
#include <string>
#include <sys/stat.h>
#include <thread>

using namespace orthoray;
using namespace orthoray::test;

namespace {

const std::string box = instance("2d/box-corner-3x5.scene");

// Bad input (cli_checks.hpp) whose one line says `message`.
void require_bad_input(const CliResult& r, const std::string& message) {
    require_bad_input(r);
    CHECK(r.err.find(message) != std::string::npos);
}

// An endless stream of one byte, like /dev/zero, without the file system.
class Endless : public std::streambuf {
public:
    explicit Endless(char byte) { std::fill(std::begin(buffer_), std::end(buffer_), byte); }

protected:
    int_type underflow() override {
        setg(buffer_, buffer_, buffer_ + sizeof buffer_);
        return traits_type::to_int_type(buffer_[0]);
    }

private:
    char buffer_[1 << 16];
};

} // namespace

TEST_CASE("a certificate line past the cap is bad input at its line", "[capped_input]") {
    for (const char byte : {'\0', 'x', '{'}) {
        CAPTURE(int(byte));
        Endless endless(byte);
        std::istream in(&endless);
        const std::string name = "endless.cert"; // the reader keeps a reference
        certify::CertificateReader reader(in, name);
        try {
            reader.next();
            FAIL("an endless line was accepted");
        } catch (const InputError& e) {
            CHECK(e.line() == 1);
            CHECK(e.column() == static_cast<int>(input_cap_bytes) + 1);
            CHECK(e.message().find("found more than 256 MiB in one line") == 0);
        }
    }
}

TEST_CASE("certificate lines of every length around the reader's chunk read back whole",
          "[capped_input]") {
    // The reader takes a line in chunks of 4096 bytes; a line of a chunk's
    // size, one less or one more must not be cut or joined.
    for (const std::size_t length : {4094, 4095, 4096, 4097, 8191, 8192}) {
        CAPTURE(length);
        const std::string word(length - 2, '7');
        std::istringstream in("# " + word + "\northoray-certificate 1\n" + "# " + word);
        const std::string name = "c";
        certify::CertificateReader reader(in, name);
        REQUIRE(reader.next());
        CHECK(reader.keyword() == "orthoray-certificate");
        CHECK_FALSE(reader.next());
    }
}

TEST_CASE("/dev/zero as a scene or a certificate: exit 2, found more than 256 MiB",
          "[capped_input][cli]") {
    require_bad_input(run_cli("solve /dev/zero"), "/dev/zero:1:268435457: found more than 256 MiB");
    require_bad_input(run_cli("verify " + quote(box) + " /dev/zero"),
                      "/dev/zero:1:268435457: found more than 256 MiB in one line");
    const TempDir dir;
    require_bad_input(
        run_cli("render " + quote(box) + " --certificate /dev/zero -o " + quote(dir.path("z.svg"))),
        "/dev/zero:1:268435457: found more than 256 MiB in one line");
    CHECK_FALSE(std::filesystem::exists(dir.path("z.svg")));
}

TEST_CASE("a scene past the cap names the line and column where it crosses it",
          "[capped_input][cli]") {
    const TempDir dir;
    const std::string path = dir.path("huge.scene");
    {
        std::ofstream out(path, std::ios::binary);
        // 1024 bytes; appended, as GCC 12 at -O3 warns falsely on `+` (-Warray-bounds).
        const std::string line = std::string("# ").append(1021, 'c').append("\n");
        for (std::size_t i = 0; i < (input_cap_bytes >> 10); ++i) out << line;
        out << "dim 2\n";
    }
    // The cap is crossed at the first byte of line 262145.
    require_bad_input(run_cli("bounds " + quote(path)),
                      "huge.scene:262145:1: found more than 256 MiB");
}

TEST_CASE("a directory as a scene or a certificate is bad input", "[capped_input][cli]") {
    const TempDir dir;
    const std::string folder = dir.path("folder");
    std::filesystem::create_directory(folder);
    require_bad_input(run_cli("solve " + quote(folder)), "folder:1:1: found a directory");
    require_bad_input(run_cli("verify " + quote(box) + " " + quote(folder)),
                      "folder:1:1: found a directory");
    require_bad_input(run_cli("render " + quote(box) + " --certificate " + quote(folder) + " -o " +
                              quote(dir.path("d.svg"))),
                      "folder:1:1: found a directory");
    CHECK_FALSE(std::filesystem::exists(dir.path("d.svg")));
}

TEST_CASE("SIGTERM while solve waits for a FIFO's writer: interrupted, exit 3",
          "[capped_input][cli]") {
    const TempDir dir;
    const std::string fifo = dir.path("scene.fifo");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const pid_t child = spawn_cli({"solve", "--json", fifo}, dir.path("out"), dir.path("err"));
    REQUIRE(child > 0);
    // Reading a FIFO waits until a writer comes; none will. Once the FIFO
    // is open, solve is waiting on it.
    REQUIRE(wait_until_open(child, fifo));
    REQUIRE(kill(child, SIGTERM) == 0);
    CHECK(wait_at_most(child, 60) == 3);
    const nlohmann::json j = nlohmann::json::parse(slurp(dir.path("out")));
    CHECK(j["answer"] == "unknown");
    CHECK(j["limit"] == "interrupt");
    CHECK(j["arithmetic"] == "none");
}
