// Every write is checked (docs/limits.md): a full device, a file size limit
// or a closed pipe is reported with exit status 5, outputs appear only
// complete (temporary file, then rename), and an output that would
// overwrite an input or has no name is refused (exit 2).
#include "support/run_cli.hpp"
#include "support/skip_test.hpp"
#include "support/spawn_cli.hpp"
#include "support/test_files.hpp"

#include "orthoray/generate.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

using namespace orthoray;
using namespace orthoray::test;
namespace fs = std::filesystem;

namespace {

const std::string box = instance("2d/box-corner-3x5.scene");

// A scene whose ray runs for hours: about 3 * 4^40 reflections.
std::string long_scene(const TempDir& dir) {
    return dir.write("long.scene",
                     write_generated(generate_coprime_cuboid(40, BoxFamily::Target::far)));
}

// The files in `dir` other than `keep`.
std::vector<std::string> leftovers(const std::string& dir, const std::vector<std::string>& keep) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (std::find(keep.begin(), keep.end(), name) == keep.end()) names.push_back(name);
    }
    return names;
}

} // namespace

TEST_CASE("a write to /dev/full is reported, exit 5", "[output_writes][cli]") {
    const auto solve = run_cli("solve " + quote(box) + " --certificate /dev/full");
    CHECK(solve.status == 5);
    CHECK(solve.err == "orthoray: cannot write the certificate '/dev/full': No space left on "
                       "device\n");
    const auto generate = run_cli("generate box --sides 3 5 -o /dev/full");
    CHECK(generate.status == 5);
    CHECK(generate.err.find("cannot write the scene '/dev/full'") != std::string::npos);
    const auto convert = run_cli("convert " + quote(box) + " /dev/full --to json");
    CHECK(convert.status == 5);
    const auto render = run_cli("render " + quote(box) + " -o /dev/full");
    CHECK(render.status == 5);
}

TEST_CASE("standard output on /dev/full or a closed pipe is a failed write, exit 5",
          "[output_writes][cli]") {
    // verify prints its verdict on a certificate cut short after the header.
    const TempDir dir;
    const std::string cut = dir.write("cut.cert", "orthoray-certificate 1\ndim 2\n");
    for (const std::string& command : std::vector<std::string>{
             "solve \"" + box + "\"", "verify \"" + box + "\" \"" + cut + "\"",
             "pieces \"" + box + "\"", "bounds \"" + box + "\"", "generate random --mirrors 20",
             "--help", "solve --help", "--version"}) {
        CAPTURE(command);
        const ShellResult full = run_shell("$ORTHORAY " + command + " >/dev/full");
        CHECK(full.status == 5);
        CHECK(full.err.find("cannot write to standard output") != std::string::npos);
    }
    // A reader that stops early: without SIGPIPE ignored the writer would die
    // of it (status 141) instead of saying so.
    const ShellResult pipe = run_shell(
        "$ORTHORAY generate random --mirrors 200000 | head -c 1 >/dev/null; exit ${PIPESTATUS[0]}");
    CHECK(pipe.status == 5);
    // The reason is told even when the failing write happened inside the
    // stream's buffering and errno was gone by the final flush.
    CHECK(pipe.err == "orthoray: cannot write to standard output: Broken pipe\n");
}

TEST_CASE("ulimit -f: the certificate is not left cut, exit 5", "[output_writes][cli]") {
    const TempDir dir;
    const std::string scene = long_scene(dir);
    const std::string cert = dir.path("c.cert");
    // 8 blocks of 512 bytes; the certificate of 10^5 reflections is larger.
    const ShellResult r = run_shell("ulimit -f 8; $ORTHORAY solve \"" + scene +
                                    "\" --max-steps 100000 --certificate \"" + cert + "\"");
    CHECK(r.status == 5);
    CHECK(r.err.find("cannot write the certificate") != std::string::npos);
    CHECK(r.err.find("File too large") != std::string::npos);
    CHECK_FALSE(fs::exists(cert));
    CHECK(leftovers(dir.path(""), {"long.scene"}).empty());
}

TEST_CASE("two outputs of one command naming the same file are refused before any work",
          "[output_writes][cli]") {
    const TempDir dir;
    const std::string scene =
        dir.write("lit.scene", "dim 2\nsplitter x 0 y 0 100 reflectance 1/2 transmittance 1/2\n"
                               "ray 1/2 0 1 1 intensity 1000\ntarget 1/2 4\n");
    const std::string same = dir.path("same.txt");
    for (const std::string& other : {same, dir.path("./same.txt")}) {
        const auto realistic =
            run_cli("realistic --from-scene " + quote(scene) + " --write-model " + quote(same) +
                    " --certificate " + quote(other));
        CHECK(realistic.status == 2);
        CHECK(realistic.out.empty());
        CHECK(realistic.err.find("naming the same file as the model") != std::string::npos);
        const auto render =
            run_cli("render " + quote(scene) + " -o " + quote(same) + " --html " + quote(other));
        CHECK(render.status == 2);
        CHECK(render.err.find("naming the same file as the picture") != std::string::npos);
    }
    const auto puzzle =
        run_cli("puzzle solve " + quote(instance("puzzles/reflect-4x4.bff")) + " -o " +
                quote(same) + " --render " + quote(dir.path("./same.txt")));
    CHECK(puzzle.status == 2);
    CHECK(puzzle.err.find("naming the same file as the solved level") != std::string::npos);
    CHECK_FALSE(fs::exists(same));
    // An output that cannot be created is found before the work, and the
    // other output is not left behind.
    const std::string model = dir.path("m.realistic");
    const auto missing = run_cli("realistic --from-scene " + quote(scene) + " --write-model " +
                                 quote(model) + " --certificate " + quote(dir.path("no/c.cert")));
    CHECK(missing.status == 2);
    CHECK(missing.err.find("cannot write the certificate") != std::string::npos);
    CHECK_FALSE(fs::exists(model));
    // convert checks its output before the reading (a 10^6-digit scene reads
    // for seconds): here the input does not even exist.
    const auto convert =
        run_cli("convert " + quote(dir.path("absent.scene")) + " " + quote(dir.path("no/x.json")));
    CHECK(convert.status == 2);
    CHECK(convert.err.find("cannot write the scene") != std::string::npos);
    // So does puzzle scene.
    const auto scene_of = run_cli("puzzle scene " + quote(dir.path("absent.bff")) + " -o " +
                                  quote(dir.path("no/x.scene")));
    CHECK(scene_of.status == 2);
    CHECK(scene_of.err.find("cannot write the scene") != std::string::npos);
    CHECK(leftovers(dir.path(""), {"lit.scene"}).empty());
}

TEST_CASE("an output is refused when it has no name or names an input", "[output_writes][cli]") {
    const TempDir dir;
    const std::string scene = dir.write("box.scene", slurp(box));
    const auto empty = run_cli("solve " + quote(scene) + " --certificate ''");
    CHECK(empty.status == 2);
    CHECK(empty.out.empty());
    CHECK(empty.err.find("--certificate: found an empty value, expected a file name") !=
          std::string::npos);
    for (const std::string& same : {scene, dir.path("./box.scene")}) {
        const auto r = run_cli("solve " + quote(scene) + " --certificate " + quote(same));
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.find("naming the input") != std::string::npos);
    }
    fs::create_hard_link(scene, dir.path("link.scene"));
    CHECK(run_cli("convert " + quote(scene) + " " + quote(dir.path("link.scene"))).status == 2);
    CHECK(run_cli("render " + quote(scene) + " -o " + quote(scene)).status == 2);
    CHECK(slurp(scene) == slurp(box)); // untouched
    CHECK(run_cli("generate box -o ''").status == 2);
    // "-" would be a file of that name, in the working directory.
    for (const std::string& args :
         {"solve " + quote(scene) + " --certificate -",
          std::string("generate box --sides 3 5 -o -"), "batch " + quote(scene) + " -o -",
          "convert " + quote(scene) + " -"}) {
        const auto dash = run_cli(args);
        CHECK(dash.status == 2);
        CHECK(dash.out.empty());
        CHECK(dash.err.find("found '-' for the ") != std::string::npos);
        CHECK(dash.err.find("expected a file name (/dev/stdout for standard output)") !=
              std::string::npos);
        CHECK(!fs::exists("-"));
    }
}

TEST_CASE("solve with --engine graph and --certificate is a usage error, and writes nothing",
          "[output_writes][cli]") {
    const TempDir dir;
    const auto r =
        run_cli("solve " + quote(box) + " --engine graph --certificate " + quote(dir.path("g")));
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("--engine graph") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path("g")));
}

TEST_CASE("kill -9 while a certificate is written leaves no file verify could take as complete",
          "[output_writes][cli]") {
    const TempDir dir;
    const std::string scene = long_scene(dir);
    const std::string cert = dir.path("c.cert");
    for (const int milliseconds : {5, 50, 300}) {
        CAPTURE(milliseconds);
        const pid_t child =
            spawn_cli({"solve", scene, "--certificate", cert}, dir.path("out"), dir.path("err"));
        REQUIRE(child > 0);
        std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
        REQUIRE(kill(child, SIGKILL) == 0);
        CHECK(wait_for(child) == -SIGKILL);
        // Only the temporary file may remain, under a name of its own.
        CHECK_FALSE(fs::exists(cert));
        for (const std::string& name : leftovers(dir.path(""), {"long.scene", "out", "err"})) {
            CHECK(name.rfind(".c.cert.partial-", 0) == 0);
            fs::remove(dir.path(name));
        }
    }
    // A run stopped by a limit still leaves its partial certificate.
    const auto limited =
        run_cli("solve " + quote(scene) + " --max-steps 1000 --certificate " + quote(cert));
    CHECK(limited.status == 3);
    const auto verdict = run_cli("verify " + quote(scene) + " " + quote(cert));
    CHECK(verdict.status == 1);
    CHECK(verdict.out.find("partial certificate: 1000 reflections") != std::string::npos);
}

TEST_CASE("a full file system: the write error is reported and the old file kept",
          "[output_writes][cli]") {
    // A 64 KiB tmpfs, where mounting is allowed (root in a container);
    // elsewhere /dev/full and ulimit -f above cover the same paths.
    const TempDir dir;
    const std::string mount = dir.path("small");
    fs::create_directory(mount);
    if (run_shell("mount -t tmpfs -o size=64k tmpfs \"" + mount + "\"").status != 0) {
        skip_test("cannot mount a small tmpfs here");
        return;
    }
    const std::string scene = long_scene(dir);
    const std::string cert = mount + "/c.cert";
    std::ofstream(cert) << "old\n";
    const auto r =
        run_cli("solve " + quote(scene) + " --max-steps 100000 --certificate " + quote(cert));
    CHECK(r.status == 5);
    CHECK(r.err.find("No space left on device") != std::string::npos);
    CHECK(slurp(cert) == "old\n");
    CHECK(leftovers(mount, {"c.cert"}).empty());
    run_shell("umount \"" + mount + "\"");
}

TEST_CASE("an output through a symbolic link replaces the file it names, never the link",
          "[output_writes][cli]") {
    const TempDir dir;
    const std::string scene = run_cli("convert " + quote(box) + " /dev/stdout").out;
    REQUIRE(scene.starts_with("dim 2\n"));
    // A link to a file: the file is replaced, the link stays.
    const std::string target = dir.write("target.scene", "old\n");
    const std::string link = dir.path("link.scene");
    fs::create_symlink("target.scene", link);
    CHECK(run_cli("convert " + quote(box) + " " + quote(link)).status == 0);
    CHECK(fs::is_symlink(link));
    CHECK(slurp(target) == scene);
    // A link to no file yet: the file is created where it points.
    fs::create_directory(dir.path("sub"));
    const std::string ahead = dir.path("ahead.scene");
    fs::create_symlink("sub/new.scene", ahead);
    CHECK(run_cli("convert " + quote(box) + " " + quote(ahead)).status == 0);
    CHECK(fs::is_symlink(ahead));
    CHECK(slurp(dir.path("sub/new.scene")) == scene);
    // A link into a closed descriptor, as /dev/stdout is with standard
    // output closed: refused, where a file was once renamed over the link.
    const std::string closed = dir.path("stdout");
    fs::create_symlink("/proc/self/fd/1", closed);
    const ShellResult r =
        run_shell("$ORTHORAY convert " + quote(box) + " " + quote(closed) + " >&-");
    CHECK(r.status == 2);
    CHECK(r.err.find("cannot write the scene") != std::string::npos);
    CHECK(fs::read_symlink(closed) == "/proc/self/fd/1");
    // /dev/stdout redirected to a file goes through the shell's descriptor,
    // so `>>` appends instead of the file being replaced.
    const std::string log = dir.write("log.txt", "first\n");
    CHECK(run_shell("$ORTHORAY convert " + quote(box) + " /dev/stdout >> " + quote(log)).status ==
          0);
    CHECK(slurp(log) == "first\n" + scene);
    // Only a name of standard output goes through it: the very file it is
    // redirected to, named as itself, is replaced, or solve's answer would
    // land after the certificate's end.
    const std::string cert = dir.path("c.cert");
    CHECK(run_shell("$ORTHORAY solve " + quote(box) + " --certificate " + quote(cert) + " > " +
                    quote(cert))
              .status == 0);
    CHECK(run_cli("verify " + quote(box) + " " + quote(cert)).status == 0);
    // A loop of links: refused, the links kept.
    fs::create_symlink("loop-b", dir.path("loop-a"));
    fs::create_symlink("loop-a", dir.path("loop-b"));
    const CliResult loop = run_cli("convert " + quote(box) + " " + quote(dir.path("loop-a")));
    CHECK(loop.status == 2);
    CHECK(loop.err.find("cannot write the scene") != std::string::npos);
    CHECK(fs::is_symlink(dir.path("loop-a")));
    CHECK(leftovers(dir.path(""), {"target.scene", "link.scene", "sub", "ahead.scene", "stdout",
                                   "log.txt", "c.cert", "loop-a", "loop-b"})
              .empty());
}

TEST_CASE("two outputs that will be one new file, in two spellings, are refused",
          "[output_writes][cli]") {
    // "y.svg" and "./y.svg" resolved differently while neither existed.
    const TempDir dir;
    const ShellResult r = run_shell("cd " + quote(dir.path("")) + " && $ORTHORAY render " +
                                    quote(box) + " -o y.svg --html ./y.svg");
    CHECK(r.status == 2);
    CHECK(r.err.find("naming the same file as the picture") != std::string::npos);
    CHECK(leftovers(dir.path(""), {}).empty());
}

TEST_CASE("a stop while the result is printed lets it finish: all of it or nothing",
          "[output_writes][cli]") {
    // Each command prints its whole result at the end. Its reader here waits
    // a second before reading, so the command sits in a write to a full pipe
    // when SIGTERM comes; exchange used to end there, exit 3 with 64 KiB
    // printed, and render -o /dev/stdout wrote its picture before it held
    // signals.
    const TempDir dir;
    const std::string scene = quote(dir.write(
        "r.scene", run_cli("generate random --dim 2 --mirrors 2000 --box --bits 30").out));
    for (const std::string& command :
         {"exchange " + scene + " --json", "render " + scene + " -o /dev/stdout --steps 40000"}) {
        CAPTURE(command);
        const std::size_t whole = run_cli(command).out.size();
        REQUIRE(whole > 256 * 1024);
        const std::string fifo = dir.path("fifo"), count = dir.path("count");
        const ShellResult r = run_shell(
            "rm -f " + quote(fifo) + "; mkfifo " + quote(fifo) + "; $ORTHORAY " + command + " > " +
            quote(fifo) + " & pid=$!; exec 3< " + quote(fifo) + "; sleep 1; kill -TERM $pid; " +
            "wc -c <&3 > " + quote(count) + "; wait $pid");
        const std::size_t printed = std::stoul(slurp(count));
        INFO("status " << r.status << ", " << printed << " of " << whole << " bytes");
        // Under a slow build the signal may still come while it computes.
        CHECK(((r.status == 0 && printed == whole) || (r.status == 3 && printed == 0)));
    }
}
