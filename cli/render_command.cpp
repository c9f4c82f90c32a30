// orthoray render FILE: draw the scene and its trajectory as SVG or PNG.
#include "commands.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/render.hpp"
#include "orthoray/solve.hpp"
#include "scene_format_option.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace orthoray::cli {
namespace {

struct RenderArgs {
    std::string file, out, certificate, format;
    std::uint64_t steps = 1000;
};

// Passes on the first `limit` segments of a path (limit + 1 points), and
// keeps the direction the ray leaves the last one in (the solver streams
// it; an escape's final ray is drawn along it).
class FirstSegments : public PathSink {
public:
    FirstSegments(PathSink& next, std::optional<std::uint64_t> limit)
        : next_(next), limit_(limit) {}
    void visit(const Vector& point, const Vector& direction) override {
        if (limit_ && points_ > *limit_) {
            cut_ = true;
            return;
        }
        ++points_;
        last_direction_ = direction;
        next_.visit(point, direction);
    }
    bool cut() const { return cut_; }
    const Vector& last_direction() const { return last_direction_; }

private:
    PathSink& next_;
    std::optional<std::uint64_t> limit_;
    std::uint64_t points_ = 0;
    bool cut_ = false;
    Vector last_direction_;
};

std::string scene_summary(const std::string& file, const Scene& scene) {
    std::size_t absorbers = 0;
    for (const Element& e : scene.elements) absorbers += e.kind == ElementKind::absorber;
    return std::filesystem::path(file).filename().string() + ": " + std::to_string(scene.dim) +
           "D, " + std::to_string(scene.elements.size() - absorbers) + " mirrors, " +
           std::to_string(absorbers) + " absorbers";
}

std::string verdict_line(const std::string& answer, Reason reason, const Integer& reflections) {
    return "answer " + answer + ", reason " + to_string(reason) + ", " + reflections.get_str() +
           (reason == Reason::cycle ? " reflections a period" : " reflections");
}

// Runs `rsvg-convert -o png svg` without a shell.
void convert_to_png(const std::string& svg, const std::string& png) {
    std::string program = "rsvg-convert", dash_o = "-o", out = png, in = svg;
    char* argv[] = {program.data(), dash_o.data(), out.data(), in.data(), nullptr};
    pid_t pid = 0;
    if (posix_spawnp(&pid, "rsvg-convert", nullptr, nullptr, argv, environ) != 0)
        throw UsageError("PNG output needs the program rsvg-convert (Debian package "
                         "librsvg2-bin); install it, or write an .svg file instead");
    int status = 0;
    if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw UsageError("rsvg-convert could not write '" + png + "'");
}

void write_picture(const SceneRenderer& renderer, const std::string& out) {
    const bool png = out.size() > 4 && (out.ends_with(".png") || out.ends_with(".PNG"));
    std::string svg_path = out;
    if (png) {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "orthoray-render-XXXXXX").string();
        const int fd = mkstemp(pattern.data());
        if (fd < 0) throw UsageError("cannot create a temporary file for the SVG");
        close(fd);
        svg_path = pattern;
    }
    {
        std::ofstream file(svg_path, std::ios::binary | std::ios::trunc);
        if (!file) throw UsageError("cannot write the picture file '" + out + "'");
        renderer.write_svg(file);
        if (!file.flush()) throw UsageError("cannot write the picture file '" + out + "'");
    }
    if (png) {
        struct Remove {
            std::string path;
            ~Remove() { std::remove(path.c_str()); }
        } remove_svg{svg_path};
        convert_to_png(svg_path, out);
    }
}

int run(const RenderArgs& args, const CLI::Option* steps) {
    const Scene scene = load_scene(args.file, scene_format_named(args.format));
    SceneRenderer renderer(scene);
    renderer.add_caption(scene_summary(args.file, scene));
    PathEnd end;
    if (!args.certificate.empty()) {
        std::ifstream cert(args.certificate, std::ios::binary);
        if (!cert) read_file(args.certificate); // throws the usual FILE:1:1 message
        std::optional<std::uint64_t> limit;
        if (steps->count() > 0) limit = args.steps;
        FirstSegments first(renderer, limit);
        const CertificateClaim claim = read_certificate_path(scene, cert, args.certificate, first);
        const std::string source = std::filesystem::path(args.certificate).filename().string();
        if (!claim.complete)
            renderer.add_caption("path: incomplete certificate " + source + " (no verdict)");
        else
            renderer.add_caption(verdict_line(claim.answer, claim.reason, claim.reflections) +
                                 " (claimed by " + source + "; 'orthoray verify' checks it)");
        if (first.cut())
            renderer.add_caption("path: the first " + std::to_string(args.steps) +
                                 " segments of the certificate (--steps)");
        else if (claim.complete)
            end = {claim.reason, claim.direction};
    } else {
        FirstSegments path(renderer, std::nullopt);
        SolveOptions options;
        options.max_steps = args.steps;
        options.path = &path;
        const Answer answer = solve(scene, options);
        if (answer.decided())
            renderer.add_caption(
                verdict_line(answer_word(answer), answer.reason, answer.reflections));
        else
            renderer.add_caption("answer unknown: the first " + std::to_string(args.steps) +
                                 " reflections are drawn (--steps N draws more)");
        end = {answer.reason, path.last_direction()};
    }
    renderer.finish(end);
    write_picture(renderer, args.out);
    std::cout << "wrote " << args.out << " (" << renderer.segments() << " segments"
              << (renderer.thinned() ? ", thinned" : "") << ")\n";
    return yes;
}

} // namespace

Command add_render(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Draw the scene and the ray's path: SVG, or PNG when OUT ends in .png\n"
                  "(through rsvg-convert). 2D scenes get one view; 3D scenes get the xy, xz\n"
                  "and yz projections and an oblique view. The caption gives the answer.\n\n"
                  "Example:\n"
                  "  orthoray render instances/2d/box-corner-3x5.scene -o box.svg\n"
                  "  orthoray solve maze.scene --certificate maze.cert\n"
                  "  orthoray render maze.scene --certificate maze.cert -o maze.png\n\n"
                  "Exit status: 0 written, 2 bad input or usage (docs/render.md).");
    cmd->add_option("FILE", args->file, "the scene (.scene text or JSON)")->required();
    cmd->add_option("-o,--output", args->out,
                    "the picture to write: NAME.svg, or NAME.png (default: FILE's name with "
                    ".svg, in the current directory)");
    cmd->add_option("--certificate", args->certificate,
                    "draw the path this certificate lists (text or jsonl) instead of solving");
    CLI::Option* steps =
        cmd->add_option("--steps", args->steps,
                        "draw the first N segments: without --certificate, solve with at most N "
                        "reflections (default 1000)")
            ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1'000'000'000'000}));
    add_scene_format_option(cmd, args->format);
    return [args, steps] {
        if (args->out.empty())
            args->out = std::filesystem::path(args->file).stem().string() + ".svg";
        return run(*args, steps);
    };
}

} // namespace orthoray::cli
