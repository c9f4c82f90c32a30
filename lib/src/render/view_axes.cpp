// The axes of a view: ticks with exact labels (axis_ticks.cpp) along a
// projection's two axes, or the oblique view's key.
#include "render/view_axes.hpp"

#include "render/axis_ticks.hpp"

#include <algorithm>
#include <array>
#include <string>

namespace orthoray::render {

void write_axes(SvgWriter& svg, const ViewPlacement& v, const Frame& frame) {
    const double bottom = v.top + v.height;
    // Returns what follows the axis's name: the offset its labels count
    // from (" - 1e40"), or nothing.
    auto axis_line = [&](int axis, bool horizontal) -> std::string {
        const double length = horizontal ? v.width : v.height;
        const int count = std::max(2, static_cast<int>(length / 90));
        const AxisTicks ticks = axis_ticks(frame.lo[axis], frame.hi[axis], count);
        for (const Tick& t : ticks.ticks) {
            const double pos = t.fraction * frame.extent[axis] * v.scale;
            if (horizontal) {
                const std::string x = number_text(v.left + pos);
                svg.empty("line", {{"class", "tick"},
                                   {"x1", x},
                                   {"y1", number_text(bottom)},
                                   {"x2", x},
                                   {"y2", number_text(bottom + 5)}});
                svg.text("text",
                         {{"class", "tick"},
                          {"x", x},
                          {"y", number_text(bottom + 18)},
                          {"text-anchor", "middle"}},
                         t.label);
            } else {
                const std::string y = number_text(bottom - pos);
                svg.empty("line", {{"class", "tick"},
                                   {"x1", number_text(v.left - 5)},
                                   {"y1", y},
                                   {"x2", number_text(v.left)},
                                   {"y2", y}});
                svg.text("text",
                         {{"class", "tick"},
                          {"x", number_text(v.left - 8)},
                          {"y", number_text(bottom - pos + 4)},
                          {"text-anchor", "end"}},
                         t.label);
            }
        }
        if (ticks.offset.empty()) return {};
        return (ticks.offset_negative ? " + " : " - ") + ticks.offset;
    };
    const std::string a_offset = axis_line(v.a, true);
    const std::string b_offset = axis_line(v.b, false);
    svg.text("text",
             {{"class", "axis"},
              {"x", number_text(v.left + v.width / 2)},
              {"y", number_text(bottom + 36)},
              {"text-anchor", "middle"}},
             axis_name(v.a) + a_offset);
    // The vertical axis's name with an offset may be long: it goes above
    // the plot, where it has the view's width, and the side keeps the name.
    svg.text("text",
             {{"class", "axis"},
              {"x", number_text(v.left - 62)},
              {"y", number_text(v.top + v.height / 2)}},
             std::string(1, axis_name(v.b)));
    if (!b_offset.empty())
        svg.text("text",
                 {{"class", "axis"}, {"x", number_text(v.left)}, {"y", number_text(v.top - 8)}},
                 axis_name(v.b) + b_offset);
}

// The oblique view has no axis to tick; a small key in the margin left
// of its plot area shows which way x, y and z run. It stays outside the
// plot, so its labels never cover the start, target or path (the
// frame's low corner, where the key used to be, is often the start).
void write_oblique_axis_key(SvgWriter& svg, const ViewPlacement& v) {
    constexpr double arm = 26;
    const Pixel o{v.left - 68, v.top + v.height};
    const std::array<Pixel, 3> tips{{{o.x + arm, o.y},
                                     {o.x + arm * 2 * oblique_x, o.y - arm * 2 * oblique_y},
                                     {o.x, o.y - arm}}};
    const std::array<Pixel, 3> label_at{{{tips[0].x + 4, tips[0].y + 4},
                                         {tips[1].x + 3, tips[1].y - 3},
                                         {tips[2].x - 4, tips[2].y - 6}}};
    for (int j = 0; j < 3; ++j) {
        svg.empty("line", {{"class", "axis-arrow"},
                           {"x1", number_text(o.x)},
                           {"y1", number_text(o.y)},
                           {"x2", number_text(tips[j].x)},
                           {"y2", number_text(tips[j].y)}});
        svg.text("text",
                 {{"class", "axis"},
                  {"x", number_text(label_at[j].x)},
                  {"y", number_text(label_at[j].y)}},
                 std::string(1, axis_name(j)));
    }
}

} // namespace orthoray::render
