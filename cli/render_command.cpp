// orthoray render FILE: draw the scene and its trajectory as SVG or PNG.
#include "commands.hpp"
#include "option_checks.hpp"
#include "orthoray/certificate.hpp"
#include "orthoray/parse.hpp"
#include "orthoray/render.hpp"
#include "orthoray/solve.hpp"
#include "output_file.hpp"
#include "run_monitor.hpp"
#include "scene_format_option.hpp"
#include "stop_at_once.hpp"
#include "svg_to_png.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

namespace orthoray::cli {
namespace {

struct RenderArgs {
    std::string file, out, html, certificate, format;
    std::uint64_t steps = 1000;
    double timeout = 0;
    bool quiet = false;
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

// Holds a certificate's first points back until the certificate is known to
// list its path. An induction certificate lists a prefix and then its proof;
// the induction engine's lists only up to the first reflection, too little to
// draw, so when the whole certificate fits here its picture is simulated
// instead (release() is then never called and the held points are dropped).
// The default engine's lists what it simulated before inducing, often
// thousands of points: those are the path's, and are drawn as a path
// certificate's would be.
class HeldPrefix : public PathSink {
public:
    explicit HeldPrefix(PathSink& next) : next_(next) {}
    void visit(const Vector& point, const Vector& direction) override {
        ++points_;
        if (released_) return next_.visit(point, direction);
        held_.push_back({point, direction});
        if (held_.size() > most_held) release();
    }
    void release() {
        for (const auto& [point, direction] : held_) next_.visit(point, direction);
        held_.clear();
        released_ = true;
    }
    bool released() const { return released_; }
    std::uint64_t points() const { return points_; }

private:
    static constexpr std::size_t most_held = 16; // the induction engine's certificates list 2
    PathSink& next_;
    std::vector<std::pair<Vector, Vector>> held_;
    bool released_ = false;
    std::uint64_t points_ = 0;
};

std::string scene_summary(const std::string& file, const Scene& scene) {
    std::size_t absorbers = 0, splitters = 0, one_sided = 0;
    for (const Element& e : scene.elements) {
        absorbers += e.kind == ElementKind::absorber;
        splitters += e.kind == ElementKind::splitter;
        one_sided += e.one_sided();
    }
    std::string text = std::filesystem::path(file).filename().string() + ": " +
                       std::to_string(scene.dim) + "D, " +
                       std::to_string(scene.elements.size() - absorbers - splitters) +
                       " mirrors, " + std::to_string(absorbers) + " absorbers";
    if (splitters > 0) text += ", " + std::to_string(splitters) + " splitters";
    if (one_sided > 0) text += ", " + std::to_string(one_sided) + " one-sided";
    if (scene.rays.size() > 1) text += ", " + std::to_string(scene.rays.size()) + " rays";
    if (scene.targets.size() > 1) text += ", " + std::to_string(scene.targets.size()) + " targets";
    return text;
}

// How to read the new elements, when the scene has them.
std::optional<std::string> element_key(const Scene& scene) {
    bool splitters = false, one_sided = false;
    for (const Element& e : scene.elements) {
        splitters = splitters || e.kind == ElementKind::splitter;
        one_sided = one_sided || e.one_sided();
    }
    if (!splitters && !one_sided) return std::nullopt;
    std::string key = "key: ";
    if (splitters) key += "splitters teal, dashed";
    if (splitters && one_sided) key += "; ";
    if (one_sided) key += "one-sided elements ticked on the side they act on";
    return key;
}

std::string verdict_line(const std::string& answer, Reason reason, const Integer& reflections) {
    return "answer " + answer + ", reason " + to_string(reason) + ", " + reflections.get_str() +
           (reason == Reason::cycle ? " reflections a period" : " reflections");
}

// Each target's status for its marker: the illumination answer's, or a
// single trajectory's read as one target (hit: lit; another answer: unlit).
std::vector<TargetAnswer> target_statuses(const Answer& answer) {
    if (answer.illumination()) return answer.targets;
    TargetAnswer target;
    if (answer.decided())
        target.status = answer.yes() ? TargetAnswer::Status::lit : TargetAnswer::Status::unlit;
    return {target};
}

std::string lit_line(const Answer& answer) {
    std::size_t lit = 0;
    std::string unlit, unknown;
    for (std::size_t t = 0; t < answer.targets.size(); ++t) {
        const std::string name = std::to_string(t + 1);
        switch (answer.targets[t].status) {
        case TargetAnswer::Status::lit:
            ++lit;
            break;
        case TargetAnswer::Status::unlit:
            unlit += (unlit.empty() ? "" : ", ") + name;
            break;
        case TargetAnswer::Status::unknown:
            unknown += (unknown.empty() ? "" : ", ") + name;
            break;
        }
    }
    std::string line = "targets: " + std::to_string(lit) + " of " +
                       std::to_string(answer.targets.size()) + " lit (gold)";
    if (!unlit.empty()) line += "; unlit (grey, dashed): " + unlit;
    if (!unknown.empty()) line += "; unknown (dotted): " + unknown;
    return line;
}

// How long render lets the solver decide the caption's answer when no
// --timeout is given: a picture should not wait for ever on a 3D orbit of
// 10^30 reflections, which solve would step through.
constexpr std::chrono::seconds decide_budget{10};

std::string undecided_line() {
    return "answer unknown: not decided within " + std::to_string(decide_budget.count()) +
           " s ('orthoray solve' decides it without that limit)";
}

// The answer, with the engines and limits `solve` uses by default, but at
// most decide_budget of time (render's own --timeout ends the process).
Answer decide(const Scene& scene, const RenderArgs& args) {
    SolveMonitor progress(scene, SolveMonitor::Clock::now() + decide_budget, !args.quiet);
    SolveOptions options;
    options.monitor = &progress;
    Answer answer = solve(scene, options);
    progress.erase_progress();
    return answer;
}

// The first --steps reflections of the path, simulated; how it ends.
PathEnd draw_first_reflections(const Scene& scene, const RenderArgs& args,
                               SceneRenderer& renderer) {
    FirstSegments path(renderer, std::nullopt);
    SolveOptions options;
    options.max_steps = args.steps;
    options.path = &path;
    // For the progress line only: stop requests end the process at once.
    SolveMonitor progress(scene, std::nullopt, !args.quiet);
    options.monitor = &progress;
    const Answer drawn = solve(scene, options);
    progress.erase_progress();
    if (!drawn.decided())
        renderer.add_caption("path: the first " + std::to_string(args.steps) +
                             " reflections are drawn (--steps N draws more)");
    return {drawn.reason, path.last_direction()};
}

// Every branch of every ray, shaded by reflections so far, and each target
// marked lit or unlit from solve(): for scenes with splitters, one-sided
// elements, or several rays or targets (docs/render.md).
void draw_branches(const Scene& scene, const RenderArgs& args, SceneRenderer& renderer) {
    // For the progress line only: stop requests end the process at once.
    SolveMonitor progress(scene, std::nullopt, !args.quiet, "states");
    const BranchWalk walk = walk_branches(scene, renderer, args.steps, &progress);
    progress.erase_progress();
    const Answer answer = decide(scene, args);
    renderer.mark_targets(target_statuses(answer));
    if (answer.decided())
        renderer.add_caption(
            answer.illumination() ? std::string("answer ") + answer_word(answer) + ", reason " +
                                        to_string(answer.reason)
            : answer.reason == Reason::cycle && answer.tail > 0
                ? "answer no, reason cycle, tail " + answer.tail.get_str() + ", period " +
                      answer.period().get_str()
                : verdict_line(answer_word(answer), answer.reason, answer.reflections));
    else
        renderer.add_caption(undecided_line());
    if (answer.illumination()) renderer.add_caption(lit_line(answer));
    if (const std::optional<std::string> key = element_key(scene)) renderer.add_caption(*key);
    renderer.add_caption(
        walk.complete ? "branches: all " + std::to_string(walk.states) +
                            " reachable states drawn, shaded by reflections so far"
                      : "branches: the first " + std::to_string(walk.states) +
                            " states drawn, fewest reflections first (--steps N draws more)");
}

// The picture's bytes, whole: SVG, or PNG converted from it by rsvg-convert
// through pipes (svg_to_png.hpp). Made in memory while a stop may still end
// the run (a conversion can take seconds), so that what is written after
// stop_no_more() is only a copy: a target that is written in place (a pipe,
// /dev/stdout) then gets the whole picture or nothing.
std::string picture_bytes(const SceneRenderer& renderer, const RenderArgs& args) {
    std::ostringstream svg;
    renderer.write_svg(svg);
    if (!args.out.ends_with(".png") && !args.out.ends_with(".PNG")) return std::move(svg).str();
    std::ostringstream png;
    svg_to_png(svg.str(), png);
    return std::move(png).str();
}

// Segments (with their exact points) the interactive viewer keeps: a
// browser steps through a few thousand smoothly, and memory stays bounded.
constexpr std::size_t viewer_segments = 5000;

int run(const RenderArgs& args, const CLI::Option* steps, const CLI::Option* timeout) {
    stop_at_once(timeout->count() > 0 ? std::optional<double>(args.timeout) : std::nullopt);
    // Opened before any work, so that a path that cannot be written is
    // refused at once; written at the end, and renamed into place together.
    refuse_same_output(args.out, "the picture", args.html, "the viewer page");
    std::optional<OutputFile> picture, page;
    if (!args.out.empty())
        picture.emplace(args.out, std::vector{args.file, args.certificate}, "the picture");
    if (!args.html.empty())
        page.emplace(args.html, std::vector{args.file, args.certificate}, "the viewer page");
    const Scene scene = load_scene(args.file, scene_format_named(args.format));
    RenderOptions look;
    if (!args.html.empty()) look.viewer_segments = viewer_segments;
    SceneRenderer renderer(scene, look);
    renderer.add_caption(scene_summary(args.file, scene));
    PathEnd end;
    const bool branches = !scene.single_trajectory() || scene.has_one_sided();
    if (branches && !args.certificate.empty())
        throw UsageError("found --certificate for a scene with splitters, one-sided elements or "
                         "several rays or targets, expected a scene of one two-sided trajectory "
                         "(render draws such a scene's branches from the scene itself; its "
                         "certificate lists branch states, not a path)");
    if (branches) {
        draw_branches(scene, args, renderer);
    } else if (!args.certificate.empty()) {
        const std::unique_ptr<std::istream> cert = open_file_stream(args.certificate);
        std::optional<std::uint64_t> limit;
        if (steps->count() > 0) limit = args.steps;
        FirstSegments first(renderer, limit);
        HeldPrefix held(first);
        const CertificateClaim claim = read_certificate_path(scene, *cert, args.certificate, held);
        const std::string source = std::filesystem::path(args.certificate).filename().string();
        if (!claim.complete)
            renderer.add_caption("path: incomplete certificate " + source + " (no verdict)");
        else
            renderer.add_caption(verdict_line(claim.answer, claim.reason, claim.reflections) +
                                 " (claimed by " + source + "; 'orthoray verify' checks it)");
        if (!claim.lists_path && !held.released()) {
            renderer.add_caption("path: simulated; the induction certificate lists " +
                                 std::to_string(held.points()) + " points only");
            end = draw_first_reflections(scene, args, renderer);
        } else {
            held.release();
            if (first.cut())
                renderer.add_caption("path: the first " + std::to_string(args.steps) +
                                     " segments of the certificate (--steps)");
            else if (!claim.lists_path) // the prefix is drawn; the path goes on past it
                renderer.add_caption("path: the " + std::to_string(held.points()) +
                                     " points the induction certificate lists before its proof");
            else if (claim.complete)
                end = {claim.reason, claim.direction};
        }
    } else {
        // The caption's answer is decided as `solve` decides it, not capped
        // at --steps (in 2D the induction engine answers orbits far longer
        // than any picture), within decide_budget.
        const Answer answer = decide(scene, args);
        if (answer.decided())
            renderer.add_caption(
                verdict_line(answer_word(answer), answer.reason, answer.reflections));
        else
            renderer.add_caption(undecided_line());
        // The picture: the first --steps reflections of the path.
        end = draw_first_reflections(scene, args, renderer);
    }
    if (!branches) renderer.finish(end);
    const std::string picture_text = picture ? picture_bytes(renderer, args) : std::string();
    // The interactive viewer's page (docs/render.md, "Interactive viewer").
    std::ostringstream page_text;
    if (page)
        renderer.write_html(page_text,
                            "orthoray: " + std::filesystem::path(args.file).filename().string());
    // Everything is made: from here a stop would leave one file written and
    // not the other, or a picture printed in part.
    stop_no_more();
    if (picture) picture->stream() << picture_text;
    if (page) page->stream() << page_text.view();
    if (picture) picture->commit();
    if (page) page->commit();
    if (picture) {
        std::cout << "wrote " << args.out << " (" << renderer.segments() << " segments"
                  << (renderer.thinned() ? ", thinned" : "") << ")\n";
    }
    if (page) {
        std::cout << "wrote " << args.html << " (" << renderer.segments() << " segments"
                  << (renderer.segments() > viewer_segments
                          ? ", the first " + std::to_string(viewer_segments) + " in the viewer"
                          : std::string())
                  << ")\n";
    }
    return yes;
}

} // namespace

Command add_render(CLI::App& app) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Draw the scene and the ray's path: SVG, or PNG when OUT ends in .png\n"
                  "(through rsvg-convert). 2D scenes get one view; 3D scenes get the xy, xz\n"
                  "and yz projections and an oblique view. The caption gives the answer.\n"
                  "Scenes with splitters, one-sided elements, or several rays or targets are\n"
                  "drawn as every branch of every ray (each reachable state once, at most\n"
                  "--steps of them), shaded by reflections so far; splitters dashed, ticks on\n"
                  "the side a one-sided element acts on, targets gold when lit, grey when not.\n\n"
                  "Example:\n"
                  "  orthoray render instances/2d/box-corner-3x5.scene -o box.svg\n"
                  "  orthoray solve maze.scene --certificate maze.cert\n"
                  "  orthoray render maze.scene --certificate maze.cert -o maze.png\n"
                  "  orthoray render maze.scene --html maze.html\n\n"
                  "Exit status: 0 written, 2 bad input or usage (docs/render.md), 3 stopped\n"
                  "by --timeout, SIGINT or SIGTERM (nothing written), 5 a failed write.");
    cmd->add_option("FILE", args->file, "the scene (.scene text or JSON)")->required();
    cmd->add_option("-o,--output", args->out,
                    "the picture to write: NAME.svg, NAME.png, or NAME.html for the interactive "
                    "viewer (default: FILE's name with .svg, in the current directory, unless "
                    "--html is given)")
        ->check(not_empty("a file name"));
    cmd->add_option("--html", args->html,
                    "write the interactive viewer here: one self-contained HTML page with a step "
                    "slider, play/pause, zoom, pan, 3D rotation and the exact coordinates of "
                    "each point on hover (the first 5000 segments)")
        ->check(not_empty("a file name"));
    cmd->add_option("--certificate", args->certificate,
                    "draw the path this certificate lists (text or jsonl) instead of solving")
        ->check(not_empty("a file name"));
    CLI::Option* steps =
        cmd->add_option("--steps", args->steps,
                        "draw the path's first N reflections (default 1000), and its last "
                        "segment when it ends by then, or for branches at most N states; the "
                        "caption's answer is decided as 'solve' decides it")
            ->transform(whole_number_in(1, 1'000'000'000'000));
    add_scene_format_option(cmd, args->format);
    CLI::Option* timeout = add_timeout_option(cmd, args->timeout, "the drawing");
    cmd->add_flag("--quiet", args->quiet,
                  "no progress line (it is shown on long runs only when stderr is a terminal)");
    return [args, steps, timeout] {
        if (args->out.ends_with(".html") || args->out.ends_with(".HTML")) {
            if (!args->html.empty())
                throw UsageError("found -o " + args->out + " and --html " + args->html +
                                 ", expected one HTML page (-o NAME.svg or NAME.png draws the "
                                 "picture beside it)");
            args->html = args->out;
            args->out.clear();
        }
        if (args->out.empty() && args->html.empty())
            args->out = std::filesystem::path(args->file).stem().string() + ".svg";
        return run(*args, steps, timeout);
    };
}

} // namespace orthoray::cli
