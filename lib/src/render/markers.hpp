// The small marks of a picture, in page coordinates: a ray's start, a
// target, an absorption point, a label, and the ticks that show which side
// a one-sided element acts on (docs/render.md).
#pragma once

#include "render/svg_writer.hpp"
#include "render/view_layout.hpp"

#include <string>
#include <vector>

namespace orthoray::render {

// A dot at `start` and an arrow toward `ahead` (any point along the ray's
// direction; only the way it lies from `start` counts).
void write_start(SvgWriter& svg, const Pixel& start, const Pixel& ahead);

// A circled cross of CSS class `cls` ("target", "target-lit", ...).
void write_target(SvgWriter& svg, const Pixel& at, const char* cls);

// A black square.
void write_absorbed(SvgWriter& svg, const Pixel& at);

// Text beside a marker, to its left near the view's right edge so that the
// view's clip does not cut it.
void write_label(SvgWriter& svg, const ViewPlacement& view, const Pixel& at,
                 const std::string& text);

// Path data for short ticks along the edges of `shape` (two points: a
// segment; more: a closed polygon), each pointing the way from `base` to
// `toward`. Nothing when those coincide on the page, as for a face seen
// head-on: no direction on the page then tells the sides apart.
std::string side_ticks(const std::vector<Pixel>& shape, const Pixel& base, const Pixel& toward);

} // namespace orthoray::render
