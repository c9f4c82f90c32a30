// Draws the elements and the streamed path into the views laid out by
// view_layout.cpp, and writes the SVG through svg_writer.hpp. Coordinates
// reach this file already normalised by the exact frame (frame.cpp).
#include "orthoray/render.hpp"

#include "render/element_shapes.hpp"
#include "render/frame.hpp"
#include "render/markers.hpp"
#include "render/path_thinner.hpp"
#include "render/svg_writer.hpp"
#include "render/view_axes.hpp"
#include "render/view_layout.hpp"
#include "render/viewer_html.hpp"
#include "render/viewer_record.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace orthoray {
namespace {

using render::kind_class;
using render::number_text;
using render::Pixel;
using render::Point3;
using render::SvgWriter;
using render::View;

constexpr double caption_line = 18;

// The path's colour at `fraction` of its length: amber early, through
// vermilion, to deep purple late. Hues away from the mirrors' blue and the
// start's green; dark at the end so the last turns stand out.
std::string ramp_colour(double fraction) {
    static constexpr std::array<std::array<double, 3>, 3> stops{
        {{240, 163, 10}, {214, 64, 40}, {92, 24, 120}}};
    const double f = std::clamp(fraction, 0.0, 1.0) * 2;
    const std::size_t i = f >= 1 ? 1 : 0;
    const double t = f - static_cast<double>(i);
    char buffer[8];
    int rgb[3];
    for (int c = 0; c < 3; ++c)
        rgb[c] = static_cast<int>(std::lround(stops[i][c] + t * (stops[i + 1][c] - stops[i][c])));
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
    return buffer;
}

} // namespace

struct SceneRenderer::Impl {
    const Scene& scene;
    RenderOptions options;
    render::Frame frame;
    render::ViewerRecord viewer; // what write_html shows, exactly
    std::vector<View> views;
    double page_width = 0, page_height = 0;
    std::vector<std::string> caption;
    std::size_t elements_drawn = 0, elements_total = 0;

    std::optional<Point3> last;
    std::uint64_t visits = 0;
    // The segment drawn after the last point: to the target (a hit) or out
    // to the frame's edge (an escape). An absorption's point is a visit.
    bool final_segment = false;
    std::optional<PathEnd> end;

    // Branches (walk_branches) instead of one path.
    bool branches = false;
    std::uint64_t branch_segments = 0, most_reflections = 0;
    std::vector<Point3> absorptions; // at most max_absorptions
    static constexpr std::size_t max_absorptions = 10'000;
    std::vector<TargetAnswer> target_status; // empty: targets drawn plain

    Impl(const Scene& s, const RenderOptions& o)
        : scene(s), options(o), frame(s), viewer(s, frame, o.viewer_segments) {
        render::PageLayout page = render::lay_out_views(frame, scene.dim, options.view_size);
        const std::size_t vertices = options.max_path_vertices / page.views.size();
        for (render::ViewPlacement& v : page.views) views.emplace_back(std::move(v), vertices);
        page_width = page.width;
        page_height = page.height;
        elements_total = scene.elements.size();
        elements_drawn = render::draw_elements(scene, frame, views, options.max_element_shapes);
    }

    // Where a ray from `from` along `direction` leaves the frame, in
    // normalised units; nothing when it does not move in the picture.
    std::optional<Point3> exit_point(const Point3& from, const Vector& direction) const {
        double longest = 0;
        Point3 v{0, 0, 0};
        for (int j = 0; j < scene.dim; ++j) {
            v[j] = frame.normalised_component(direction[j], j);
            longest = std::max(longest, std::abs(v[j]));
        }
        if (!(longest > 0) || !std::isfinite(longest)) return std::nullopt;
        double t = HUGE_VAL;
        for (int j = 0; j < scene.dim; ++j) {
            v[j] /= longest;
            if (v[j] > 0) t = std::min(t, (frame.extent[j] - from[j]) / v[j]);
            if (v[j] < 0) t = std::min(t, -from[j] / v[j]);
        }
        if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
        Point3 out = from;
        for (int j = 0; j < 3; ++j) out[j] += t * v[j];
        return out;
    }

    void branch(const BranchSegment& s) {
        branches = true;
        ++branch_segments;
        most_reflections = std::max(most_reflections, s.reflections);
        const Point3 from = frame.normalised(s.from);
        const std::optional<Point3> to =
            s.escape ? exit_point(from, s.direction) : frame.normalised(s.to);
        viewer.segment(s, to);
        if (s.absorbed && absorptions.size() < max_absorptions) absorptions.push_back(*to);
        if (!to) return;
        for (View& v : views) {
            const Pixel a = v.map(from), b = v.map(*to);
            v.path.add_ranked(s.reflections, a.x, a.y, b.x, b.y);
        }
    }

    void segment(const Point3& from, const Point3& to) {
        for (View& v : views) {
            const Pixel a = v.map(from), b = v.map(to);
            v.path.add(a.x, a.y, b.x, b.y);
        }
    }

    void visit(const Vector& point) {
        const Point3 n = frame.normalised(point);
        viewer.visit(point);
        if (last) segment(*last, n);
        last = n;
        ++visits;
    }

    void finish(const PathEnd& e) {
        end = e;
        if (!last) return;
        viewer.finish(e,
                      e.reason == Reason::escape ? exit_point(*last, e.direction) : std::nullopt);
        if (e.reason == Reason::hit) {
            segment(*last, frame.normalised(scene.target()));
            final_segment = true;
        } else if (e.reason == Reason::escape) {
            // Out along the final direction to the frame's edge.
            if (const std::optional<Point3> out = exit_point(*last, e.direction)) {
                segment(*last, *out);
                final_segment = true;
            }
        }
    }

    std::uint64_t segments() const {
        if (branches) return branch_segments;
        return (visits > 0 ? visits - 1 : 0) + (final_segment ? 1 : 0);
    }

    // The view that shows the most of the path: the 2D view, or in 3D the
    // oblique one, since projections fold retraced segments onto each other
    // as a matter of course.
    const render::PathThinner& fullest_path() const {
        const View* best = &views.front();
        for (const View& v : views)
            if (v.path.drawn() > best->path.drawn()) best = &v;
        return best->path;
    }

    bool cut() const {
        for (const View& v : views)
            if (v.path.cut()) return true;
        return false;
    }

    bool thinned() const {
        const render::PathThinner& path = fullest_path();
        return path.drawn() < path.segments() || cut();
    }

    void write_view(SvgWriter& svg, const View& v, std::size_t index) const {
        const std::string clip = "clip" + std::to_string(index);
        svg.open("g", {{"class", "view"}, {"data-name", v.title.empty() ? "xy" : v.title}});
        svg.open("clipPath", {{"id", clip}});
        svg.empty("rect", {{"x", number_text(v.left - 4)},
                           {"y", number_text(v.top - 4)},
                           {"width", number_text(v.width + 8)},
                           {"height", number_text(v.height + 8)}});
        svg.close("clipPath");
        svg.empty("rect", {{"class", "frame"},
                           {"x", number_text(v.left)},
                           {"y", number_text(v.top)},
                           {"width", number_text(v.width)},
                           {"height", number_text(v.height)}});
        if (!v.title.empty())
            svg.text(
                "text",
                {{"class", "title"}, {"x", number_text(v.left)}, {"y", number_text(v.top - 8)}},
                v.title);
        if (v.oblique)
            render::write_oblique_axis_key(svg, v);
        else
            render::write_axes(svg, v, frame);
        svg.open("g", {{"clip-path", "url(#" + clip + ")"}});
        auto path = [&](const char* cls, const std::string& d) {
            if (!d.empty()) svg.empty("path", {{"class", cls}, {"d", d}});
        };
        auto elements = [&] {
            for (std::size_t kind = 0; kind < kind_class.size(); ++kind)
                path(("face-" + std::string(kind_class[kind])).c_str(), v.faces[kind]);
            for (std::size_t kind = 0; kind < kind_class.size(); ++kind) {
                path(kind_class[kind], v.edges[kind]);
                path(("side-" + std::string(kind_class[kind])).c_str(), v.ticks[kind]);
            }
        };
        // Branches cover much of the picture, so the elements go on top of
        // them; a single path is drawn over the elements.
        if (!branches) elements();
        write_trajectory(svg, v);
        if (branches) elements();
        write_markers(svg, v);
        svg.close("g");
        svg.close("g");
    }

    // The path, band by band in the order it was travelled, each band in
    // its colour on the ramp (ramp_colour), so even a tangle shows which
    // way the ray went.
    void write_trajectory(SvgWriter& svg, const View& v) const {
        const std::vector<std::string>& bands = v.path.bands();
        const double last_band = static_cast<double>(std::max<std::size_t>(bands.size(), 2) - 1);
        for (std::size_t i = 0; i < bands.size(); ++i) {
            if (bands[i].empty()) continue;
            svg.empty("path", {{"class", "trajectory"},
                               {"stroke", ramp_colour(static_cast<double>(i) / last_band)},
                               {"d", bands[i]}});
        }
    }

    // A ray's start and a point a little ahead along its direction, as
    // this view sees them. The direction is scaled so its largest part is 1
    // in normalised units (the scene's numbers may be far beyond what a
    // double can divide).
    void write_start(SvgWriter& svg, const View& v, const Ray& ray) const {
        const Point3 from = frame.normalised(ray.start);
        Point3 ahead = from, d{0, 0, 0};
        double largest = 0;
        for (int j = 0; j < scene.dim; ++j) {
            d[j] = frame.normalised_component(ray.direction[j], j);
            largest = std::max(largest, std::abs(d[j]));
        }
        if (largest > 0 && std::isfinite(largest))
            for (int j = 0; j < scene.dim; ++j) ahead[j] += 0.01 * d[j] / largest;
        render::write_start(svg, v.map(from), v.map(ahead));
    }

    // The marker's look: plain without a status (a single trajectory's
    // picture), else lit, unlit or unknown.
    const char* target_class(std::size_t index) const {
        if (index >= target_status.size()) return "target";
        switch (target_status[index].status) {
        case TargetAnswer::Status::lit:
            return "target-lit";
        case TargetAnswer::Status::unlit:
            return "target-unlit";
        case TargetAnswer::Status::unknown:
            break;
        }
        return "target-unknown";
    }

    void write_markers(SvgWriter& svg, const View& v) const {
        for (std::size_t r = 0; r < scene.rays.size(); ++r) {
            write_start(svg, v, scene.rays[r]);
            if (scene.rays.size() > 1)
                render::write_label(svg, v, v.map(frame.normalised(scene.rays[r].start)),
                                    "ray " + std::to_string(r + 1));
        }
        for (const Point3& point : absorptions) render::write_absorbed(svg, v.map(point));
        if (end && end->reason == Reason::absorbed && last)
            render::write_absorbed(svg, v.map(*last));
        for (std::size_t t = 0; t < scene.targets.size(); ++t) {
            const Pixel at = v.map(frame.normalised(scene.targets[t]));
            render::write_target(svg, at, target_class(t));
            if (scene.targets.size() > 1)
                render::write_label(svg, v, at, "target " + std::to_string(t + 1));
        }
    }

    std::vector<std::string> caption_lines() const {
        std::vector<std::string> lines = caption;
        std::uint64_t drawn = 0, total = 0;
        bool cut = false;
        for (const View& v : views) {
            drawn = std::max(drawn, v.path.drawn());
            total = std::max(total, v.path.segments());
            cut = cut || v.path.cut();
        }
        if (thinned())
            lines.push_back(
                "thinned: " + std::to_string(drawn) + " of " + std::to_string(segments()) +
                " segments drawn (segments on pixels already drawn are merged" +
                (cut ? "; cut at the " + std::to_string(options.max_path_vertices) + "-vertex cap"
                     : std::string()) +
                ")");
        if (elements_drawn < elements_total)
            lines.push_back("elements: " + std::to_string(elements_drawn) + " of " +
                            std::to_string(elements_total) + " drawn in a view (shape cap)");
        if (frame.separate_scales)
            lines.push_back("axes scaled separately (the scene is very elongated)");
        return lines;
    }

    // A key to the path's shading at the caption's right: early, the ramp
    // in steps, late.
    // Branches: on a row of its own below the caption, since their caption
    // lines are long, reading "reflections so far: 0 [ramp] N".
    void write_ramp_key(SvgWriter& svg, double caption_height, std::size_t lines) const {
        constexpr int steps = 8;
        constexpr double step_width = 10;
        const double y = branches ? -caption_height + 8 + caption_line * static_cast<double>(lines)
                                  : -caption_height + 8;
        const double ramp_left = branches ? 150 : page_width - 40 - steps * step_width;
        const double right = ramp_left + 28 + steps * step_width;
        svg.text("text",
                 {{"class", "legend"},
                  {"x", number_text(ramp_left - 4)},
                  {"y", number_text(y + 10)},
                  {"text-anchor", "end"}},
                 branches ? "reflections so far: 0" : "path: early");
        for (int i = 0; i < steps; ++i)
            svg.empty("rect", {{"class", "legend"},
                               {"x", number_text(ramp_left + i * step_width)},
                               {"y", number_text(y)},
                               {"width", number_text(step_width)},
                               {"height", "12"},
                               {"fill", ramp_colour(i / (steps - 1.0))}});
        svg.text("text",
                 {{"class", "legend"}, {"x", number_text(right - 24)}, {"y", number_text(y + 10)}},
                 branches ? std::to_string(most_reflections) : std::string("late"));
    }

    void write(std::ostream& out) const {
        const std::vector<std::string> lines = caption_lines();
        const bool ramp_key = fullest_path().bands().size() > 1;
        const std::size_t rows = std::max<std::size_t>(lines.size(), 1) + (branches && ramp_key);
        const double caption_height = caption_line * static_cast<double>(rows) + 12;
        // Thinner lines when there are many elements, so that a maze of
        // 10^5 mirrors is not one blue square.
        const double element_stroke = elements_total <= 200    ? 2
                                      : elements_total <= 5000 ? 1.2
                                                               : 0.6;
        // Likewise a dense path, so the mirrors still show through it.
        const std::uint64_t drawn = fullest_path().drawn();
        const double path_stroke = drawn <= 100     ? 2
                                   : drawn <= 1000  ? 1.3
                                   : drawn <= 20000 ? 0.8
                                                    : 0.4;
        char style[2048];
        std::snprintf(
            style, sizeof style,
            "<style>\n"
            "text{font-family:sans-serif;font-size:12px;fill:#222}\n"
            "text.caption{font-size:14px}\n"
            "text.title,text.axis{font-size:13px;font-weight:bold}\n"
            ".frame{fill:none;stroke:#bbb;stroke-width:1}\n"
            "line.tick{stroke:#888}\n"
            ".axis-arrow{stroke:#666;stroke-width:1.5}\n"
            ".mirror{fill:none;stroke:#1f5fa8;stroke-width:%g;stroke-linecap:round}\n"
            ".absorber{fill:none;stroke:#111;stroke-width:%g;stroke-dasharray:%g %g}\n"
            ".splitter{fill:none;stroke:#0e8f8f;stroke-width:%g;stroke-dasharray:%g %g}\n"
            ".face-mirror{fill:#1f5fa8;fill-opacity:0.12;stroke:#1f5fa8;stroke-width:1}\n"
            ".face-absorber{fill:#111;fill-opacity:0.35;stroke:#111;stroke-width:1.5}\n"
            ".face-splitter{fill:#0e8f8f;fill-opacity:0.08;stroke:#0e8f8f;stroke-width:1;"
            "stroke-dasharray:5 3}\n"
            ".side-mirror{stroke:#1f5fa8;stroke-width:1.2}\n"
            ".side-absorber{stroke:#111;stroke-width:1.2}\n"
            ".side-splitter{stroke:#0e8f8f;stroke-width:1.2}\n"
            ".trajectory{fill:none;stroke-width:%g;stroke-opacity:0.9;stroke-linejoin:round;"
            "stroke-linecap:round}\n"
            "circle.start{fill:#1a9a3a}\n"
            ".start-arrow{fill:none;stroke:#1a9a3a;stroke-width:2.5}\n"
            "path.target{stroke:#d01c1c;stroke-width:2.5}\n"
            "circle.target{fill:none;stroke:#d01c1c;stroke-width:2}\n"
            "path.target-lit{stroke:#d01c1c;stroke-width:2.5}\n"
            "circle.target-lit{fill:#ffd23f;stroke:#d01c1c;stroke-width:2}\n"
            "path.target-unlit,path.target-unknown{stroke:#666;stroke-width:2}\n"
            "circle.target-unlit{fill:#fff;fill-opacity:0.7;stroke:#666;stroke-width:2;"
            "stroke-dasharray:3 2}\n"
            "circle.target-unknown{fill:#fff;fill-opacity:0.7;stroke:#666;stroke-width:2;"
            "stroke-dasharray:1 2}\n"
            "text.marker-label{font-size:11px;fill:#222;paint-order:stroke;stroke:#fff;"
            "stroke-width:3px;stroke-linejoin:round}\n"
            "rect.absorbed{fill:#111}\n"
            "rect.legend{stroke:none}\n"
            "</style>\n",
            element_stroke, 2 * element_stroke, 3 * element_stroke, 1.5 * element_stroke,
            1.5 * element_stroke, 4 * element_stroke, 2.5 * element_stroke, path_stroke);
        out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
        SvgWriter svg(out);
        const std::string height = number_text(page_height + caption_height);
        svg.open("svg", {{"xmlns", "http://www.w3.org/2000/svg"},
                         {"width", number_text(page_width)},
                         {"height", height},
                         {"viewBox", "0 " + number_text(-caption_height) + " " +
                                         number_text(page_width) + " " + height}});
        svg.raw(style);
        svg.empty("rect", {{"x", "0"},
                           {"y", number_text(-caption_height)},
                           {"width", "100%"},
                           {"height", "100%"},
                           {"fill", "white"}});
        for (std::size_t i = 0; i < lines.size(); ++i)
            svg.text(
                "text",
                {{"class", "caption"},
                 {"x", "12"},
                 {"y", number_text(-caption_height + 20 + caption_line * static_cast<double>(i))}},
                lines[i]);
        if (ramp_key) write_ramp_key(svg, caption_height, lines.size());
        for (std::size_t i = 0; i < views.size(); ++i) write_view(svg, views[i], i);
        svg.close("svg");
    }
};

SceneRenderer::SceneRenderer(const Scene& scene, const RenderOptions& options)
    : impl_(std::make_unique<Impl>(scene, options)) {}

SceneRenderer::~SceneRenderer() = default;

void SceneRenderer::visit(const Vector& point, const Vector&) {
    impl_->visit(point);
}

void SceneRenderer::finish(const PathEnd& end) {
    impl_->finish(end);
}

void SceneRenderer::segment(const BranchSegment& segment) {
    impl_->branch(segment);
}

void SceneRenderer::mark_targets(const std::vector<TargetAnswer>& targets) {
    impl_->target_status = targets;
    impl_->viewer.mark_targets(targets);
}

void SceneRenderer::add_caption(const std::string& line) {
    impl_->caption.push_back(line);
}

std::uint64_t SceneRenderer::segments() const {
    return impl_->segments();
}

bool SceneRenderer::thinned() const {
    return impl_->thinned();
}

void SceneRenderer::write_svg(std::ostream& out) const {
    impl_->write(out);
}

void SceneRenderer::set_grid(const std::vector<std::pair<Vector, Vector>>& lines) {
    impl_->viewer.set_grid(lines);
}

void SceneRenderer::write_html(std::ostream& out, const std::string& title) const {
    // The SVG's thinning does not touch the viewer's segments, so its caption
    // line is left out; the frame's scales are the viewer's too.
    std::vector<std::string> caption = impl_->caption;
    if (impl_->frame.separate_scales)
        caption.push_back("axes scaled separately (the scene is very elongated)");
    render::write_viewer_html(out, title, impl_->viewer.to_json(caption));
}

} // namespace orthoray
