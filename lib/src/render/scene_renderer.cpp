// Lays out the views of a scene, draws the elements and the streamed path
// into them, and writes the SVG. Coordinates reach this file already
// normalised by the exact frame (frame.cpp).
#include "orthoray/render.hpp"

#include "render/axis_ticks.hpp"
#include "render/frame.hpp"
#include "render/path_thinner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <unordered_set>

namespace orthoray {
namespace {

using render::Point3;
struct Pixel {
    double x = 0, y = 0;
};

// Page layout, in pixels.
constexpr double margin_left = 78, margin_right = 24, margin_top = 30, margin_bottom = 46;
constexpr double caption_line = 18;

// The oblique view: x to the right, z up, y receding at 30 degrees.
const double oblique_x = 0.5 * std::cos(std::numbers::pi / 6),
             oblique_y = 0.5 * std::sin(std::numbers::pi / 6);

std::string number_text(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", value);
    return buffer;
}

std::string escape_xml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            // Control bytes are not allowed in XML 1.0 at all.
            if (static_cast<unsigned char>(c) >= 0x20 || c == '\t') out += c;
        }
    }
    return out;
}

// One view: an orthographic projection onto axes (a, b), or the oblique view.
struct View {
    std::string title;
    int a = 0, b = 1;
    bool oblique = false;
    double left = 0, top = 0;     // the plot area's corner on the page
    double width = 0, height = 0; // the plot area's size
    double scale = 1;             // pixels per normalised unit
    std::string mirrors, absorbers, faces_mirror, faces_absorber; // SVG path data
    std::size_t shapes = 0;
    render::PathThinner path;

    explicit View(std::size_t max_vertices) : path(max_vertices) {}

    // n: normalised coordinates (each in [0, extent]).
    Pixel map(const Point3& n) const {
        if (oblique)
            return {left + (n[0] + oblique_x * n[1]) * scale,
                    top + height - (n[2] + oblique_y * n[1]) * scale};
        return {left + n[a] * scale, top + height - n[b] * scale};
    }
};

} // namespace

struct SceneRenderer::Impl {
    const Scene& scene;
    RenderOptions options;
    render::Frame frame;
    std::vector<View> views;
    double page_width = 0, page_height = 0;
    std::vector<std::string> caption;
    std::size_t elements_drawn = 0, elements_total = 0;

    std::optional<Point3> last;
    std::uint64_t visits = 0;
    std::optional<PathEnd> end;

    Impl(const Scene& s, const RenderOptions& o) : scene(s), options(o), frame(s) {
        layout();
        draw_elements();
    }

    void layout() {
        const double size = options.view_size;
        const std::size_t view_count = scene.dim == 2 ? 1 : 4;
        const std::size_t vertices = options.max_path_vertices / view_count;
        auto add_view = [&](std::string title, int a, int b, bool oblique) {
            View v(vertices);
            v.title = std::move(title);
            v.a = a;
            v.b = b;
            v.oblique = oblique;
            const double w =
                oblique ? frame.extent[0] + oblique_x * frame.extent[1] : frame.extent[a];
            const double h =
                oblique ? frame.extent[2] + oblique_y * frame.extent[1] : frame.extent[b];
            v.scale = size / std::max(w, h);
            v.width = w * v.scale;
            v.height = h * v.scale;
            views.push_back(std::move(v));
        };
        if (scene.dim == 2) {
            add_view("", 0, 1, false);
        } else {
            add_view("xy (top)", 0, 1, false);
            add_view("xz (front)", 0, 2, false);
            add_view("yz (side)", 1, 2, false);
            add_view("oblique", 0, 2, true);
        }
        // Views in rows of two; the caption goes above them.
        const double cell_w = margin_left + size + margin_right;
        const double cell_h = margin_top + size + margin_bottom;
        for (std::size_t i = 0; i < views.size(); ++i) {
            View& v = views[i];
            v.left = static_cast<double>(i % 2) * cell_w + margin_left + (size - v.width) / 2;
            v.top = static_cast<double>(i / 2) * cell_h + margin_top + (size - v.height) / 2;
        }
        page_width = cell_w * (views.size() > 1 ? 2 : 1);
        page_height = cell_h * static_cast<double>((views.size() + 1) / 2);
        if (views.size() == 1) { // one view: the page fits it, without blank bands
            View& v = views.front();
            v.left = margin_left;
            v.top = margin_top;
            page_width = margin_left + v.width + margin_right;
            page_height = margin_top + v.height + margin_bottom;
        }
    }

    // Elements as compact path data: a segment where the view sees the
    // element edge-on, a quadrilateral where it sees its face. Shapes that
    // snap to the same half pixels as one already drawn are skipped.
    void draw_elements() {
        elements_total = scene.elements.size();
        const std::size_t cap = options.max_element_shapes / views.size();
        for (View& v : views) {
            std::unordered_set<std::string> seen;
            for (const Element& e : scene.elements) {
                if (v.shapes >= cap) break;
                Point3 c0 = frame.normalised(e.lo), c1 = frame.normalised(e.hi);
                std::vector<Pixel> corners;
                bool face = false;
                if (scene.dim == 2 || (!v.oblique && (e.axis == v.a || e.axis == v.b))) {
                    corners = {v.map(c0), v.map(c1)};
                } else {
                    face = true;
                    // The rectangle's corners: the two non-normal axes vary.
                    int p = -1, q = -1;
                    for (int j = 0; j < 3; ++j)
                        if (j != e.axis) (p < 0 ? p : q) = j;
                    Point3 k = c0;
                    for (int corner : {0, 1, 3, 2}) {
                        k[p] = corner & 1 ? c1[p] : c0[p];
                        k[q] = corner & 2 ? c1[q] : c0[q];
                        corners.push_back(v.map(k));
                    }
                }
                std::string d;
                for (std::size_t i = 0; i < corners.size(); ++i) {
                    d += i ? 'L' : 'M';
                    d += number_text(corners[i].x);
                    d += ' ';
                    d += number_text(corners[i].y);
                }
                if (face) d += "Z";
                if (!seen.insert(d + (e.kind == ElementKind::mirror ? "m" : "a")).second) continue;
                ++v.shapes;
                const bool mirror = e.kind == ElementKind::mirror;
                (face ? (mirror ? v.faces_mirror : v.faces_absorber)
                      : (mirror ? v.mirrors : v.absorbers)) += d;
            }
        }
        elements_drawn = elements_total;
        for (const View& v : views)
            if (v.shapes >= cap) elements_drawn = std::min(elements_drawn, v.shapes);
    }

    void segment(const Point3& from, const Point3& to) {
        for (View& v : views) {
            const Pixel a = v.map(from), b = v.map(to);
            v.path.add(a.x, a.y, b.x, b.y);
        }
    }

    void visit(const Vector& point) {
        const Point3 n = frame.normalised(point);
        if (last) segment(*last, n);
        last = n;
        ++visits;
    }

    void finish(const PathEnd& e) {
        end = e;
        if (!last) return;
        if (e.reason == Reason::hit) {
            segment(*last, frame.normalised(scene.target()));
        } else if (e.reason == Reason::escape) {
            // Out along the final direction to the frame's edge.
            double longest = 0;
            Point3 v{0, 0, 0};
            for (int j = 0; j < scene.dim; ++j) {
                v[j] = frame.normalised_component(e.direction[j], j);
                longest = std::max(longest, std::abs(v[j]));
            }
            if (!(longest > 0) || !std::isfinite(longest)) return;
            double t = HUGE_VAL;
            for (int j = 0; j < scene.dim; ++j) {
                v[j] /= longest;
                if (v[j] > 0) t = std::min(t, (frame.extent[j] - (*last)[j]) / v[j]);
                if (v[j] < 0) t = std::min(t, -(*last)[j] / v[j]);
            }
            if (t > 0 && std::isfinite(t)) {
                Point3 out = *last;
                for (int j = 0; j < 3; ++j) out[j] += t * v[j];
                segment(*last, out);
            }
        }
    }

    std::uint64_t segments() const { return visits > 0 ? visits - 1 : 0; }

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

    void write_view(std::ostream& out, const View& v, std::size_t index) const {
        out << "<g class=\"view\" data-name=\"" << (v.title.empty() ? "xy" : v.title) << "\">\n";
        out << "<clipPath id=\"clip" << index << "\"><rect x=\"" << number_text(v.left - 4)
            << "\" y=\"" << number_text(v.top - 4) << "\" width=\"" << number_text(v.width + 8)
            << "\" height=\"" << number_text(v.height + 8) << "\"/></clipPath>\n";
        out << "<rect class=\"frame\" x=\"" << number_text(v.left) << "\" y=\""
            << number_text(v.top) << "\" width=\"" << number_text(v.width) << "\" height=\""
            << number_text(v.height) << "\"/>\n";
        if (!v.title.empty())
            out << "<text class=\"title\" x=\"" << number_text(v.left) << "\" y=\""
                << number_text(v.top - 8) << "\">" << escape_xml(v.title) << "</text>\n";
        if (v.oblique)
            write_oblique_axes(out, v);
        else
            write_axes(out, v);
        out << "<g clip-path=\"url(#clip" << index << ")\">\n";
        auto path = [&](const char* cls, const std::string& d) {
            if (!d.empty()) out << "<path class=\"" << cls << "\" d=\"" << d << "\"/>\n";
        };
        path("face-mirror", v.faces_mirror);
        path("face-absorber", v.faces_absorber);
        path("mirror", v.mirrors);
        path("absorber", v.absorbers);
        path("trajectory", v.path.path_data());
        write_markers(out, v);
        out << "</g>\n</g>\n";
    }

    void write_axes(std::ostream& out, const View& v) const {
        const double bottom = v.top + v.height;
        auto axis_line = [&](int axis, bool horizontal) {
            const double length = horizontal ? v.width : v.height;
            const int count = std::max(2, static_cast<int>(length / 90));
            for (const render::Tick& t :
                 render::axis_ticks(frame.lo[axis], frame.hi[axis], count)) {
                const double pos = t.fraction * frame.extent[axis] * v.scale;
                if (horizontal)
                    out << "<line class=\"tick\" x1=\"" << number_text(v.left + pos) << "\" y1=\""
                        << number_text(bottom) << "\" x2=\"" << number_text(v.left + pos)
                        << "\" y2=\"" << number_text(bottom + 5) << "\"/><text class=\"tick\" x=\""
                        << number_text(v.left + pos) << "\" y=\"" << number_text(bottom + 18)
                        << "\" text-anchor=\"middle\">" << escape_xml(t.label) << "</text>\n";
                else
                    out << "<line class=\"tick\" x1=\"" << number_text(v.left - 5) << "\" y1=\""
                        << number_text(bottom - pos) << "\" x2=\"" << number_text(v.left)
                        << "\" y2=\"" << number_text(bottom - pos)
                        << "\"/><text class=\"tick\" x=\"" << number_text(v.left - 8) << "\" y=\""
                        << number_text(bottom - pos + 4) << "\" text-anchor=\"end\">"
                        << escape_xml(t.label) << "</text>\n";
            }
        };
        axis_line(v.a, true);
        axis_line(v.b, false);
        out << "<text class=\"axis\" x=\"" << number_text(v.left + v.width / 2) << "\" y=\""
            << number_text(bottom + 36) << "\" text-anchor=\"middle\">" << axis_name(v.a)
            << "</text>\n<text class=\"axis\" x=\"" << number_text(v.left - 62) << "\" y=\""
            << number_text(v.top + v.height / 2) << "\">" << axis_name(v.b) << "</text>\n";
    }

    // The oblique view has no common scale to tick; it shows which way the
    // axes run from the frame's low corner instead.
    void write_oblique_axes(std::ostream& out, const View& v) const {
        const Pixel o = v.map({0, 0, 0});
        for (int j = 0; j < 3; ++j) {
            Point3 tip{0, 0, 0};
            tip[j] = frame.extent[j] * 0.25;
            const Pixel p = v.map(tip);
            out << "<line class=\"axis-arrow\" x1=\"" << number_text(o.x) << "\" y1=\""
                << number_text(o.y) << "\" x2=\"" << number_text(p.x) << "\" y2=\""
                << number_text(p.y) << "\"/><text class=\"axis\" x=\"" << number_text(p.x + 4)
                << "\" y=\"" << number_text(p.y - 4) << "\">" << axis_name(j) << "</text>\n";
        }
    }

    void write_markers(std::ostream& out, const View& v) const {
        // Start: a dot and an arrow along the start direction as this view sees it.
        const Pixel s = v.map(frame.normalised(scene.ray().start));

        // The direction in normalised units, scaled so its largest part is
        // 1 (the scene's numbers may be far beyond what a double can divide).
        const Point3 from = frame.normalised(scene.ray().start);
        Point3 ahead = from, d{0, 0, 0};
        double largest = 0;
        for (int j = 0; j < scene.dim; ++j) {
            d[j] = frame.normalised_component(scene.ray().direction[j], j);
            largest = std::max(largest, std::abs(d[j]));
        }
        if (largest > 0 && std::isfinite(largest))
            for (int j = 0; j < scene.dim; ++j) ahead[j] += 0.01 * d[j] / largest;
        const Pixel a = v.map(ahead);
        const double dx = a.x - s.x, dy = a.y - s.y, length = std::hypot(dx, dy);
        out << "<circle class=\"start\" cx=\"" << number_text(s.x) << "\" cy=\"" << number_text(s.y)
            << "\" r=\"5\"/>\n";
        if (length > 1e-6 && std::isfinite(length)) {
            const double ux = dx / length, uy = dy / length, tip_x = s.x + 34 * ux,
                         tip_y = s.y + 34 * uy;
            out << "<path class=\"start-arrow\" d=\"M" << number_text(s.x) << " "
                << number_text(s.y) << "L" << number_text(tip_x) << " " << number_text(tip_y) << "M"
                << number_text(tip_x - 9 * ux + 5 * uy) << " "
                << number_text(tip_y - 9 * uy - 5 * ux) << "L" << number_text(tip_x) << " "
                << number_text(tip_y) << "L" << number_text(tip_x - 9 * ux - 5 * uy) << " "
                << number_text(tip_y - 9 * uy + 5 * ux) << "\"/>\n";
        }
        if (end && end->reason == Reason::absorbed && last) {
            const Pixel p = v.map(*last);
            out << "<rect class=\"absorbed\" x=\"" << number_text(p.x - 5) << "\" y=\""
                << number_text(p.y - 5) << "\" width=\"10\" height=\"10\"/>\n";
        }
        const Pixel t = v.map(frame.normalised(scene.target()));
        out << "<path class=\"target\" d=\"M" << number_text(t.x - 7) << " " << number_text(t.y - 7)
            << "L" << number_text(t.x + 7) << " " << number_text(t.y + 7) << "M"
            << number_text(t.x - 7) << " " << number_text(t.y + 7) << "L" << number_text(t.x + 7)
            << " " << number_text(t.y - 7) << "\"/><circle class=\"target\" cx=\""
            << number_text(t.x) << "\" cy=\"" << number_text(t.y) << "\" r=\"9\"/>\n";
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

    void write(std::ostream& out) const {
        const std::vector<std::string> lines = caption_lines();
        const double caption_height = caption_line * static_cast<double>(lines.size()) + 12;
        // Thinner lines when there are many elements, so that a maze of
        // 10^5 mirrors is not one blue square.
        const double element_stroke = elements_total <= 200    ? 2
                                      : elements_total <= 5000 ? 1.2
                                                               : 0.6;
        // Likewise a dense path, so the mirrors still show through it.
        const std::uint64_t drawn = fullest_path().drawn();
        const double path_stroke = drawn <= 1000 ? 1.3 : drawn <= 20000 ? 0.8 : 0.4;
        out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << number_text(page_width)
            << "\" height=\"" << number_text(page_height + caption_height) << "\" viewBox=\"0 "
            << number_text(-caption_height) << " " << number_text(page_width) << " "
            << number_text(page_height + caption_height) << "\">\n"
            << "<style>\n"
               "text{font-family:sans-serif;font-size:12px;fill:#222}\n"
               "text.caption{font-size:14px}\n"
               "text.title,text.axis{font-size:13px;font-weight:bold}\n"
               ".frame{fill:none;stroke:#bbb;stroke-width:1}\n"
               "line.tick{stroke:#888}\n"
               ".axis-arrow{stroke:#666;stroke-width:1.5}\n"
            << ".mirror{fill:none;stroke:#1f5fa8;stroke-width:" << element_stroke
            << ";stroke-linecap:round}\n"
            << ".absorber{fill:none;stroke:#111;stroke-width:" << 2 * element_stroke
            << ";stroke-dasharray:" << 3 * element_stroke << " " << 1.5 * element_stroke
            << "}\n"
               ".face-mirror{fill:#1f5fa8;fill-opacity:0.12;stroke:#1f5fa8;stroke-width:1}\n"
               ".face-absorber{fill:#111;fill-opacity:0.35;stroke:#111;stroke-width:1.5}\n"
            << ".trajectory{fill:none;stroke:#e8730c;stroke-width:" << path_stroke
            << ";stroke-opacity:0.85;stroke-linejoin:round}\n"
            << "circle.start{fill:#1a9a3a}\n"
               ".start-arrow{fill:none;stroke:#1a9a3a;stroke-width:2.5}\n"
               "path.target{stroke:#d01c1c;stroke-width:2.5}\n"
               "circle.target{fill:none;stroke:#d01c1c;stroke-width:2}\n"
               "rect.absorbed{fill:#111}\n"
               "</style>\n"
            << "<rect x=\"0\" y=\"" << number_text(-caption_height) << "\" width=\"100%\" "
            << "height=\"100%\" fill=\"white\"/>\n";
        for (std::size_t i = 0; i < lines.size(); ++i)
            out << "<text class=\"caption\" x=\"12\" y=\""
                << number_text(-caption_height + 20 + caption_line * static_cast<double>(i))
                << "\">" << escape_xml(lines[i]) << "</text>\n";
        for (std::size_t i = 0; i < views.size(); ++i) write_view(out, views[i], i);
        out << "</svg>\n";
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

} // namespace orthoray
