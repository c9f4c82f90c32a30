#include "render/markers.hpp"

#include <algorithm>
#include <cmath>

namespace orthoray::render {

void write_start(SvgWriter& svg, const Pixel& s, const Pixel& a) {
    const double dx = a.x - s.x, dy = a.y - s.y, length = std::hypot(dx, dy);
    svg.empty("circle",
              {{"class", "start"}, {"cx", number_text(s.x)}, {"cy", number_text(s.y)}, {"r", "5"}});
    if (!(length > 1e-6) || !std::isfinite(length)) return;
    const double ux = dx / length, uy = dy / length, tip_x = s.x + 34 * ux, tip_y = s.y + 34 * uy;
    svg.empty("path", {{"class", "start-arrow"},
                       {"d", PathData()
                                 .move(s.x, s.y)
                                 .line(tip_x, tip_y)
                                 .move(tip_x - 9 * ux + 5 * uy, tip_y - 9 * uy - 5 * ux)
                                 .line(tip_x, tip_y)
                                 .line(tip_x - 9 * ux - 5 * uy, tip_y - 9 * uy + 5 * ux)
                                 .text()}});
}

void write_target(SvgWriter& svg, const Pixel& t, const char* cls) {
    // The circle first: a lit target's is filled, and the cross goes on top.
    svg.empty("circle",
              {{"class", cls}, {"cx", number_text(t.x)}, {"cy", number_text(t.y)}, {"r", "9"}});
    svg.empty("path", {{"class", cls},
                       {"d", PathData()
                                 .move(t.x - 7, t.y - 7)
                                 .line(t.x + 7, t.y + 7)
                                 .move(t.x - 7, t.y + 7)
                                 .line(t.x + 7, t.y - 7)
                                 .text()}});
}

void write_absorbed(SvgWriter& svg, const Pixel& p) {
    svg.empty("rect", {{"class", "absorbed"},
                       {"x", number_text(p.x - 5)},
                       {"y", number_text(p.y - 5)},
                       {"width", "10"},
                       {"height", "10"}});
}

void write_label(SvgWriter& svg, const ViewPlacement& view, const Pixel& at,
                 const std::string& text) {
    const bool left = at.x > view.left + view.width - 80;
    svg.text("text",
             {{"class", "marker-label"},
              {"x", number_text(left ? at.x - 10 : at.x + 10)},
              {"y", number_text(at.y - 10)},
              {"text-anchor", left ? "end" : "start"}},
             text);
}

std::string side_ticks(const std::vector<Pixel>& shape, const Pixel& base, const Pixel& toward) {
    const double nx = toward.x - base.x, ny = toward.y - base.y, length = std::hypot(nx, ny);
    if (!(length > 1e-9) || !std::isfinite(length)) return {};
    constexpr double spacing = 9, tick = 6; // pixels
    const double ux = tick * nx / length, uy = tick * ny / length;
    const std::size_t edges = shape.size() == 2 ? 1 : shape.size();
    PathData ticks;
    for (std::size_t i = 0; i < edges; ++i) {
        const Pixel& p = shape[i];
        const Pixel& q = shape[(i + 1) % shape.size()];
        const double along = std::hypot(q.x - p.x, q.y - p.y);
        if (!std::isfinite(along)) continue;
        const int count = std::clamp(static_cast<int>(along / spacing), 1, 64);
        for (int k = 0; k < count; ++k) {
            const double t = (k + 0.5) / count;
            const double x = p.x + t * (q.x - p.x), y = p.y + t * (q.y - p.y);
            ticks.move(x, y).line(x + ux, y + uy);
        }
    }
    return ticks.text();
}

} // namespace orthoray::render
