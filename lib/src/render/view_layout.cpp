#include "render/view_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace orthoray::render {

const double oblique_x = 0.5 * std::cos(std::numbers::pi / 6),
             oblique_y = 0.5 * std::sin(std::numbers::pi / 6);

Pixel ViewPlacement::map(const Point3& n) const {
    if (oblique)
        return {left + (n[0] + oblique_x * n[1]) * scale,
                top + height - (n[2] + oblique_y * n[1]) * scale};
    return {left + n[a] * scale, top + height - n[b] * scale};
}

PageLayout lay_out_views(const Frame& frame, int dim, double view_size) {
    PageLayout page;
    auto add_view = [&](std::string title, int a, int b, bool oblique) {
        ViewPlacement v;
        v.title = std::move(title);
        v.a = a;
        v.b = b;
        v.oblique = oblique;
        // Normalised width and height for now; pixels once the scale is known.
        v.width = oblique ? frame.extent[0] + oblique_x * frame.extent[1] : frame.extent[a];
        v.height = oblique ? frame.extent[2] + oblique_y * frame.extent[1] : frame.extent[b];
        page.views.push_back(std::move(v));
    };
    if (dim == 2) {
        add_view("", 0, 1, false);
    } else {
        add_view("xy (top)", 0, 1, false);
        add_view("xz (front)", 0, 2, false);
        add_view("yz (side)", 1, 2, false);
        add_view("oblique", 0, 2, true);
    }
    // One scale for all views: the largest at which each fits its cell.
    double scale = HUGE_VAL;
    for (const ViewPlacement& v : page.views)
        scale = std::min(scale, view_size / std::max(v.width, v.height));
    for (ViewPlacement& v : page.views) {
        v.scale = scale;
        v.width *= scale;
        v.height *= scale;
    }
    if (page.views.size() == 1) { // one view: the page fits it, without blank bands
        ViewPlacement& v = page.views.front();
        v.left = margin_left;
        v.top = margin_top;
        page.width = margin_left + v.width + margin_right;
        page.height = margin_top + v.height + margin_bottom;
        return page;
    }
    // Rows of two. On one scale the views differ in size, so each column
    // is as wide as its widest view and each row as tall as its tallest,
    // with the views centred in their cells: no blank bands.
    const std::size_t rows = (page.views.size() + 1) / 2;
    std::array<double, 2> column_width{};
    std::vector<double> row_height(rows, 0);
    for (std::size_t i = 0; i < page.views.size(); ++i) {
        column_width[i % 2] = std::max(column_width[i % 2], page.views[i].width);
        row_height[i / 2] = std::max(row_height[i / 2], page.views[i].height);
    }
    std::vector<double> row_top(rows, 0);
    for (std::size_t r = 1; r < rows; ++r)
        row_top[r] = row_top[r - 1] + margin_top + row_height[r - 1] + margin_bottom;
    const std::array<double, 2> column_left{0, margin_left + column_width[0] + margin_right};
    for (std::size_t i = 0; i < page.views.size(); ++i) {
        ViewPlacement& v = page.views[i];
        v.left = column_left[i % 2] + margin_left + (column_width[i % 2] - v.width) / 2;
        v.top = row_top[i / 2] + margin_top + (row_height[i / 2] - v.height) / 2;
    }
    page.width = column_left[1] + margin_left + column_width[1] + margin_right;
    page.height = row_top.back() + margin_top + row_height.back() + margin_bottom;
    return page;
}

} // namespace orthoray::render
