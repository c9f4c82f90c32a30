// Where the views of a picture go on the page. A 2D scene has one view; a
// 3D scene four (the xy, xz and yz projections and an oblique view), all on
// ONE scale, so that a length reads the same in every view and the views
// can be compared side by side: the scale is the largest at which every
// view fits its cell.
#pragma once

#include "render/frame.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace orthoray::render {

struct Pixel {
    double x = 0, y = 0;
};

// Page margins around a view's plot area, in pixels: room for tick labels
// on the left and below, for the title above.
constexpr double margin_left = 78, margin_right = 24, margin_top = 30, margin_bottom = 46;

// One view: an orthographic projection onto axes (a, b), or the oblique
// view (x to the right, z up, y receding at 30 degrees, at half length).
struct ViewPlacement {
    std::string title;
    int a = 0, b = 1;
    bool oblique = false;
    double left = 0, top = 0;     // the plot area's corner on the page
    double width = 0, height = 0; // the plot area's size
    double scale = 1;             // pixels per normalised unit

    // n: normalised coordinates (each in [0, extent]).
    Pixel map(const Point3& n) const;
};

struct PageLayout {
    std::vector<ViewPlacement> views;
    double width = 0, height = 0;
};

// Views in rows of two; the largest view is view_size pixels on its longer side.
PageLayout lay_out_views(const Frame& frame, int dim, double view_size);

// The oblique view's unit step along y, in normalised units across and up.
extern const double oblique_x, oblique_y;

} // namespace orthoray::render
